// SPDX-License-Identifier: MIT
// One label's way through a shot (compose/label_ways.hpp): a change of place glides, never
// faster than a step's reach, round what stands across the straight way between; where every way
// that glides runs into something, a 2D label may jump once instead; over steps not evenly
// apart, each step as far as its time allows; a way round that is too long for the time planned
// arrives later. A few boxes and numbers, no picture (well under a millisecond).
#include "compose/label_ways.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "compose/label_cost.hpp"

namespace collide::compose {
namespace {

constexpr double kWidthPx = 20.0, kHeightPx = 10.0;
constexpr double kReachPx = 10.5;  // per step
constexpr std::size_t kSteps = 12;

Box at(double x, double y) {
  return {x, y, x + kWidthPx, y + kHeightPx};
}

// A label by a body standing at the origin: place A where it starts, place B 40 px across and
// 40 px up, where it must be from step 8 on; the way between planned as a glide from step 2.
struct Shot {
  WaySteps steps;
  WayPlan plan;
};

Shot aShot() {
  Shot shot;
  for (std::size_t k = 0; k < kSteps; ++k) {
    shot.steps.body_px.push_back({0.0, 0.0});
    shot.steps.reach_px.push_back(k > 0 ? kReachPx : 0.0);
    shot.steps.boxes.push_back({at(0.0, 0.0), at(40.0, -40.0)});
    shot.steps.costs.push_back({0.0, 0.0});
    shot.plan.chosen.push_back(k <= 2 ? 0 : 1);
  }
  shot.plan.glides.push_back({2, 8});
  return shot;
}

// Something standing across the straight way from A to B (its middle, (20, -20)).
bool acrossTheStraightWay(const Box& box) {
  return box.intersects({12.0, -28.0, 28.0, -12.0});
}

double hardAcrossTheStraightWay(std::size_t, const Box& box) {
  return acrossTheStraightWay(box) ? kHard : 0.0;
}

// How far each step of `way` moves from the one before (0 for the first), each step checked to
// keep clear of what stands across the straight way and to move no farther than its reach.
std::vector<double> movesClearWithinReach(const Way& way, const WaySteps& steps) {
  std::vector<double> moved_px(kSteps, 0.0);
  for (std::size_t k = 0; k < kSteps; ++k) {
    SCOPED_TRACE("step " + std::to_string(k));
    EXPECT_FALSE(acrossTheStraightWay(way.shown[k]));
    if (k == 0) continue;
    moved_px[k] =
        std::hypot(way.shown[k].x0 - way.shown[k - 1].x0, way.shown[k].y0 - way.shown[k - 1].y0);
    EXPECT_LE(moved_px[k], steps.reach_px[k] + 1e-9);
  }
  return moved_px;
}

TEST(LabelWaysTest, AGlideGoesRoundWhatStandsAcrossTheStraightWay) {
  Shot shot = aShot();
  const Way way = glidingWay(shot.steps, shot.plan, hardAcrossTheStraightWay, kOneLine);
  EXPECT_EQ(way.jumps, 0u);
  // Round it: 40 px across, then 40 up (up first, it would run into it too), 80 px at no more
  // than the reach a step, so at least ceil(80 / 10.5) = 8 steps: it sets off 8 steps before it
  // must arrive, at step 0.
  const std::size_t needs = static_cast<std::size_t>(std::ceil(80.0 / kReachPx));
  ASSERT_EQ(needs, 8u);
  const std::vector<double> moved_px = movesClearWithinReach(way, shot.steps);
  for (std::size_t k = 1; k < kSteps; ++k) EXPECT_EQ(moved_px[k] > 0.0, k <= needs) << "step " << k;
  EXPECT_DOUBLE_EQ(way.shown[8].x0, 40.0);
  EXPECT_DOUBLE_EQ(way.shown[8].y0, -40.0);
}

// After an event a label moves fast for a while (kEventGlidePxPerS), then slowly: a way round
// what stands across that is longer than the straight way the plan timed its glide by arrives
// later, moving as fast as each step's reach allows, rather than jump.
TEST(LabelWaysTest, AGlideRoundThatCannotArriveInTimeArrivesLater) {
  constexpr double kFastPx = 30.0, kSlowPx = 6.0;  // a step's reach: two fast steps, then slow
  Shot shot = aShot();
  for (std::size_t k = 0; k < kSteps; ++k) {
    shot.steps.reach_px[k] = k == 0 ? 0.0 : (k <= 2 ? kFastPx : kSlowPx);
    shot.plan.chosen[k] = k == 0 ? 0 : 1;
  }
  // Planned as the straight way's 56.6 px over the two fast steps.
  shot.plan.glides = {{0, 2}};
  ASSERT_EQ(glidingWay(shot.steps, shot.plan, hardAcrossTheStraightWay, kOneLine).jumps, 1u);
  const Way way = glidingWay(shot.steps, shot.plan, hardAcrossTheStraightWay, kOneLine, true);
  EXPECT_EQ(way.jumps, 0u);
  // Round it is 40 px across and 40 up, 80 px: the two fast steps take 60, and at 6 px a step
  // the other 20 take ceil(20 / 6) = 4 more, so it arrives at step 6, not before.
  const std::size_t arrives =
      2 + static_cast<std::size_t>(std::ceil((80.0 - 2 * kFastPx) / kSlowPx));
  ASSERT_EQ(arrives, 6u);
  movesClearWithinReach(way, shot.steps);
  for (std::size_t k = 0; k < kSteps; ++k) {
    const bool on_b = way.shown[k].x0 == 40.0 && way.shown[k].y0 == -40.0;
    EXPECT_EQ(on_b, k >= arrives) << "step " << k;
  }
}

TEST(LabelWaysTest, WithNoFreeWayRoundItTheLabelKeepsItsPlaceUntilTheChange) {
  Shot shot = aShot();
  // Nothing free but A and B themselves: no way round.
  const auto cost_at = [](std::size_t, const Box& box) {
    const bool a_or_b = (box.x0 == 0.0 && box.y0 == 0.0) || (box.x0 == 40.0 && box.y0 == -40.0);
    return a_or_b ? 0.0 : kHard;
  };
  const Way way = glidingWay(shot.steps, shot.plan, cost_at, kOneLine);
  EXPECT_EQ(way.jumps, 1u);
  for (std::size_t k = 0; k < 8; ++k) EXPECT_DOUBLE_EQ(way.shown[k].x0, 0.0) << "step " << k;
  EXPECT_DOUBLE_EQ(way.shown[8].x0, 40.0);
}

// Six steps of a still body and two places 100 px apart, each free for half the shot: no glide
// of 2 px a step gets from one to the other (a ball in flight crosses the picture faster than a
// glide takes its label around it).
constexpr std::size_t kHalvesSteps = 6;
constexpr std::size_t kFreeFirst = 3;  // steps the first place is free; the second after them

WaySteps halvesFree() {
  WaySteps steps;
  for (std::size_t k = 0; k < kHalvesSteps; ++k) {
    steps.body_px.push_back({0.0, 0.0});
    steps.reach_px.push_back(k > 0 ? 2.0 : 0.0);
    steps.boxes.push_back({Box{0.0, 0.0, 10.0, 10.0}, Box{100.0, 0.0, 110.0, 10.0}});
    const bool first_free = k < kFreeFirst;
    steps.costs.push_back({first_free ? 0.0 : kHard, first_free ? kHard : 0.0});
  }
  steps.change_cost = 10.0;
  return steps;
}

TEST(LabelWaysTest, AJumpWhereEveryGlideRunsIntoSomething) {
  WaySteps steps = halvesFree();
  steps.jump_cost = 0.5 * kHard;
  const WayPlan plan = cheapestWay(steps);
  // One jump costs half an overlap; standing on either place the whole shot costs three.
  std::vector<int> expected;
  for (std::size_t k = 0; k < kHalvesSteps; ++k) expected.push_back(k < kFreeFirst ? 0 : 1);
  EXPECT_EQ(plan.chosen, expected);
  EXPECT_TRUE(plan.glides.empty());
}

TEST(LabelWaysTest, NoJumpWhereJumpsAreNotAllowed) {
  const WayPlan plan = cheapestWay(halvesFree());
  ASSERT_EQ(plan.chosen.size(), kHalvesSteps);
  // It stays on one place, running into something for half the shot (a label along a track).
  for (std::size_t k = 1; k < kHalvesSteps; ++k) EXPECT_EQ(plan.chosen[k], plan.chosen.front());
}

// A label that stood on A at the shot before (the last candidate, costing 100 a step) and may
// change to B (costing nothing, `copies_of_b` candidates standing there) for 10, where only A and
// B are free and nothing between them is.
WaySteps standingOnAWithBCheaper(std::size_t copies_of_b) {
  WaySteps steps;
  for (std::size_t k = 0; k < kSteps; ++k) {
    steps.body_px.push_back({0.0, 0.0});
    steps.reach_px.push_back(k > 0 ? kReachPx : 0.0);
    std::vector<Box> boxes(copies_of_b, at(40.0, -40.0));
    std::vector<double> costs(copies_of_b, 0.0);
    boxes.push_back(at(0.0, 0.0));
    costs.push_back(100.0);
    steps.boxes.push_back(boxes);
    steps.costs.push_back(costs);
  }
  steps.change_cost = 10.0;
  steps.starts_on_last = true;
  return steps;
}

double onlyAOrBFree(std::size_t, const Box& box) {
  const bool a_or_b = (box.x0 == 0.0 && box.y0 == 0.0) || (box.x0 == 40.0 && box.y0 == -40.0);
  return a_or_b ? 0.0 : kHard;
}

void expectStaysOnA(const Way& way) {
  EXPECT_EQ(way.jumps, 0u);
  for (std::size_t k = 0; k < kSteps; ++k) {
    EXPECT_DOUBLE_EQ(way.shown[k].x0, 0.0) << "step " << k;
    EXPECT_DOUBLE_EQ(way.shown[k].y0, 0.0) << "step " << k;
  }
}

// Where a change of place that costs least has no free way between, the way is planned again
// without it: a label that may stay where it stands, at some cost, stays rather than jumps.
TEST(LabelWaysTest, AChangeWithNoFreeWayIsPlannedAgainWithoutIt) {
  WaySteps steps = standingOnAWithBCheaper(1);
  // The cheapest way changes to B (100 a step for staying against 10 for the change), and jumps
  // there.
  ASSERT_EQ(glidingWay(steps, cheapestWay(steps), onlyAOrBFree, kOneLine).jumps, 1u);
  expectStaysOnA(endingWay(steps, {}, kHard, onlyAOrBFree, kOneLine));
}

// A place may stand among a label's candidates more than once (a standing place added where a
// candidate stood, label_ways.hpp): a change found with no free way is not tried again to the
// same place as another candidate, however many stand there.
TEST(LabelWaysTest, AChangeWithNoFreeWayIsNotTriedAgainToTheSamePlace) {
  constexpr std::size_t kCopiesOfB = 5;  // more than the way is planned again
  WaySteps steps = standingOnAWithBCheaper(kCopiesOfB);
  expectStaysOnA(endingWay(steps, {}, kHard, onlyAOrBFree, kOneLine));
}

// Steps need not stand evenly apart (one halfway between two, where an arrow changes rows): a
// glide moves at its speed, each step as far as its time allows, none farther.
TEST(LabelWaysTest, AGlideOverAStepHalfwayMovesHalfAsFarThere) {
  constexpr double kPxPerTime = 10.0;
  constexpr double kAcrossPx = 30.0;  // from A to B
  constexpr double kMustArrive = 5.0;
  const std::vector<double> times{0.0, 1.0, 2.0, 3.0, 3.5, 4.0, 5.0, 6.0, 7.0};
  WaySteps steps;
  for (std::size_t k = 0; k < times.size(); ++k) {
    steps.t_s.push_back(times[k]);
    steps.body_px.push_back({0.0, 0.0});
    steps.reach_px.push_back(k > 0 ? kPxPerTime * (times[k] - times[k - 1]) : 0.0);
    steps.boxes.push_back({at(0.0, 0.0), at(kAcrossPx, 0.0)});
    // A until it must arrive at B (it runs into something there from then on), B after.
    const bool on_b = times[k] >= kMustArrive;
    steps.costs.push_back({on_b ? kHard : 0.0, on_b ? 0.0 : 100.0});
  }
  steps.change_cost = 10.0;
  const auto free = [](std::size_t, const Box&) { return 0.0; };
  const Way way = glidingWay(steps, cheapestWay(steps), free, kOneLine);
  EXPECT_EQ(way.jumps, 0u);
  // It is on B by the time it must be, having set off kAcrossPx / kPxPerTime before it arrived,
  // over the step halfway, and moves with the time: as far a step as the step's time allows.
  std::size_t arrives = 0;
  while (arrives < times.size() && way.shown[arrives].x0 != kAcrossPx) ++arrives;
  ASSERT_LT(arrives, times.size());
  EXPECT_LE(times[arrives], kMustArrive);
  const double sets_off = times[arrives] - kAcrossPx / kPxPerTime;
  EXPECT_LT(sets_off, 3.5);
  EXPECT_GT(times[arrives], 3.5);
  for (std::size_t k = 0; k < times.size(); ++k) {
    SCOPED_TRACE("at " + std::to_string(times[k]));
    const double expected_x =
        kPxPerTime * std::clamp(times[k] - sets_off, 0.0, kAcrossPx / kPxPerTime);
    EXPECT_NEAR(way.shown[k].x0, expected_x, 1e-9);
    if (k > 0) {
      EXPECT_LE(way.shown[k].x0 - way.shown[k - 1].x0, steps.reach_px[k] + 1e-9);
    }
  }
}

// A label standing still on the page at A, (0, 0), while its body runs on under it at kBodyPx
// a step (three times a step's reach); until step kPassed its arrow passes under A, so that no
// place lower is free, and at the shot's last step (before its event) something closes in on A
// and on every place less than kClearPx below it (another body's arrow tip, where A would read as
// that body's). Planned back from the last step, A shifted down by the least of the tries that
// clears it (kShiftPx a try) is added, and the label glides there on the page (beyond its body
// the way is kBodyPx a step longer, more than any step's reach) in time: it never runs into
// anything.
TEST(LabelWaysTest, AStandingLabelGetsOutOfTheWayByTheLastStepBeforeTheEvent) {
  constexpr double kBodyPx = 3.0 * kReachPx, kClearPx = 10.0, kShiftPx = 4.0;
  constexpr int kTries = 5;
  constexpr std::size_t kPassed = 6;
  const std::size_t last = kSteps - 1;
  const auto closing_in = [&](std::size_t k, const Box& box) {
    const bool passing_under = k < kPassed && box.y0 > 0.0;
    return passing_under || (k == last && box.y0 < kClearPx) ? kHard : 0.0;
  };
  WaySteps steps;
  for (std::size_t k = 0; k < kSteps; ++k) {
    steps.body_px.push_back({kBodyPx * static_cast<double>(k), 30.0});
    steps.reach_px.push_back(k > 0 ? kReachPx : 0.0);
    steps.boxes.push_back({at(0.0, 0.0)});
    steps.costs.push_back({closing_in(k, at(0.0, 0.0))});
  }
  steps.change_cost = 10.0;
  addEndingPlaces(steps, kShiftPx * kTries, kTries, kOneLine, closing_in);
  // The least multiple of kShiftPx that is at least kClearPx: 12 px down.
  const double shift_px = std::ceil(kClearPx / kShiftPx) * kShiftPx;
  ASSERT_EQ(steps.boxes.front().size(), 2u);
  for (std::size_t k = 0; k < kSteps; ++k) {
    EXPECT_EQ(steps.boxes[k][1].y0, shift_px);
    EXPECT_EQ(steps.boxes[k][1].x0, 0.0);
  }
  // Beyond its body only, no glide gets there: it stays on A and runs into it at the end.
  const Way beyond = endingWay(steps, {}, kHard, closing_in, kOneLine);
  EXPECT_EQ(beyond.shown[last].y0, 0.0);
  steps.glides_on_page = true;
  const Way way = endingWay(steps, {}, kHard, closing_in, kOneLine);
  EXPECT_EQ(way.jumps, 0u);
  EXPECT_EQ(way.shown[last].y0, shift_px);
  for (std::size_t k = 0; k < kSteps; ++k) {
    SCOPED_TRACE("step " + std::to_string(k));
    EXPECT_LT(closing_in(k, way.shown[k]), kOneLine);
    EXPECT_EQ(way.shown[k].x0, 0.0);
    if (k > 0) {
      EXPECT_LE(way.shown[k].y0 - way.shown[k - 1].y0, kReachPx + 1e-9);
    }
  }
}

}  // namespace
}  // namespace collide::compose
