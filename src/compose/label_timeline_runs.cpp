// SPDX-License-Identifier: MIT
// LabelTimeline's runs: the way one label takes through a run of steps (label_ways.hpp), priced
// with the shot's probes, from where it stood before the run to where it stands across the event
// that ends the shot.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "compose/label_cost.hpp"
#include "compose/label_timeline.hpp"
#include "compose/label_way_moves.hpp"
#include "compose/label_ways.hpp"

namespace collide::compose {
namespace {

// What changing its place in a shot costs a label, in lines of its text farther off at every
// step: it keeps one place through the shot where that costs less.
constexpr double kChangeLines = 20.0;
// The same in a 2D panel, where a label keeps its side of its ball more firmly: beside a ball in
// flight a change of place is seldom a glide (the places between run into the ball's turning
// arrow) but a jump, so a place a little better must not draw it off (bouncing-ball 640x360's
// m₁ swapped under its readout after the last bounces, 42 and 77 px).
constexpr double kChangeLines2d = 60.0;
// Where a label may stand still while its body moves on (label_ways.hpp's addStandingPlaces):
// its kStandPerStep cheapest places every kStandEvery steps, at most kStandStarts times a run.
constexpr std::size_t kStandEvery = 3;
constexpr std::size_t kStandStarts = 12;
constexpr std::size_t kStandPerStep = 2;
// What starting a shot elsewhere than where a label stood at its event costs, in overlaps: taken
// where staying on runs into something for at least a step.
constexpr double kEventJumpHards = 0.5;
// What a jump within a shot costs a label in a 2D panel, in overlaps: taken only where every way
// that glides runs into something for longer (a place it runs into is no place at all: the frame
// places it elsewhere, one jump there and another back). A ball in flight crosses the picture
// faster than any glide takes a label around it; along a track, bodies close in slowly enough.
constexpr double kInShotJumpHards = 0.5;
// How far a place free until the shot's last step before an event may be shifted to be free
// there too (label_ways.hpp's addEndingPlaces), in lines of its text, and in how many tries: a
// readout standing over the track gets out of the way of another body's arrow tip closing in
// by a part of a line, never into another row.
constexpr double kEndingShiftLines = 0.75;
constexpr int kEndingShiftTries = 6;

// What placement prefers of a place between its candidates: what the nearest one prefers, and a
// pixel for each pixel farther (as a slide along a row costs, label_candidates.cpp).
double preferenceAt(const Label& label, const Box& box) {
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < label.candidates.size() && c < label.base_cost.size(); ++c) {
    // A distance is never negative: a candidate that prefers no less than the least so far
    // cannot lower it (and hypot is dear where this runs for every standing place and step).
    if (label.base_cost[c] >= least) continue;
    const Box& place = label.candidates[c];
    least = std::min(least, label.base_cost[c] + std::hypot(box.x0 - place.x0, box.y0 - place.y0));
  }
  return std::isfinite(least) ? least : 0.0;
}

// How many of the steps are not halfway between two.
std::size_t wholeSteps(const WaySteps& ways) {
  return static_cast<std::size_t>(std::count(ways.halfway.begin(), ways.halfway.end(), false));
}

// `box` carried by its body from `body_px` to `then_px`, as wide and high as `size`. Along a
// track (not `two_d`), a text that narrows (a readout whose arrow is gone at an event, "v₁′ =
// 0 m/s") in a place wholly left of its body keeps its right edge, by its block, where its left
// edge would leave it standing off on its own; else its left edge stays.
Box carriedBox(const Box& box, const core::Vec2& body_px, const core::Vec2& then_px,
               const core::Vec2& size, bool two_d) {
  core::Vec2 corner = core::Vec2{box.x0, box.y0} + (then_px - body_px);
  const double width = box.x1 - box.x0;
  if (!two_d && box.x1 <= body_px.x() && size.x() < width) corner.x() += width - size.x();
  return {corner.x(), corner.y(), corner.x() + size.x(), corner.y() + size.y()};
}

// Where label `was` (a LabelTimeline::LabelAt) stood, carried by its body to `body_px`, as wide
// and high as `size`.
template <typename LabelAt>
Box whereItStood(const LabelAt& was, const core::Vec2& body_px, const core::Vec2& size,
                 bool two_d) {
  return carriedBox(was.shownBox(), was.body_px, body_px, size, two_d);
}

// Whether the label `was` (at the step before a run) runs into something carried along by its
// body to `now`, the run's first step, and nothing standing where it stood (`cost(0, box)`).
template <typename LabelAt, typename Cost>
bool standsWhereCarriedRunsInto(const LabelAt& was, const LabelAt& now, const Label& label,
                                const Cost& cost) {
  return cost(0, whereItStood(was, was.body_px, label.size, true)) < kHard &&
         cost(0, whereItStood(was, now.body_px, label.size, true)) >= kHard;
}

// Where `was` stood at the step before the run (the shot before's last step at a shot's start,
// `at_event`), carried along by its body, as each step's last candidate: it starts there.
template <typename LabelAt, typename Cost>
void startWhereItStood(WaySteps& ways, const std::vector<LabelAt*>& at,
                       const std::vector<const Label*>& label, const LabelAt& was, bool at_event,
                       bool two_d, const Cost& between_cost) {
  // In 2D, where its kind of places changes within the shot and the place it had runs into
  // something carried along, it stands where it stood if that is free: a bullet's readout where
  // its arrow vanishes in its last frame before the block (carried 145 px a frame into it).
  const bool stands = two_d && !at_event &&
                      standsWhereCarriedRunsInto(was, *at.front(), *label.front(), between_cost);
  for (std::size_t j = 0; j < at.size(); ++j) {
    const Box box = whereItStood(was, stands ? was.body_px : at[j]->body_px, label[j]->size, two_d);
    ways.boxes[j].push_back(box);
    ways.costs[j].push_back(between_cost(j, box));
  }
  ways.starts_on_last = true;
  // At the event that starts the shot it may start elsewhere instead, where staying on would
  // run into something: one jump at the event reads better than a label placed off its way
  // while it runs into something (elsewhere, frame by frame) and back.
  if (at_event) {
    ways.restart_cost = kEventJumpHards * kHard;
  } else if (two_d) {
    // Where its kind of places changes within the shot (its arrow grew past its ball's edge):
    // as anywhere in its shot, rather than a step where it stood running into something.
    ways.restart_cost = kInShotJumpHards * kHard;
  }
}

// What each place of `run`'s last step costs carried across the event that ends the shot to each
// of `instants` (the label there `then_of(end)`, null: none; the place there `carried(end, box)`);
// empty where none is given.
template <typename Instants, typename ThenOf, typename Carried>
std::vector<double> acrossCosts(const WaySteps& run, const Instants& instants,
                                const ThenOf& then_of, const Carried& carried, std::size_t panel) {
  std::vector<double> costs;
  for (const auto* end : instants) {
    const Label* then = then_of(*end);
    if (then == nullptr) continue;
    costs.resize(run.boxes.back().size(), 0.0);
    for (std::size_t c = 0; c < run.boxes.back().size(); ++c) {
      costs[c] += end->probe.cost(panel, *then, carried(*end, run.boxes.back()[c]), -1);
    }
  }
  return costs;
}

// The way through `ways` (label_ways.hpp's endingWay, each place at the last step costing
// `across(run)` more carried across the event). Where `shift_px` > 0, with places shifted up to
// that far that get out of the way by the last step (addEndingPlaces), gliding on the page
// between places that stand still, unless that way jumps more often than the one without.
template <typename Across, typename CostAt, typename BetweenCost>
Way plannedWay(WaySteps& ways, double shift_px, const Across& across, const CostAt& cost_at,
               const BetweenCost& between_cost) {
  const auto way_of = [&](WaySteps& run) {
    return endingWay(run, across(run), kEventJumpHards * kHard, cost_at, kOneLine);
  };
  if (!(shift_px > 0.0)) return way_of(ways);
  WaySteps ending = ways;
  ending.glides_on_page = true;
  addEndingPlaces(ending, shift_px, kEndingShiftTries, kOneLine, between_cost);
  Way way = way_of(ending);
  if (way.jumps == 0) return way;
  Way own = way_of(ways);
  return own.jumps < way.jumps ? own : way;
}

}  // namespace

