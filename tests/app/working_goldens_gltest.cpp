// SPDX-License-Identifier: MIT
// Goldens of the working panel (issue 41) beside the scene at 1280x720, the size a teacher
// projects: the worked example after its impact, the ballistic pendulum on its rise and the
// glancing hit once every step has appeared (the steps show from the impact on, one each
// compose::kWorkingStepDelay_s). Each baseline was opened and looked at before it was committed.
#include <gtest/gtest.h>

#include "scene_goldens.hpp"

namespace collide::working_goldens {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

using test::GoldenShot;

class WorkingGoldensGLTest : public ::testing::TestWithParam<GoldenShot> {};

TEST_P(WorkingGoldensGLTest, MatchesItsGolden) {
  const GoldenShot& shot = GetParam();
  scene::SceneDesc scene = scene::loadPreset(shot.preset);
  scene.view.working = true;
  EXPECT_TRUE(test::sceneMatchesGolden(scene, shot.t_s, kWidth, kHeight, shot.golden));
}

INSTANTIATE_TEST_SUITE_P(
    Presets, WorkingGoldensGLTest,
    ::testing::Values(GoldenShot{"worked-example", 2.5, "working_worked_example"},
                      GoldenShot{"ballistic-pendulum", 1.25, "working_ballistic_pendulum"},
                      GoldenShot{"billiards-glancing", 1.2, "working_billiards_glancing"}),
    test::goldenShotName);

}  // namespace
}  // namespace collide::working_goldens
