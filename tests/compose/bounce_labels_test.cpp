// SPDX-License-Identifier: MIT
// A ball's labels across a bounce (issue 37, layout planned over time): bouncing-ball at 640x360
// bounces at about 2.06 s. Its readout, planned before its mass label, glided up after the bounce
// into the place "m₁ = 0.600 kg" stood on across it, and the mass label left that place in one
// jump at the bounce, 184 px, to the other side of the ball (compose/label_timeline_ways.cpp:
// a shot whose labels jump is planned again with the mass labels first). Across the bounce no
// label moves more than kEventPx beyond its ball, and before it no more than kCalmPx. Lays out
// seven frames after planning the video's first four shots: well under a second.
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "render/frame_layout.hpp"
#include "scene/scene_desc.hpp"
#include "video_frame_checks.hpp"

namespace collide {
namespace {

constexpr int kFps = 60;
// The ball's mass label, as `collide layout` names it.
const std::string kMassLabel = "mass.1";

TEST(BounceLabelsTest, MassLabelStaysByItsBallAcrossABounce) {
  constexpr int kWidthPx = 640, kHeightPx = 360;
  const app::Animation animation =
      app::animate(scene::loadPreset("bouncing-ball"), {kWidthPx, kHeightPx});
  // The frames from 2.0 s to 2.1 s, and the bounce between two of them.
  constexpr int kFirst = 120, kLast = 126;
  const double from_s = static_cast<double>(kFirst) / kFps,
               to_s = static_cast<double>(kLast) / kFps;
  std::optional<double> bounce_s;
  for (const physics::CollisionEvent& event : animation.frames.panelTimeline(0).collisions()) {
    if (event.time_s > from_s && event.time_s < to_s) bounce_s = event.time_s;
  }
  ASSERT_TRUE(bounce_s.has_value()) << "a bounce between " << from_s << " and " << to_s << " s";
  std::optional<test::FrameItems> was;
  for (int k = kFirst; k <= kLast; ++k) {
    const double t_s = static_cast<double>(k) / kFps;
    const test::FrameItems now = test::frameItems(
        t_s, render::drawnItems(animation.frames.frameAtSimulated(t_s), kWidthPx, kHeightPx));
    EXPECT_EQ(now.texts.count(kMassLabel), 1u) << "m₁ by its ball at " << t_s << " s";
    if (was) {
      const double limit_px = t_s > *bounce_s ? test::kEventPx : test::kCalmPx;
      for (const std::string& jump :
           test::textsThatJump(*was, now, limit_px, test::TextsOf::kBodies)) {
        ADD_FAILURE() << jump;
      }
    }
    was = now;
  }
}

}  // namespace
}  // namespace collide
