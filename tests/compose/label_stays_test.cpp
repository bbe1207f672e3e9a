// SPDX-License-Identifier: MIT
// Which moves of a label fade (compose/label_fades.hpp): a jump within a shot between two places
// of one kind (by its body, or in its legend) fades where it stands at least kShortestStay_s at
// each, and stays a jump where it stands shorter; at an event a move to another place always
// fades. A label shown for less than a fade with nothing before or after it is a blink and not
// seen; a frame that shows a label where the plan does not have it shows it only where the plan
// shows it whole. Steps built here; every expected value from the fade's length, its frame of
// margin and the stays' lengths.
#include <gtest/gtest.h>

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
// starts a shot.
struct Stretch {
  double from_s, to_s;
  LabelPlace at;
  int place;
  bool event = false;
};

std::vector<PlaceAtStep> stretchSteps(const std::vector<Stretch>& stretches) {
  std::vector<PlaceAtStep> steps;
  for (const Stretch& stretch : stretches) {
    for (int k = 0; stretch.from_s + k * kWalkStep_s <= stretch.to_s + 1e-9; ++k) {
      steps.push_back(
          {stretch.from_s + k * kWalkStep_s, stretch.at, stretch.event && k == 0, stretch.place});
    }
  }
  return steps;
}

std::vector<int> placeIds(const std::vector<PlaceAtStep>& steps) {
  std::vector<int> places;
  for (const PlaceAtStep& step : steps) places.push_back(step.place);
  return places;
}

TEST(LabelStaysTest, AJumpWithinAShotFadesOnlyWhereBothStaysLastASecond) {
  for (const LabelPlace at : {LabelPlace::kBody, LabelPlace::kLegend}) {
    // 0.5 s at the first place: shorter than kShortestStay_s, so the jump stays a jump.
    ASSERT_LT(0.5, kShortestStay_s);
    std::vector<PlaceAtStep> short_stay =
        stretchSteps({{0.0, 0.5, at, 0}, {0.5 + kWalkStep_s, 2.0, at, 1}});
    compose::joinShortStays(short_stay);
    EXPECT_EQ(placeIds(short_stay), std::vector<int>(short_stay.size(), 0));
    // 1.2 s and 1.3 s: both long enough, two places.
    ASSERT_GE(1.2, kShortestStay_s);
    std::vector<PlaceAtStep> long_stays =
        stretchSteps({{0.0, 1.2, at, 0}, {1.2 + kWalkStep_s, 2.5, at, 1}});
    const std::vector<int> before = placeIds(long_stays);
    compose::joinShortStays(long_stays);
    EXPECT_EQ(placeIds(long_stays), before);
  }
}

TEST(LabelStaysTest, AtAnEventAMoveToAnotherPlaceStaysAMoveHoweverShort) {
  std::vector<PlaceAtStep> steps = stretchSteps(
      {{0.0, 0.5, LabelPlace::kBody, 0}, {0.5 + kWalkStep_s, 0.7, LabelPlace::kBody, 1, true}});
  const std::vector<int> before = placeIds(steps);
  compose::joinShortStays(steps);
  EXPECT_EQ(placeIds(steps), before);
}

TEST(LabelStaysTest, AStayOnBothSidesOfAnEventIsMeasuredAsOne) {
  // 1.5 s before the event and 0.17 s after it at place 0, then 1.27 s at place 1: the stay at
  // place 0 lasts 1.7 s, so the jump fades.
  std::vector<PlaceAtStep> steps =
      stretchSteps({{0.0, 1.5, LabelPlace::kBody, 0},
                    {1.5 + kWalkStep_s, 1.7, LabelPlace::kBody, 0, true},
                    {1.7 + kWalkStep_s, 3.0, LabelPlace::kBody, 1}});
  const std::vector<int> before = placeIds(steps);
  compose::joinShortStays(steps);
  EXPECT_EQ(placeIds(steps), before);
}

TEST(LabelStaysTest, BodyToLegendIsAChangeOfPlaceNotAJump) {
  std::vector<PlaceAtStep> steps = stretchSteps(
      {{0.0, 0.3, LabelPlace::kBody, 0}, {0.3 + kWalkStep_s, 0.6, LabelPlace::kLegend, 1}});
  const std::vector<int> before = placeIds(steps);
  compose::joinShortStays(steps);
  EXPECT_EQ(placeIds(steps), before);
}

TEST(LabelStaysTest, ALabelShownForLessThanAFadeBetweenNothingIsNotSeen) {
  // Shown from 0.5 s; the next step where it is not is 0.6 s: 0.1 s, under kFade_s.
  const std::vector<PlaceAtStep> blink =
      stretchSteps({{0.0, 0.5 - kWalkStep_s, LabelPlace::kNowhere, 0},
                    {0.5, 0.5 + 2 * kWalkStep_s, LabelPlace::kBody, 1},
                    {0.6, 1.0, LabelPlace::kNowhere, 0}});
  ASSERT_LT(0.1, kFade_s);
  for (const double t : {0.5, 0.55, 0.58}) {
    EXPECT_DOUBLE_EQ(compose::placeOpacity(blink, true, LabelPlace::kBody, t), 0.0) << t;
  }
  // Shown from 0.5 s to 1.0 s (the next step 1.033 s): longer than a fade, whole.
  const std::vector<PlaceAtStep> seen =
      stretchSteps({{0.0, 0.5 - kWalkStep_s, LabelPlace::kNowhere, 0},
                    {0.5, 1.0, LabelPlace::kBody, 1},
                    {1.0 + kWalkStep_s, 1.5, LabelPlace::kNowhere, 0}});
  ASSERT_GE(1.0 + kWalkStep_s - 0.5, kFade_s);
  EXPECT_DOUBLE_EQ(compose::placeOpacity(seen, true, LabelPlace::kBody, 0.75), 1.0);
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
  EXPECT_DOUBLE_EQ(compose::placeOpacity(steps, true, LabelPlace::kBody, 0.95), planned);
  EXPECT_DOUBLE_EQ(compose::placeOpacity(steps, true, LabelPlace::kLegend, 0.95), 0.0);
  // At 0.2 s the plan shows it whole by its body: a frame that lists it shows it whole.
  EXPECT_DOUBLE_EQ(compose::placeOpacity(steps, true, LabelPlace::kLegend, 0.2), 1.0);
}

}  // namespace
}  // namespace collide
