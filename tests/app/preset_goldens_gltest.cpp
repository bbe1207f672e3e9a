// Goldens of the presets a teacher pastes into lecture notes, at the moment each one teaches:
// the break spreading the rack, the glancing hit after impact, the stuck pair turning, the
// granular chain mid-way, the pi blocks during their exchange, and the bullet before (its arrow
// off scale, with a break) and after it embeds (one body, one readable arrow). Each baseline was
// opened and looked at before it was committed.
#include <gtest/gtest.h>

#include "app/animation.hpp"
#include "golden.hpp"
#include "render/renderer.hpp"
#include "scene/scene_desc.hpp"

namespace collide::preset_goldens {
namespace {

constexpr int kWidth = 480, kHeight = 270;

::testing::AssertionResult presetMatchesGolden(const std::string& preset, double t_s,
                                               const std::string& name) {
  const compose::FrameSource source =
      app::animate(scene::loadPreset(preset), {kWidth, kHeight}).frames;
  render::Renderer renderer(kWidth, kHeight);
  test::GoldenOptions options;
  options.renderer = renderer.glRendererName();
  return test::compareWithGolden(renderer.render(source.frameAtSimulated(t_s)),
                                 "app/" + name + ".png", options);
}

TEST(PresetGoldensGLTest, BilliardsBreak) {
  EXPECT_TRUE(presetMatchesGolden("billiards-break", 1.0, "billiards_break"));
}

TEST(PresetGoldensGLTest, BilliardsGlancing) {
  EXPECT_TRUE(presetMatchesGolden("billiards-glancing", 0.6, "billiards_glancing"));
}

TEST(PresetGoldensGLTest, StickTwoD) {
  EXPECT_TRUE(presetMatchesGolden("stick-2d", 2.0, "stick_2d"));
}

TEST(PresetGoldensGLTest, GranularChain) {
  EXPECT_TRUE(presetMatchesGolden("granular-chain", 1.3, "granular_chain"));
}

TEST(PresetGoldensGLTest, PiBlocks) {
  EXPECT_TRUE(presetMatchesGolden("pi-blocks", 2.5, "pi_blocks"));
}

TEST(PresetGoldensGLTest, BulletBeforeAndAfterItEmbeds) {
  EXPECT_TRUE(presetMatchesGolden("bullet-block", 0.005, "bullet_block_before"));
  EXPECT_TRUE(presetMatchesGolden("bullet-block", 1.5, "bullet_block_after"));
}

}  // namespace
}  // namespace collide::preset_goldens
