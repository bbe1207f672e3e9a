// SPDX-License-Identifier: MIT
// A label changing places between its body and its legend fades out at the one and then in at
// the other (compose/label_fades.hpp): its opacity from the steps of the layout over time, worked
// out here from the fade's length and the frame it is gone early; and perfectly-inelastic's v₂,
// which leaves block 2 for the legend at about 0.77 s while the blocks close in, read frame by
// frame up to the impact as `collide layout --fps 60` writes them: never at both places, each
// fade at least 0.3 s (18 frames at 60 fps), and whole in the still at the same instant.
#include "compose/label_fades.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "render/frame_layout.hpp"
#include "scene/scene_io.hpp"
#include "video_frame_checks.hpp"

namespace collide {
namespace {

using compose::kFade_s;
using compose::kFadeGap_s;
using compose::LabelPlace;
using compose::PlaceAtStep;

constexpr double kStep_s = 1.0 / 30.0;

// Steps every kStep_s from 0: by its body up to body_until_s, then listed to 2 s; the first
// listed step starts a shot where `at_event`.
std::vector<PlaceAtStep> leaving(double body_until_s, bool at_event) {
  std::vector<PlaceAtStep> steps;
  for (int k = 0; k * kStep_s <= 2.0 + 1e-9; ++k) {
    const double t = k * kStep_s;
    const bool by_body = t <= body_until_s + 1e-9;
    const bool first_listed = !by_body && !steps.empty() && steps.back().at == LabelPlace::kBody;
    steps.push_back(
        {t, by_body ? LabelPlace::kBody : LabelPlace::kLegend, at_event && first_listed});
    steps.back().playback_s = t;
  }
  return steps;
}

// The opacity at t_s of a video played as fast as simulated (compose::placeOpacity).
double opacityAt(const std::vector<PlaceAtStep>& steps, bool from_start, LabelPlace shown,
                 double t_s) {
  return compose::placeOpacity(steps, from_start, shown, t_s, t_s);
}

TEST(LabelFadesTest, ALabelFadesOutByItsBodyThenInInItsLegend) {
  const std::vector<PlaceAtStep> steps = leaving(1.0, false);
  const double last_by_body = 1.0, first_listed = 1.0 + kStep_s;
  // By its body: whole until a fade and a frame before its last step there, then falling
  // linearly to nothing a frame before that step.
  EXPECT_DOUBLE_EQ(opacityAt(steps, true, LabelPlace::kBody, 0.5), 1.0);
  EXPECT_NEAR(opacityAt(steps, true, LabelPlace::kBody, last_by_body - kFadeGap_s - 0.5 * kFade_s),
              0.5, 1e-9);
  EXPECT_NEAR(opacityAt(steps, true, LabelPlace::kBody, last_by_body - kFadeGap_s), 0.0, 1e-9);
  // Between the two steps a frame may show it at either place: at neither is it seen.
  const double between = 0.5 * (last_by_body + first_listed);
  EXPECT_DOUBLE_EQ(opacityAt(steps, true, LabelPlace::kBody, between), 0.0);
  EXPECT_DOUBLE_EQ(opacityAt(steps, true, LabelPlace::kLegend, between), 0.0);
  // In its legend: rising from its first step there, whole a fade later.
  EXPECT_NEAR(opacityAt(steps, true, LabelPlace::kLegend, first_listed + 0.25 * kFade_s), 0.25,
              1e-9);
  EXPECT_DOUBLE_EQ(opacityAt(steps, true, LabelPlace::kLegend, first_listed + kFade_s), 1.0);
}

TEST(LabelFadesTest, ReachedAtAnEventItStandsWholeFromTheEventOn) {
  const std::vector<PlaceAtStep> steps = leaving(1.0, true);
  // A still just after an impact shows the label whole where it went; it faded out before.
  EXPECT_DOUBLE_EQ(opacityAt(steps, true, LabelPlace::kLegend, 1.0 + kStep_s + 1e-3), 1.0);
  EXPECT_NEAR(opacityAt(steps, true, LabelPlace::kBody, 1.0 - kFadeGap_s - 0.5 * kFade_s), 0.5,
              1e-9);
}

TEST(LabelFadesTest, AShortStayFromTheVideosStartIsNotSeenHalfWay) {
  // By its body for 0.2 s from the start, then listed: a fade out would show it half seen at
  // the first frame; it is listed from the start instead (nothing by its body).
  const std::vector<PlaceAtStep> steps = leaving(0.2, false);
  EXPECT_DOUBLE_EQ(opacityAt(steps, true, LabelPlace::kBody, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(opacityAt(steps, true, LabelPlace::kBody, 0.1), 0.0);
  // The same steps seen from the middle of a video (their first not the video's): it fades.
  EXPECT_NEAR(opacityAt(steps, false, LabelPlace::kBody, 0.1), (0.2 - kFadeGap_s - 0.1) / kFade_s,
              1e-9);
}

TEST(LabelFadesTest, ALegendLineThatVanishesAtAnEventIsWholeBeforeIt) {
  // Listed from 1.0333 s, its body merged with another at 1.5 s (shown nowhere from there): it
  // fades in whole before the event. Listed only from 1.4 s, the fade could not end by 1.5 s.
  for (const double listed_from_s : {1.0 + kStep_s, 1.4}) {
    std::vector<PlaceAtStep> steps = leaving(listed_from_s - kStep_s, false);
    for (PlaceAtStep& step : steps) {
      if (step.t_s >= 1.5 - 1e-9) step.at = LabelPlace::kNowhere;
    }
    const double last_frame = 1.5 - kFadeGap_s;
    const bool room = last_frame - listed_from_s >= kFade_s;
    EXPECT_DOUBLE_EQ(opacityAt(steps, true, LabelPlace::kLegend, last_frame), room ? 1.0 : 0.0)
        << listed_from_s;
  }
}

TEST(LabelFadesTest, AJumpByItsBodyFadesLikeAChangeOfPlace) {
  // By its body throughout, its way jumping at 1.0333 s from one place (0) to another (1).
  std::vector<PlaceAtStep> steps = leaving(2.5, false);
  for (PlaceAtStep& step : steps) step.place = step.t_s > 1.0 + 1e-9 ? 1 : 0;
  EXPECT_NEAR(opacityAt(steps, true, LabelPlace::kBody, 1.0 - kFadeGap_s - 0.5 * kFade_s), 0.5,
              1e-9);
  EXPECT_DOUBLE_EQ(opacityAt(steps, true, LabelPlace::kBody, 1.0 + 0.5 * kStep_s), 0.0);
  EXPECT_NEAR(opacityAt(steps, true, LabelPlace::kBody, 1.0 + kStep_s + 0.5 * kFade_s), 0.5, 1e-9);
}

TEST(LabelFadesTest, ALabelThatNeverChangesPlacesIsWhole) {
  std::vector<PlaceAtStep> steps = leaving(2.5, false);  // by its body throughout
  for (PlaceAtStep& step : steps) {
    if (step.t_s > 1.5) step.at = LabelPlace::kNowhere;  // its readout gone (its body stopped)
  }
  for (const double t : {0.0, 0.7, 1.49, 1.6}) {
    EXPECT_DOUBLE_EQ(opacityAt(steps, true, LabelPlace::kBody, t), 1.0) << t;
  }
}

// The opacity of the text `id` in `frame` (0: not drawn).
double opacityOf(const test::FrameItems& frame, const std::string& id) {
  const auto text = frame.texts.find(id);
  return text == frame.texts.end() ? 0.0 : text->second.opacity;
}

TEST(LabelFadesTest, PerfectlyInelasticsReadoutLeavesForItsLegendWithoutAJump) {
  constexpr int kFps = 60, kWidthPx = 1280, kHeightPx = 720;
  const app::Animation animation =
      app::animate(scene::loadPreset("perfectly-inelastic"), {kWidthPx, kHeightPx});
  const compose::FrameSource& source = animation.frames;
  std::vector<double> by_body, listed;  // velocity.2's opacity at each, frame by frame
  std::optional<double> fading_s;       // an instant it is fading by its body
  // From 0.3 s to the impact (the blocks merge and their readouts with them).
  ASSERT_FALSE(source.timeline().collisions().empty());
  const double impact_s = source.timeline().collisions().front().time_s;
  for (int k = static_cast<int>(0.3 * kFps); source.simulatedAt(double(k) / kFps) < impact_s; ++k) {
    const double t_s = source.simulatedAt(double(k) / kFps);
    const test::FrameItems items = test::frameItems(
        t_s, render::drawnItems(source.frameAt(double(k) / kFps), kWidthPx, kHeightPx));
    const double body = opacityOf(items, "velocity.2"),
                 legend = opacityOf(items, "legend.velocity.2");
    EXPECT_FALSE(body > 0.0 && legend > 0.0) << "shown at both places at t = " << t_s;
    by_body.push_back(body);
    listed.push_back(legend);
    if (body > 0.2 && body < 0.8) fading_s = t_s;
  }
  // It leaves: by its body first, then listed, whole there before the impact merges the blocks.
  ASSERT_DOUBLE_EQ(by_body.front(), 1.0);
  ASSERT_DOUBLE_EQ(*std::max_element(listed.begin(), listed.end()), 1.0);
  // Each fade lasts at least 0.3 s: 18 frames at 60 fps, no step larger than a share of that.
  const auto steady = [](const std::vector<double>& opacity) {
    int fading_frames = 0;
    for (std::size_t k = 1; k < opacity.size(); ++k) {
      EXPECT_LE(std::abs(opacity[k] - opacity[k - 1]), 1.0 / 18.0 + 1e-6) << "frame " << k;
      if (opacity[k] > 0.0 && opacity[k] < 1.0) ++fading_frames;
    }
    return fading_frames;
  };
  EXPECT_GE(steady(by_body), 17);
  EXPECT_GE(steady(listed), 17);
  // A still is whole: at an instant the video fades it, the still shows it solid, in its place.
  ASSERT_TRUE(fading_s);
  const test::FrameItems still = test::frameItems(
      *fading_s, render::drawnItems(source.frameAtSimulated(*fading_s), kWidthPx, kHeightPx));
  EXPECT_DOUBLE_EQ(opacityOf(still, "velocity.2"), 1.0);
}

}  // namespace
}  // namespace collide
