// The command line's contract, run in-process: exit codes, one-line errors, nothing written on bad
// input. Rendering runs are in cli_render_gltest.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "scratch.hpp"

namespace collide {
namespace {
namespace fs = std::filesystem;

using test::CliResult;
using test::run;

// A fresh empty directory per test, removed afterwards.
class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::makeUniqueTempDir(
        "collide_cli_test_" +
        std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_");
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  bool dirIsEmpty() const { return fs::is_empty(dir_); }

  // Bad input: exit 2, exactly one line on stderr that mentions `needle`, nothing on stdout, and no
  // file written.
  void expectBadInput(const std::vector<std::string>& args, const std::string& needle) {
    const CliResult result = run(args);
    EXPECT_EQ(result.exit_code, 2) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_NE(result.err.find(needle), std::string::npos) << result.err;
    EXPECT_TRUE(result.out.empty()) << result.out;
    EXPECT_TRUE(dirIsEmpty());
  }

  fs::path dir_;
};

TEST_F(CliTest, HelpOnEveryCommandExitsZero) {
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"--help"}, {"render", "--help"}, {"still", "--help"}, {"presets", "--help"}}) {
    const CliResult result = run(args);
    EXPECT_EQ(result.exit_code, 0) << args.front();
    EXPECT_NE(result.out.find("Usage"), std::string::npos) << result.out;
  }
  EXPECT_NE(run({"render", "--help"}).out.find("--fps"), std::string::npos);
}

TEST_F(CliTest, VersionAndPresets) {
  EXPECT_EQ(run({"--version"}).exit_code, 0);
  EXPECT_NE(run({"--version"}).out.find("collide "), std::string::npos);
  const CliResult presets = run({"presets"});
  EXPECT_EQ(presets.exit_code, 0);
  EXPECT_NE(presets.out.find("worked-example"), std::string::npos);
}

TEST_F(CliTest, MissingCommandOrOptionIsBadUsage) {
  expectBadInput({}, "no command given");
  expectBadInput({"render", "worked-example"}, "--output");
  expectBadInput({"still", "worked-example", "-o", path("a.png"), "--at", "x"}, "--at");
  expectBadInput({"render", "worked-example", "-o", path("a.mp4"), "--bogus"}, "--bogus");
}

TEST_F(CliTest, StillWithoutAtShowsMidScene) {
  // worked-example lasts 4 s: its middle is t = 2 s.
  const CliResult result =
      run({"still", "worked-example", "--size", "64x36", "-o", path("a.png"), "--no-alt-text"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("(t = 2.000 s)"), std::string::npos) << result.out;
}

TEST_F(CliTest, UnknownPresetSuggestsTheNearestName) {
  expectBadInput({"render", "worked-exampel", "-o", path("a.mp4")},
                 "did you mean 'worked-example'");
}

TEST_F(CliTest, OutOfRangeSettingsNameTheOptionAndTheLimits) {
  expectBadInput({"render", "worked-example", "-o", path("a.mp4"), "--size", "0x0"}, "--size");
  expectBadInput({"render", "worked-example", "-o", path("a.mp4"), "--size", "7682x4320"},
                 "7680x4320");
  expectBadInput({"render", "worked-example", "-o", path("a.mp4"), "--size", "wide"}, "--size");
  expectBadInput({"render", "worked-example", "-o", path("a.mp4"), "--fps", "0"}, "--fps");
  expectBadInput({"render", "worked-example", "-o", path("a.mp4"), "--fps", "abc"}, "--fps");
  expectBadInput({"render", "worked-example", "-o", path("a.mp4"), "--duration", "-1"},
                 "--duration");
  expectBadInput({"render", "worked-example", "-o", path("a.mp4"), "--duration", "nan"},
                 "--duration");
  expectBadInput({"render", "worked-example", "-o", path("a.mp4"), "--duration", "1e9"},
                 "--duration");
  expectBadInput({"still", "worked-example", "-o", path("a.png"), "--at", "99"}, "--at");
  expectBadInput({"still", "worked-example", "-o", path("a.png"), "--at", "-0.5"}, "--at");
}

TEST_F(CliTest, UnknownBackendIsBadInput) {
  expectBadInput({"render", "worked-example", "-o", path("a.mp4"), "--backend", "vulkan"},
                 "allowed: osmesa, egl, gpu, auto");
}

TEST_F(CliTest, OutputPathsAreCheckedBeforeAnythingRuns) {
  expectBadInput({"render", "worked-example", "-o", path("a.avi")}, "allowed: a .mp4 file");
  expectBadInput({"render", "worked-example", "-o", path("missing/a.mp4")}, "does not exist");
  expectBadInput({"still", "worked-example", "--at", "1", "-o", path("a.jpg")},
                 "allowed: a .png, .svg or .pdf file");
  expectBadInput({"still", "worked-example", "--at", "1", "-o", path("missing/a.png")},
                 "does not exist");
}

}  // namespace
}  // namespace collide
