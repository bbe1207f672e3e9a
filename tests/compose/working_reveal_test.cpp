// SPDX-License-Identifier: MIT
// When the working panel's steps show (issue 41), on the frame description: a still at t is the
// video's frame at t, so before the impact it shows the given values only, the laws from the
// impact on, and the whole working once every step has appeared; every step has appeared by the
// end of the scene, however soon after the impact it ends; a strobe picture, the whole run in one
// image, shows the whole working. The worked example's carts meet at t = 3.5 m / 3 m/s = 7/6 s
// (their facing edges 4 m - 0.5 m apart, closing at 2 - (-1) m/s); its given values are the two
// masses, the two velocities and e: five lines under their heading.
#include <gtest/gtest.h>

#include "app/animation.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

constexpr double kImpact_s = 3.5 / 3.0;
constexpr int kGivenLines = 1 + 5;  // the heading and m1, m2, v1, v2, e

compose::FrameSource workedExample(double duration_s) {
  scene::SceneDesc scene = scene::loadPreset("worked-example");
  scene.view.working = true;
  scene.duration_s = duration_s;
  return app::animate(scene, {640, 360}).frames;
}

// Lines shown at t, and the working's line count.
std::pair<int, int> shownAt(const compose::FrameSource& source, double t_s) {
  const frame::FrameModel frame = source.frameAtSimulated(t_s);
  EXPECT_TRUE(frame.working.has_value());
  if (!frame.working) return {0, 0};
  return {frame.working->shown_lines, static_cast<int>(frame.working->lines.size())};
}

bool isHeading(const compose::FrameSource& source, int line) {
  const frame::FrameModel frame = source.frameAtSimulated(0.0);
  return frame.working->lines.at(static_cast<std::size_t>(line)).sides.empty();
}

TEST(WorkingRevealTest, BeforeTheImpactTheGivenValuesThenTheStepsInTurn) {
  const compose::FrameSource source = workedExample(4.0);
  EXPECT_EQ(shownAt(source, 0.0).first, kGivenLines);
  EXPECT_EQ(shownAt(source, kImpact_s - 0.01).first, kGivenLines);
  // From the impact on the laws: whole steps, each ending where the next heading starts.
  const auto [at_impact, lines] = shownAt(source, kImpact_s + 0.01);
  EXPECT_GT(at_impact, kGivenLines);
  ASSERT_LT(at_impact, lines);
  EXPECT_TRUE(isHeading(source, at_impact));
  EXPECT_EQ(shownAt(source, 2.5).first, lines);  // the still a teacher takes after the impact
}

TEST(WorkingRevealTest, EveryStepHasAppearedByTheEnd) {
  // The scene ends 0.1 s after the impact: less than one step's usual delay.
  const compose::FrameSource source = workedExample(kImpact_s + 0.1);
  const auto [at_end, lines] = shownAt(source, kImpact_s + 0.1);
  EXPECT_EQ(at_end, lines);
  EXPECT_EQ(shownAt(source, kImpact_s - 0.01).first, kGivenLines);
}

TEST(WorkingRevealTest, AStrobePictureShowsTheWholeWorking) {
  const compose::FrameSource source = workedExample(kImpact_s + 0.1);
  const frame::FrameModel strobe = source.strobeFrame(0.0);
  ASSERT_TRUE(strobe.working.has_value());
  EXPECT_EQ(strobe.working->shown_lines, -1);
}

}  // namespace
}  // namespace collide
