// The picture commands and style options through the CLI, in-process: strobe, chart, --theme,
// --font, --chart, --panels; bad values exit 2 with one line naming the option, and write nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "cli_runner.hpp"
#include "golden.hpp"
#include "png_io.hpp"
#include "render/renderer.hpp"
#include "scene/scene_io.hpp"
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

// A strobe that cannot teach its scene (billiards-break: sixteen balls' images are a cloud of
// dots) is still drawn as asked, and the run names the still that shows the scene instead (the
// one batch and lessons draw in its place).
TEST_F(VisualsCliGLTest, AStrobeThatCannotTeachNamesTheStillThatDoes) {
  const CliResult r =
      run({"strobe", "billiards-break", "-o", path("b.png"), "--size", "320x180", "--rate", "2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("b.png")));
  EXPECT_NE(r.err.find("warning: billiards-break: its strobe is a cloud of images"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("collide still billiards-break --at 1\n"), std::string::npos) << r.err;
  // A scene whose strobe teaches says nothing of the kind.
  const CliResult worked =
      run({"strobe", "worked-example", "-o", path("w.png"), "--size", "320x180", "--rate", "2"});
  ASSERT_EQ(worked.exit_code, 0) << worked.err;
  EXPECT_EQ(worked.err.find("cloud of images"), std::string::npos) << worked.err;
}

TEST_F(VisualsCliGLTest, ChartWritesAPng) {
  const CliResult r = run({"chart", "worked-example", "-o", path("c.png"), "--size", "320x180",
                           "--chart", "momentum", "--theme", "dark"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("momentum"), std::string::npos);
  // The picture is the momentum chart in the dark theme, as drawn here from the scene.
  const frame::FrameModel frame =
      app::animate(
          scene::loadScene("worked-example", {scene::parseSetExpression("view.chart=\"momentum\""),
                                              scene::parseSetExpression("view.theme=\"dark\"")}),
          {1280, 720})
          .frames.chartFrame();
  ASSERT_EQ(frame.charts.size(), 1u);
  EXPECT_EQ(frame.charts[0].title, "Momentum against time");
  render::Renderer renderer(320, 180);
  EXPECT_TRUE(test::judgeImages(test::readPng(path("c.png")).view(), renderer.render(frame)));
}

TEST_F(VisualsCliGLTest, StillTakesStyleOptions) {
  const CliResult r = run({"still", "worked-example", "--at", "2", "-o", path("p.png"), "--size",
                           "320x180", "--theme", "high-contrast", "--panels", "restitution=1,0",
                           "--chart", "energy", "--font", render::defaultFontPath()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("p.png")));
}

// Each style option shows in the picture: the still equals the same scene with the option
// written into it (view.theme, view.panels, view.chart) drawn here, and differs from the plain
// still. The frame drawn here has what the option asks for (a dark background, two panels, a
// chart), so a CLI that ignored the option fails.
TEST_F(VisualsCliGLTest, StyleOptionsTakeEffectInThePicture) {
  struct Case {
    std::vector<std::string> options;
    std::string set;
    std::function<void(const frame::FrameModel&)> expect;
  };
  const std::vector<Case> cases = {
      {{"--theme", "dark"},
       "view.theme=\"dark\"",
       [](const frame::FrameModel& f) {
         const frame::Rgba& bg = f.style.background;
         EXPECT_LT(0.2126 * bg.r + 0.7152 * bg.g + 0.0722 * bg.b, 0.25) << "a dark background";
       }},
      {{"--panels", "restitution=1,0"},
       "view.panels={parameter=\"restitution\", values=[1, 0]}",
       [](const frame::FrameModel& f) {
         ASSERT_EQ(f.panels.size(), 2u);
         EXPECT_EQ(f.panels[0].heading, "e = 1");
         EXPECT_EQ(f.panels[1].heading, "e = 0");
       }},
      {{"--chart", "energy"},
       "view.chart=\"energy\"",
       [](const frame::FrameModel& f) {
         ASSERT_EQ(f.charts.size(), 1u);
         EXPECT_EQ(f.charts[0].title, "Energy against time");
       }},
      {{"--chart", "momentum"},
       "view.chart=\"momentum\"",
       [](const frame::FrameModel& f) {
         ASSERT_EQ(f.charts.size(), 1u);
         EXPECT_EQ(f.charts[0].title, "Momentum against time");
       }},
  };
  const double at_s = 2.0;
  render::Renderer renderer(320, 180);
  const core::Image plain = core::Image::copyOf(renderer.render(
      app::animate(scene::loadScene("worked-example"), {320, 180}).frames.frameAtSimulated(at_s)));
  for (const Case& c : cases) {
    SCOPED_TRACE(c.set);
    std::vector<std::string> args = {"still", "worked-example", "--at",   "2",
                                     "-o",    path("p.png"),    "--size", "320x180"};
    args.insert(args.end(), c.options.begin(), c.options.end());
    const CliResult r = run(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const core::Image still = test::readPng(path("p.png"));
    const frame::FrameModel frame =
        app::animate(scene::loadScene("worked-example", {scene::parseSetExpression(c.set)}),
                     {320, 180})
            .frames.frameAtSimulated(at_s);
    c.expect(frame);
    // The top-left corner is background, in the theme's colour.
    const std::uint8_t* corner = still.view().pixel(0, 0);
    const frame::Rgba& bg = frame.style.background;
    EXPECT_NEAR(corner[0], 255.0 * bg.r, 1.0);
    EXPECT_NEAR(corner[1], 255.0 * bg.g, 1.0);
    EXPECT_NEAR(corner[2], 255.0 * bg.b, 1.0);
    EXPECT_TRUE(test::judgeImages(still.view(), renderer.render(frame)));
    EXPECT_FALSE(test::judgeImages(still.view(), plain.view())) << "the option changed nothing";
  }
  // The plain still is the plain frame: the comparison above is exact enough to tell.
  ASSERT_EQ(run({"still", "worked-example", "--at", "2", "-o", path("q.png"), "--size", "320x180"})
                .exit_code,
            0);
  EXPECT_TRUE(test::judgeImages(test::readPng(path("q.png")).view(), plain.view()));
}

TEST_F(VisualsCliGLTest, BadStyleValuesExitTwoAndWriteNothing) {
  struct Case {
    std::vector<std::string> extra;
    std::string names;
  };
  const std::vector<Case> cases = {
      {{"--theme", "neon"}, "--theme: 'neon'"},
      {{"--font", "/no/such/font.ttf"}, "--font: '/no/such/font.ttf'"},
      {{"--chart", "velocity"}, "--chart: 'velocity'"},
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
