// Every preset simulates over its whole duration without a physics warning, renders a short video
// through the CLI with nothing on stderr, and its still through the CLI is the video's frame.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "app/cli.hpp"
#include "app/world_from_scene.hpp"
#include "golden.hpp"
#include "physics/simulate.hpp"
#include "png_io.hpp"
#include "progress_lines.hpp"
#include "render/renderer.hpp"
#include "scene/scene_desc.hpp"
#include "scratch.hpp"

namespace collide {
namespace {
namespace fs = std::filesystem;

int runCli(std::vector<std::string> args, std::string& err) {
  args.insert(args.begin(), "collide");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  std::ostringstream out, errors;
  const int code = app::runCli(static_cast<int>(argv.size()), argv.data(), out, errors);
  err = errors.str();
  return code;
}

TEST(PresetsGLTest, EveryPresetSimulatesWithoutAWarning) {
  for (const scene::PresetInfo& preset : scene::presetList()) {
    SCOPED_TRACE(preset.name);
    const scene::SceneDesc scene = scene::loadPreset(preset.name);
    const physics::Timeline timeline = physics::simulate(app::worldFromScene(scene));
    EXPECT_EQ(timeline.status(), physics::SimulationStatus::kComplete);
    for (const physics::Warning& warning : timeline.warnings()) ADD_FAILURE() << warning.message;
    EXPECT_GT(timeline.collisionCount(), 0) << "a collision preset without a collision";
  }
}

// One test per preset, so that ctest runs them side by side (under the sanitizers the slowest
// presets, a chain of many impacts and the gas, take seconds each). The video runs under the
// sanitizers too: it simulates, lays out, draws and encodes every preset.
class PresetRenderGLTest : public ::testing::TestWithParam<std::string> {};

TEST_P(PresetRenderGLTest, RendersTheWholeSceneAsAShortVideo) {
  const std::string name = GetParam();
  const fs::path dir = test::makeUniqueTempDir("collide_presets_gltest_");
  // The whole scene at 4 frames per second: every collision happens inside the video.
  const std::string mp4 = (dir / (name + ".mp4")).string();
  std::string err;
  EXPECT_EQ(runCli({"render", name, "--fps", "4", "--size", "160x90", "--quiet", "-o", mp4}, err),
            0)
      << err;
  EXPECT_EQ(test::withoutProgressLines(err), "");
  EXPECT_GT(fs::file_size(mp4), 0u);
  fs::remove_all(dir);
}

// The still through the command line is the video's frame at that time, pixel for pixel. In the
// Release suite only: the sanitizers' run of the video above lays out and draws the same frames
// (scripts/test).
class PresetStillGLTest : public ::testing::TestWithParam<std::string> {};

TEST_P(PresetStillGLTest, IsTheVideosFrameAtThatTime) {
  const std::string name = GetParam();
  const fs::path dir = test::makeUniqueTempDir("collide_presets_gltest_");
  render::Renderer renderer(160, 90);
  const scene::SceneDesc scene = scene::loadPreset(name);
  std::string err;
  const std::string png = (dir / (name + ".png")).string();
  const std::string mid = std::to_string(0.5 * scene.duration_s);
  EXPECT_EQ(runCli({"still", name, "--at", mid, "--size", "160x90", "-o", png}, err), 0) << err;
  EXPECT_EQ(test::withoutProgressLines(err), "");
  const frame::FrameModel frame =
      app::animate(scene, {160, 90}).frames.frameAtSimulated(std::stod(mid));
  EXPECT_TRUE(test::judgeImages(test::readPng(png).view(), renderer.render(frame)));
  fs::remove_all(dir);
}

std::vector<std::string> presetNames() {
  std::vector<std::string> names;
  for (const scene::PresetInfo& preset : scene::presetList()) names.push_back(preset.name);
  return names;
}

// A test name takes letters, digits and underscores only.
std::string testNameOf(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(EveryPreset, PresetRenderGLTest, ::testing::ValuesIn(presetNames()),
                         testNameOf);
INSTANTIATE_TEST_SUITE_P(EveryPreset, PresetStillGLTest, ::testing::ValuesIn(presetNames()),
                         testNameOf);

}  // namespace
}  // namespace collide
