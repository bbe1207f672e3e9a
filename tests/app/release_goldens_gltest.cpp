// SPDX-License-Identifier: MIT
// Goldens of the scenes where energy comes in (issue 44) at 1280x720, the size a teacher
// projects: spring-carts after the push (the energy bar with its released strip and legend
// entry), recoil as the bullet flies (the rifle recoiling), and the energy chart of the gas whose
// molecules carry one internal degree of freedom (internal energy relaxing to its dashed
// equipartition level, KE to its own). Each baseline was opened and looked at before it was
// committed.
#include <gtest/gtest.h>

#include "scene_goldens.hpp"

namespace collide::release_goldens {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

using test::GoldenShot;

class ReleaseGoldensGLTest : public ::testing::TestWithParam<GoldenShot> {};

TEST_P(ReleaseGoldensGLTest, MatchesItsGolden) {
  const GoldenShot& shot = GetParam();
  EXPECT_TRUE(test::sceneMatchesGolden(scene::loadPreset(shot.preset), shot.t_s, kWidth, kHeight,
                                       shot.golden));
}

INSTANTIATE_TEST_SUITE_P(Presets, ReleaseGoldensGLTest,
                         ::testing::Values(GoldenShot{"spring-carts", 1.5, "release_spring_carts"},
                                           GoldenShot{"recoil", 0.255, "release_recoil"}),
                         test::goldenShotName);

TEST(ReleaseGoldensGLTest, GasWithInsidesEnergyChart) {
  scene::SceneDesc scene = scene::loadPreset("ideal-gas");
  scene.internal_dof = 1;
  scene.view.chart_quantity = "energy";
  const compose::FrameSource source = app::animate(scene, {kWidth, kHeight}).frames;
  render::Renderer renderer(kWidth, kHeight);
  test::GoldenOptions options;
  options.renderer = renderer.glRendererName();
  EXPECT_TRUE(test::compareWithGolden(renderer.render(source.chartFrame()),
                                      "app/release_gas_internal_chart.png", options));
}

}  // namespace
}  // namespace collide::release_goldens
