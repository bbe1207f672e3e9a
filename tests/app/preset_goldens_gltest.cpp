// Goldens of the presets a teacher pastes into lecture notes, at the moment each one teaches:
// the break spreading the rack, the glancing hit after impact, the stuck pair turning, the
// granular chain mid-way, the pi blocks during their exchange, and the bullet before (its arrow
// off scale, with a break) and after it embeds (one body, one readable arrow). Each baseline was
// opened and looked at before it was committed.
#include <gtest/gtest.h>

#include "scene_goldens.hpp"

namespace collide::preset_goldens {
namespace {

constexpr int kWidth = 480, kHeight = 270;

using test::GoldenShot;

class PresetGoldensGLTest : public ::testing::TestWithParam<GoldenShot> {};

TEST_P(PresetGoldensGLTest, MatchesItsGolden) {
  const GoldenShot& shot = GetParam();
  EXPECT_TRUE(test::sceneMatchesGolden(scene::loadPreset(shot.preset), shot.t_s, kWidth, kHeight,
                                       shot.golden));
}

INSTANTIATE_TEST_SUITE_P(Presets, PresetGoldensGLTest,
                         ::testing::Values(GoldenShot{"billiards-break", 1.0, "billiards_break"},
                                           GoldenShot{"billiards-glancing", 0.6,
                                                      "billiards_glancing"},
                                           GoldenShot{"stick-2d", 2.0, "stick_2d"},
                                           GoldenShot{"granular-chain", 1.3, "granular_chain"},
                                           GoldenShot{"pi-blocks", 2.5, "pi_blocks"},
                                           GoldenShot{"bullet-block", 0.005, "bullet_block_before"},
                                           GoldenShot{"bullet-block", 1.5, "bullet_block_after"}),
                         test::goldenShotName);

}  // namespace
}  // namespace collide::preset_goldens
