// SPDX-License-Identifier: MIT
// Which moves of a label fade (compose/label_fades.hpp): a label that jumps within a shot between
// two places of one kind (by its body, or in its legend) is not shown where it stands shorter
// than kShortestStay_s of playback (one fade less at the video's start or end), and fades out
// and in around such a stay; at an event a move to another place always fades. A label shown
// for less than a fade with nothing before or after it is a blink and not seen; a frame that
// shows a label where the plan does not have it shows it only where the plan shows it whole.
// Steps built here; every expected value from the fade's length, its frame of margin and the
// stays' lengths.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "compose/label_fades.hpp"

namespace collide {
namespace {

using compose::kFade_s;
using compose::kFadeGap_s;
using compose::kShortestStay_s;
using compose::LabelPlace;
using compose::PlaceAtStep;

constexpr double kWalkStep_s = 1.0 / 30.0;

// One stretch of steps at one place, every kWalkStep_s from from_s to to_s; `event`: its first step
// starts a shot. Played `slowdown` times slower than simulated (slow motion), from playback 0.
struct Stretch {
  double from_s, to_s;
  LabelPlace at;
  int place;
  bool event = false;
};

std::vector<PlaceAtStep> stretchSteps(const std::vector<Stretch>& stretches,
                                      double slowdown = 1.0) {
  std::vector<PlaceAtStep> steps;
  for (const Stretch& stretch : stretches) {
    for (int k = 0; stretch.from_s + k * kWalkStep_s <= stretch.to_s + 1e-9; ++k) {
      PlaceAtStep step{stretch.from_s + k * kWalkStep_s, stretch.at, stretch.event && k == 0,
                       stretch.place};
      step.playback_s = slowdown * step.t_s;
      steps.push_back(step);
    }
  }
  return steps;
}

// Whether each step is hidden, in order.
std::vector<bool> hiddenSteps(const std::vector<PlaceAtStep>& steps) {
  std::vector<bool> hidden;
  for (const PlaceAtStep& step : steps) hidden.push_back(step.hidden);
  return hidden;
}

// The same for steps whose times fall in [from_s, to_s] hidden, the others not.
std::vector<bool> hiddenWithin(const std::vector<PlaceAtStep>& steps, double from_s, double to_s) {
  std::vector<bool> hidden;
  for (const PlaceAtStep& step : steps) {
    hidden.push_back(step.t_s >= from_s - 1e-9 && step.t_s <= to_s + 1e-9);
  }
  return hidden;
}

TEST(LabelStaysTest, AStayTooShortToReadBetweenJumpsIsHidden) {
  for (const LabelPlace at : {LabelPlace::kBody, LabelPlace::kLegend}) {
    // 1.5 s, then 0.5 s (shorter than kShortestStay_s), then 1.5 s: the middle stay is hidden.
    ASSERT_LT(0.5, kShortestStay_s);
    ASSERT_GE(1.5, kShortestStay_s);
    std::vector<PlaceAtStep> steps = stretchSteps(
        {{0.0, 1.5, at, 0}, {1.5 + kWalkStep_s, 2.0, at, 1}, {2.0 + kWalkStep_s, 3.5, at, 2}});
    compose::hideShortStays(steps, false, false);
    EXPECT_EQ(hiddenSteps(steps), hiddenWithin(steps, 1.5 + kWalkStep_s, 2.0));
    // 1.2 s and 1.3 s: both long enough, nothing hidden.
    ASSERT_GE(1.2, kShortestStay_s);
    std::vector<PlaceAtStep> long_stays =
        stretchSteps({{0.0, 1.2, at, 0}, {1.2 + kWalkStep_s, 2.5, at, 1}});
    compose::hideShortStays(long_stays, false, false);
    EXPECT_EQ(hiddenSteps(long_stays), std::vector<bool>(long_stays.size(), false));
  }
}

TEST(LabelStaysTest, AStayTheFramesTakeOffThePlanIsHiddenWhereShort) {
  // Planned at place 0 throughout; the frames show it elsewhere from 0.5333 s to 0.7 s (a stay
  // off the plan, shorter than kShortestStay_s): hidden there. The planned stay before it, 0.5 s
  // from the start, is not: it fades out before the frames move it, as at any change.
  ASSERT_LT(0.7 - 0.5, kShortestStay_s);
  std::vector<PlaceAtStep> steps = stretchSteps({{0.0, 0.5, LabelPlace::kBody, 0},
                                                 {0.5 + kWalkStep_s, 0.7, LabelPlace::kBody, -1},
                                                 {0.7 + kWalkStep_s, 2.5, LabelPlace::kBody, 0}});
  for (PlaceAtStep& step : steps) step.off_plan = step.place < 0;
  compose::hideShortStays(steps, true, true);
  EXPECT_EQ(hiddenSteps(steps), hiddenWithin(steps, 0.5 + kWalkStep_s, 0.7));
  EXPECT_DOUBLE_EQ(compose::placeOpacity(steps, true, LabelPlace::kBody, 0.1, 0.1), 1.0);
  EXPECT_DOUBLE_EQ(compose::placeOpacity(steps, true, LabelPlace::kBody, 0.6, 0.6), 0.0);
}

TEST(LabelStaysTest, AStayIsMeasuredInPlaybackTime) {
  // 0.5 s simulated between two jumps is 2 s of playback in slow motion at 4 times: not hidden.
  ASSERT_GE(4.0 * 0.5, kShortestStay_s);
  std::vector<PlaceAtStep> steps = stretchSteps({{0.0, 1.5, LabelPlace::kBody, 0},
                                                 {1.5 + kWalkStep_s, 2.0, LabelPlace::kBody, 1},
                                                 {2.0 + kWalkStep_s, 3.5, LabelPlace::kBody, 2}},
                                                4.0);
  compose::hideShortStays(steps, false, false);
  EXPECT_EQ(hiddenSteps(steps), std::vector<bool>(steps.size(), false));
}

TEST(LabelStaysTest, AStayAtTheVideosStartOrEndNeedsOneFadeLess) {
  // 0.8 s at the start, then 1.5 s, then 0.8 s to the end: at least kShortestStay_s - kFade_s,
  // shown where the video starts or ends there, hidden where it does not.
  ASSERT_GE(0.8, kShortestStay_s - kFade_s);
  ASSERT_LT(0.8, kShortestStay_s);
  const std::vector<PlaceAtStep> walked =
      stretchSteps({{0.0, 0.8, LabelPlace::kBody, 0},
                    {0.8 + kWalkStep_s, 2.3, LabelPlace::kBody, 1},
                    {2.3 + kWalkStep_s, 3.1, LabelPlace::kBody, 2}});
  std::vector<PlaceAtStep> whole = walked;
  compose::hideShortStays(whole, true, true);
  EXPECT_EQ(hiddenSteps(whole), std::vector<bool>(whole.size(), false));
  std::vector<PlaceAtStep> middle = walked;
  compose::hideShortStays(middle, false, false);
  std::vector<bool> expected = hiddenWithin(middle, 0.0, 0.8);
  const std::vector<bool> at_end = hiddenWithin(middle, 2.3 + kWalkStep_s, 3.1);
  for (std::size_t k = 0; k < expected.size(); ++k) expected[k] = expected[k] || at_end[k];
  EXPECT_EQ(hiddenSteps(middle), expected);
}

TEST(LabelStaysTest, AtAnEventAMoveToAnotherPlaceStaysAMoveHoweverShort) {
  std::vector<PlaceAtStep> steps = stretchSteps(
      {{0.0, 0.5, LabelPlace::kBody, 0}, {0.5 + kWalkStep_s, 0.7, LabelPlace::kBody, 1, true}});
  compose::hideShortStays(steps, false, false);
  EXPECT_EQ(hiddenSteps(steps), std::vector<bool>(steps.size(), false));
}

TEST(LabelStaysTest, AroundAHiddenStayTheLabelFadesOutAndIn) {
  // 1.5 s at place 0, 0.5 s at place 1 (hidden), 1.5 s at place 2.
  std::vector<PlaceAtStep> steps = stretchSteps({{0.0, 1.5, LabelPlace::kBody, 0},
                                                 {1.5 + kWalkStep_s, 2.0, LabelPlace::kBody, 1},
                                                 {2.0 + kWalkStep_s, 3.5, LabelPlace::kBody, 2}});
  compose::hideShortStays(steps, true, true);
  const auto opacity = [&steps](double t_s) {
    return compose::placeOpacity(steps, true, LabelPlace::kBody, t_s, t_s);
  };
  // Whole, then fading out so that it is gone kFadeGap_s before its last step at place 0.
  EXPECT_DOUBLE_EQ(opacity(0.5), 1.0);
  const double half_out_s = 1.5 - kFadeGap_s - 0.5 * kFade_s;
  EXPECT_NEAR(opacity(half_out_s), 0.5, 1e-9);
  EXPECT_DOUBLE_EQ(opacity(1.5), 0.0);
  // Not seen through the short stay.
  for (const double t : {1.6, 1.8, 2.0}) EXPECT_DOUBLE_EQ(opacity(t), 0.0) << t;
  // Fading in from its first step at place 2, whole a fade later.
  const double arrives_s = 2.0 + kWalkStep_s;
  EXPECT_NEAR(opacity(arrives_s + 0.5 * kFade_s), 0.5, 1e-9);
  EXPECT_DOUBLE_EQ(opacity(arrives_s + kFade_s + 0.1), 1.0);
}

TEST(LabelStaysTest, AFadeLastsItsLengthInPlayback) {
  // In slow motion at 4 times, 1.5 s at place 0 then 1.5 s at place 1 (6 s of playback each):
  // half faded out kFadeGap_s + kFade_s / 2 of playback before its last step at place 0, a
  // quarter of that in simulated time.
  constexpr double kSlowdown = 4.0;
  std::vector<PlaceAtStep> steps = stretchSteps(
      {{0.0, 1.5, LabelPlace::kBody, 0}, {1.5 + kWalkStep_s, 3.0, LabelPlace::kBody, 1}},
      kSlowdown);
  compose::hideShortStays(steps, true, true);
  const double half_out_playback_s = kSlowdown * 1.5 - kFadeGap_s - 0.5 * kFade_s;
  EXPECT_NEAR(compose::placeOpacity(steps, true, LabelPlace::kBody, half_out_playback_s / kSlowdown,
                                    half_out_playback_s),
              0.5, 1e-9);
}

TEST(LabelStaysTest, AFrameARoundingErrorBeforeAnEventShowsTheShotBefore) {
  // Place 0 to the event at 1.0 s (its last step there), place 1 from the event on. A frame
  // whose time falls a rounding error before the event shows the shot before: gone (it faded
  // out before its last step there), not whole at its new place.
  std::vector<PlaceAtStep> steps = stretchSteps({{0.0, 1.0, LabelPlace::kBody, 0}});
  const std::vector<PlaceAtStep> after = stretchSteps({{1.0, 2.0, LabelPlace::kBody, 1, true}});
  steps.insert(steps.end(), after.begin(), after.end());
  const double just_before_s = std::nextafter(after.front().t_s, 0.0);
  EXPECT_DOUBLE_EQ(
      compose::placeOpacity(steps, true, LabelPlace::kBody, just_before_s, just_before_s), 0.0);
  EXPECT_DOUBLE_EQ(
      compose::placeOpacity(steps, true, LabelPlace::kBody, after.front().t_s, after.front().t_s),
      1.0);
}

TEST(LabelStaysTest, BodyToLegendIsAChangeOfPlaceNotAJump) {
  std::vector<PlaceAtStep> steps = stretchSteps(
      {{0.0, 0.3, LabelPlace::kBody, 0}, {0.3 + kWalkStep_s, 0.6, LabelPlace::kLegend, 1}});
  compose::hideShortStays(steps, false, false);
  EXPECT_EQ(hiddenSteps(steps), std::vector<bool>(steps.size(), false));
}

TEST(LabelStaysTest, ALabelShownForLessThanAFadeBetweenNothingIsNotSeen) {
  // Shown from 0.5 s; the next step where it is not is 0.6 s: 0.1 s, under kFade_s.
  const std::vector<PlaceAtStep> blink =
      stretchSteps({{0.0, 0.5 - kWalkStep_s, LabelPlace::kNowhere, 0},
                    {0.5, 0.5 + 2 * kWalkStep_s, LabelPlace::kBody, 1},
                    {0.6, 1.0, LabelPlace::kNowhere, 0}});
  ASSERT_LT(0.1, kFade_s);
  for (const double t : {0.5, 0.55, 0.58}) {
    EXPECT_DOUBLE_EQ(compose::placeOpacity(blink, true, LabelPlace::kBody, t, t), 0.0) << t;
  }
  // Shown from 0.5 s to 1.0 s (the next step 1.033 s): longer than a fade, whole.
  const std::vector<PlaceAtStep> seen =
      stretchSteps({{0.0, 0.5 - kWalkStep_s, LabelPlace::kNowhere, 0},
                    {0.5, 1.0, LabelPlace::kBody, 1},
                    {1.0 + kWalkStep_s, 1.5, LabelPlace::kNowhere, 0}});
  ASSERT_GE(1.0 + kWalkStep_s - 0.5, kFade_s);
  EXPECT_DOUBLE_EQ(compose::placeOpacity(seen, true, LabelPlace::kBody, 0.75, 0.75), 1.0);
}

TEST(LabelStaysTest, AFrameOffThePlanShowsItOnlyWhereThePlanShowsItWhole) {
  // By its body to 1.0 s, then listed: its fade out by the body ends kFadeGap_s before 1.0 s.
  const std::vector<PlaceAtStep> steps = stretchSteps(
      {{0.0, 1.0, LabelPlace::kBody, 0}, {1.0 + kWalkStep_s, 2.0, LabelPlace::kLegend, 1}});
  // A frame at 0.95 s that lists it early, while the plan fades it out by its body at
  // (its last step there - kFadeGap_s - 0.95) / kFade_s: not seen in the legend.
  double last_by_body_s = 0.0;
  for (const PlaceAtStep& step : steps) {
    if (step.at == LabelPlace::kBody) last_by_body_s = step.t_s;
  }
  const double planned = (last_by_body_s - kFadeGap_s - 0.95) / kFade_s;
  ASSERT_GT(planned, 0.0);
  ASSERT_LT(planned, 1.0);
  EXPECT_DOUBLE_EQ(compose::placeOpacity(steps, true, LabelPlace::kBody, 0.95, 0.95), planned);
  EXPECT_DOUBLE_EQ(compose::placeOpacity(steps, true, LabelPlace::kLegend, 0.95, 0.95), 0.0);
  // At 0.2 s the plan shows it whole by its body: a frame that lists it shows it whole.
  EXPECT_DOUBLE_EQ(compose::placeOpacity(steps, true, LabelPlace::kLegend, 0.2, 0.2), 1.0);
}

}  // namespace
}  // namespace collide
