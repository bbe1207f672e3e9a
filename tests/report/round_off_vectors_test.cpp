// SPDX-License-Identifier: MIT
// Nothing a report writes shows a vector's component that is round-off of zero (issue 37): beside
// its partner it reads 0, as on the pictures (text::formatComponentsIn). newtons-cradle's total
// momentum read "(−0.00997, −0.000000526) kg·m/s" in its closing caption and on its lesson page.
// Checked on the narration's closing cue, the lesson page's table and the working's given
// velocities (collide solve), each from a world made here.
#include <gtest/gtest.h>

#include <string>

#include "physics/simulate.hpp"
#include "report/lesson_page.hpp"
#include "report/narration.hpp"
#include "report_test_scenes.hpp"
#include "working/working.hpp"
#include "working/writers.hpp"

namespace collide::report {
namespace {

// The cradle's total momentum at its end: x shown to three figures, so in steps of 0.00001; y is
// far below half such a step, so beside x it is round-off of zero and reads 0.
const core::Vec2 kCradleMomentum{-0.00997, -0.000000526};
const std::string kCradleShown = "(\u22120.00997, 0) kg\u00b7m/s";

// One 1 kg disk alone in a plane, moving at v (so its momentum is v in kg·m/s), for 1 s.
physics::Timeline loneDisk(const core::Vec2& v_mps) {
  physics::WorldDef world;
  world.dimensions = 2;
  world.duration_s = 1.0;
  world.bodies.push_back({"disk", physics::Shape::kDisk, 1.0, 0.1, {0.0, 0.0}, v_mps});
  return physics::simulate(world);
}

TEST(RoundOffVectorsTest, TheClosingCaptionsMomentumReadsZeroForRoundOff) {
  const std::vector<Cue> cues = narrate(loneDisk(kCradleMomentum), {});
  ASSERT_FALSE(cues.empty());
  EXPECT_TRUE(test::contains(cues.back().text, "Total momentum " + kCradleShown))
      << cues.back().text;
}

TEST(RoundOffVectorsTest, TheLessonPagesMomentumReadsZeroForRoundOff) {
  int momentum_rows = 0;
  for (const LessonRow& row : lessonNumbers(loneDisk(kCradleMomentum))) {
    if (!test::contains(row.quantity, "momentum")) continue;
    EXPECT_EQ(row.value, kCradleShown) << row.quantity;
    ++momentum_rows;
  }
  EXPECT_EQ(momentum_rows, 2);  // at the start and at the end
}

// A 1 kg disk at 2 m/s along x, its y velocity a sway far below half a step of "2.00" (0.005),
// strikes a disk at rest head on: the working gives its velocity as (2.00, 0).
TEST(RoundOffVectorsTest, TheWorkingsGivenVelocityReadsZeroForRoundOff) {
  physics::WorldDef world;
  world.dimensions = 2;
  world.duration_s = 2.0;
  world.bodies.push_back({"one", physics::Shape::kDisk, 1.0, 0.1, {-1.0, 0.0}, {2.0, 0.000000526}});
  world.bodies.push_back({"two", physics::Shape::kDisk, 1.0, 0.1, {1.0, 0.0}, {0.0, 0.0}});
  const physics::Timeline timeline = physics::simulate(world);
  ASSERT_GE(working::impactCount(timeline), 1u);
  const std::string text = working::writeText(working::workingFor(timeline, 0));
  EXPECT_TRUE(test::contains(text, "v\u2081 = (2.00, 0) m/s")) << text;
}

}  // namespace
}  // namespace collide::report
