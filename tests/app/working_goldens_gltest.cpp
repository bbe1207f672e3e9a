// SPDX-License-Identifier: MIT
// Goldens of the working panel (issue 41) beside the scene at 1280x720, the size a teacher
// projects: the worked example after its impact, the ballistic pendulum on its rise and the
// glancing hit once every step has appeared (the steps show from the impact on, one each
// compose::kWorkingStepDelay_s). Each baseline was opened and looked at before it was committed.
#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "app/animation.hpp"
#include "golden.hpp"
#include "render/renderer.hpp"
#include "scene/scene_desc.hpp"

namespace collide::working_goldens {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

struct WorkingShot {
  const char* preset;
  double t_s;
  const char* golden;  // also the test's name
};

void PrintTo(const WorkingShot& shot, std::ostream* out) {
  *out << shot.preset << " at " << shot.t_s << " s";
}

class WorkingGoldensGLTest : public ::testing::TestWithParam<WorkingShot> {};

TEST_P(WorkingGoldensGLTest, MatchesItsGolden) {
  const WorkingShot& shot = GetParam();
  scene::SceneDesc scene = scene::loadPreset(shot.preset);
  scene.view.working = true;
  const compose::FrameSource source = app::animate(scene, {kWidth, kHeight}).frames;
  render::Renderer renderer(kWidth, kHeight);
  test::GoldenOptions options;
  options.renderer = renderer.glRendererName();
  EXPECT_TRUE(test::compareWithGolden(renderer.render(source.frameAtSimulated(shot.t_s)),
                                      std::string("app/") + shot.golden + ".png", options));
}

INSTANTIATE_TEST_SUITE_P(
    Presets, WorkingGoldensGLTest,
    ::testing::Values(WorkingShot{"worked-example", 2.5, "working_worked_example"},
                      WorkingShot{"ballistic-pendulum", 1.25, "working_ballistic_pendulum"},
                      WorkingShot{"billiards-glancing", 1.2, "working_billiards_glancing"}),
    [](const ::testing::TestParamInfo<WorkingShot>& info) {
      return std::string(info.param.golden);
    });

}  // namespace
}  // namespace collide::working_goldens
