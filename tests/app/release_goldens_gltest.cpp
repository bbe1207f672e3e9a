// SPDX-License-Identifier: MIT
// Goldens of the scenes where energy comes in (issue 44) at 1280x720, the size a teacher
// projects: spring-carts after the push (the energy bar with its released strip and legend
// entry), recoil as the bullet flies (the rifle recoiling), and the energy chart of the gas whose
// molecules carry one internal degree of freedom (internal energy relaxing to its dashed
// equipartition level, KE to its own). Each baseline was opened and looked at before it was
// committed.
#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "app/animation.hpp"
#include "golden.hpp"
#include "render/renderer.hpp"
#include "scene/scene_desc.hpp"

namespace collide::release_goldens {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

struct ReleaseShot {
  const char* preset;
  double t_s;          // simulated; below 0: the scene's chart alone
  int internal_dof;    // molecules with insides (0: as the preset has it)
  const char* golden;  // also the test's name
};

void PrintTo(const ReleaseShot& shot, std::ostream* out) {
  *out << shot.preset << " at " << shot.t_s << " s";
}

class ReleaseGoldensGLTest : public ::testing::TestWithParam<ReleaseShot> {};

TEST_P(ReleaseGoldensGLTest, MatchesItsGolden) {
  const ReleaseShot& shot = GetParam();
  scene::SceneDesc scene = scene::loadPreset(shot.preset);
  if (shot.internal_dof > 0) {
    scene.internal_dof = shot.internal_dof;
    scene.view.chart_quantity = "energy";
  }
  const compose::FrameSource source = app::animate(scene, {kWidth, kHeight}).frames;
  render::Renderer renderer(kWidth, kHeight);
  test::GoldenOptions options;
  options.renderer = renderer.glRendererName();
  const frame::FrameModel frame =
      shot.t_s < 0.0 ? source.chartFrame() : source.frameAtSimulated(shot.t_s);
  EXPECT_TRUE(test::compareWithGolden(renderer.render(frame),
                                      std::string("app/") + shot.golden + ".png", options));
}

INSTANTIATE_TEST_SUITE_P(
    Presets, ReleaseGoldensGLTest,
    ::testing::Values(ReleaseShot{"spring-carts", 1.5, 0, "release_spring_carts"},
                      ReleaseShot{"recoil", 0.255, 0, "release_recoil"},
                      ReleaseShot{"ideal-gas", -1.0, 1, "release_gas_internal_chart"}),
    [](const ::testing::TestParamInfo<ReleaseShot>& info) {
      return std::string(info.param.golden);
    });

}  // namespace
}  // namespace collide::release_goldens
