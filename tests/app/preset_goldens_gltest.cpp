// Goldens of the presets a teacher pastes into lecture notes, at the moment each one teaches:
// the break spreading the rack, the glancing hit after impact, the stuck pair turning, the
// granular chain mid-way, the pi blocks during their exchange, and the bullet before (its arrow
// off scale, with a break) and after it embeds (one body, one readable arrow). Each baseline was
// opened and looked at before it was committed.
#include <gtest/gtest.h>

#include <ostream>
#include <string>

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

// A preset at the instant it teaches, compared with golden_frames/app/<golden>.png.
struct PresetInstant {
  const char* preset;
  double t_s;
  const char* golden;  // also the test's name
};

void PrintTo(const PresetInstant& shot, std::ostream* out) {
  *out << shot.preset << " at " << shot.t_s << " s";
}

class PresetGoldensGLTest : public ::testing::TestWithParam<PresetInstant> {};

TEST_P(PresetGoldensGLTest, MatchesItsGolden) {
  const PresetInstant& shot = GetParam();
  EXPECT_TRUE(presetMatchesGolden(shot.preset, shot.t_s, shot.golden));
}

INSTANTIATE_TEST_SUITE_P(
    Presets, PresetGoldensGLTest,
    ::testing::Values(PresetInstant{"billiards-break", 1.0, "billiards_break"},
                      PresetInstant{"billiards-glancing", 0.6, "billiards_glancing"},
                      PresetInstant{"stick-2d", 2.0, "stick_2d"},
                      PresetInstant{"granular-chain", 1.3, "granular_chain"},
                      PresetInstant{"pi-blocks", 2.5, "pi_blocks"},
                      PresetInstant{"bullet-block", 0.005, "bullet_block_before"},
                      PresetInstant{"bullet-block", 1.5, "bullet_block_after"}),
    [](const ::testing::TestParamInfo<PresetInstant>& info) {
      return std::string(info.param.golden);
    });

}  // namespace
}  // namespace collide::preset_goldens