void LabelTimeline::planRun(std::vector<Step>& steps, std::size_t first, std::size_t last,
                            const LabelAt* was, std::vector<LabelProbe>& probes, AfterEnd* after,
                            const LabelAt& key) const {
  std::vector<LabelAt*> at;
  std::vector<const Label*> label;
  WaySteps ways;
  for (std::size_t k = first; k <= last; ++k) {
    at.push_back(findLabel(steps[k].placed, key));
    label.push_back(probes[k].label(key.panel, key.body, key.velocity));
    ways.body_px.push_back(at.back()->body_px);
    ways.t_s.push_back(steps[k].t_s);
    ways.halfway.push_back(steps[k].halfway);
    ways.reach_px.push_back(k > first ? (steps[k].t_s - steps[k - 1].t_s) *
                                            glideSpeedAt(steps[k].t_s, key.two_d)
                                      : 0.0);
    ways.boxes.push_back(label.back()->candidates);
    std::vector<double> costs;
    for (std::size_t c = 0; c < label.back()->candidates.size(); ++c) {
      costs.push_back(probes[k].cost(key.panel, *label.back(), label.back()->candidates[c],
                                     static_cast<int>(c)));
    }
    ways.costs.push_back(std::move(costs));
  }
  ways.change_cost = (key.two_d ? kChangeLines2d : kChangeLines) * label.front()->size.y();
  const auto cost_at = [&](std::size_t j, const Box& box) {
    return probes[first + j].cost(key.panel, *label[j], box, -1);
  };
  // A place between its candidates costs what placement prefers there too: one kept where it
  // stood, or carried along from the run before, returns where placement prefers it.
  const auto between_cost = [&](std::size_t j, const Box& box) {
    return cost_at(j, box) + preferenceAt(*label[j], box);
  };
  if (key.two_d) ways.jump_cost = kInShotJumpHards * kHard;
  addStandingPlaces(ways, std::max<std::size_t>(kStandEvery, wholeSteps(ways) / kStandStarts),
                    kStandPerStep, kOneLine, between_cost);
  if (was != nullptr) startWhereItStood(ways, at, label, *was, first == 0, key.two_d, between_cost);
  // Where the shot ends at its next event, what each place at its last step costs carried
  // across it (the new arrows, bodies in contact), and on to the next shot's first step after
  // it: a readout whose text widens there (air-track's v₂′ through the wall bounce) leaves a
  // place it would not have there before the event, not at it (39 px at once).
  std::vector<AfterEnd*> instants;
  if (after != nullptr) instants.push_back(after);
  if (after != nullptr && !after->later.empty()) instants.push_back(&after->later.front());
  const auto then_of = [&](const AfterEnd& end) -> const Label* {
    const Label* then = end.probe.label(key.panel, key.body, key.velocity);
    return then != nullptr && key.panel < end.body_px.size() &&
                   key.body < end.body_px[key.panel].size()
               ? then
               : nullptr;
  };
  const auto carried = [&](const AfterEnd& end, const Box& box) {
    return carriedBox(box, at.back()->body_px, end.body_px[key.panel][key.body], then_of(end)->size,
                      key.two_d);
  };
  const auto across = [&](const WaySteps& run) {
    return acrossCosts(run, instants, then_of, carried, key.panel);
  };
  // Where the shot ends at an event along a track, places that get out of the way in time.
  const double shift_px =
      after != nullptr && !key.two_d ? kEndingShiftLines * label.front()->size.y() : 0.0;
  const Way way = plannedWay(ways, shift_px, across, cost_at, between_cost);
  for (std::size_t j = 0; j < at.size(); ++j) {
    at[j]->shown_px = core::Vec2{way.shown[j].x0, way.shown[j].y0};
    at[j]->rides = way.rides[j];
    at[j]->size_px = label[j]->size;
    const double cost = cost_at(j, way.shown[j]);
    at[j]->free = cost < kHard;
    at[j]->taken = cost < kOneLine;
    probes[first + j].fix(key.panel, *label[j], way.shown[j], -1);
  }
  for (AfterEnd* end : instants) {
    const Label* then = then_of(*end);
    if (then != nullptr) end->probe.fix(key.panel, *then, carried(*end, way.shown.back()), -1);
  }
}

}  // namespace collide::compose
