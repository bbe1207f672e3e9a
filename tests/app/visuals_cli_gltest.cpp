// The picture commands and style options through the CLI, in-process: strobe, chart, --theme,
// --font, --chart, --panels; bad values exit 2 with one line naming the option, and write nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "render/renderer.hpp"
#include "scratch.hpp"

namespace collide {
namespace {
namespace fs = std::filesystem;

using test::CliResult;
using test::run;

class VisualsCliGLTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::makeUniqueTempDir(
        "collide_visuals_cli_" +
        std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_");
    fs::create_directories(dir_);
  }
  void TearDown() override {
    fs::remove_all(dir_);
    render::setDefaultFontPath("");  // --font is process-wide
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(VisualsCliGLTest, StrobeWritesOnePngAndCountsImages) {
  const CliResult r =
      run({"strobe", "bouncing-ball", "-o", path("s.png"), "--size", "320x180", "--rate", "10"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("s.png")));
  EXPECT_NE(r.out.find("41 images"), std::string::npos) << r.out;  // 4 s at 10 per second
}

TEST_F(VisualsCliGLTest, ChartWritesAPng) {
  const CliResult r = run({"chart", "worked-example", "-o", path("c.png"), "--size", "320x180",
                           "--chart", "momentum", "--theme", "dark"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("c.png")));
  EXPECT_NE(r.out.find("momentum"), std::string::npos);
}

TEST_F(VisualsCliGLTest, StillTakesStyleOptions) {
  const CliResult r = run({"still", "worked-example", "--at", "2", "-o", path("p.png"), "--size",
                           "320x180", "--theme", "high-contrast", "--panels", "restitution=1,0",
                           "--chart", "energy", "--font", render::defaultFontPath()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("p.png")));
}

TEST_F(VisualsCliGLTest, BadStyleValuesExitTwoAndWriteNothing) {
  struct Case {
    std::vector<std::string> extra;
    std::string names;
  };
  const std::vector<Case> cases = {
      {{"--theme", "neon"}, "--theme: 'neon'"},
      {{"--font", "/no/such/font.ttf"}, "--font: '/no/such/font.ttf'"},
      {{"--chart", "speed"}, "--chart: 'speed'"},
      {{"--panels", "restitution"}, "--panels: 'restitution'"},
      {{"--panels", "restitution=1,x"}, "--panels: 'x'"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"still", "worked-example", "--at", "1", "-o", path("x.png")};
    args.insert(args.end(), c.extra.begin(), c.extra.end());
    const CliResult r = run(args);
    EXPECT_EQ(r.exit_code, 2) << c.names;
    EXPECT_NE(r.err.find(c.names), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("x.png")));
  }
  const CliResult rate = run({"strobe", "worked-example", "-o", path("x.png"), "--rate", "0"});
  EXPECT_EQ(rate.exit_code, 2);
  EXPECT_NE(rate.err.find("--rate"), std::string::npos) << rate.err;
}

}  // namespace
}  // namespace collide
