// libavcodec and libavformat reach the program only through the video module, opened when a video
// is written: the commands that write no video never map them (issue 19, instant stills). The same
// for OpenGL (libOSMesa with LLVM, libEGL) and the GL module: the commands that draw nothing never
// map them; and for Cairo (with pixman and its X11 libraries) and the vector module: only SVG and
// PDF figures map them.
// glibc's loader lists every object it loads, dlopen'd ones included, under LD_DEBUG=files.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "scratch.hpp"

namespace collide {
namespace {

class VideoModuleGLTest : public ::testing::Test {
 protected:
  test::ScratchDir dir_{"collide_video_module_test_"};

  // Runs collide with `args`; returns what the loader reported loading (its stderr).
  std::string loadedBy(const std::string& args) {
    const std::string log = dir_.file("loader.txt");
    const std::string command = "LD_DEBUG=files " + test::shellQuoted(COLLIDE_BINARY) + " " + args +
                                " >" + dir_.shellFile("stdout.txt") + " 2>" +
                                test::shellQuoted(log);
    EXPECT_EQ(test::runShellBounded(command), 0) << args;
    return test::readFileBytes(log);
  }
};

TEST_F(VideoModuleGLTest, CommandsWithoutVideoNeverLoadLibav) {
  for (const std::string& args : std::vector<std::string>{
           "presets", "check worked-example",
           "data worked-example --csv " + dir_.shellFile("d.csv"),
           "still worked-example --at 1 --size 160x90 -o " + dir_.shellFile("s.png"),
           "strobe bouncing-ball --size 160x90 -o " + dir_.shellFile("strobe.png"),
           "chart worked-example --size 160x90 -o " + dir_.shellFile("c.png"),
           "render worked-example --duration 0.1 --size 160x90 -o " + dir_.shellFile("frames/")}) {
    const std::string loaded = loadedBy(args);
    EXPECT_NE(loaded.find("libpng"), std::string::npos) << "no loader log for: " << args;
    EXPECT_EQ(loaded.find("libavcodec"), std::string::npos) << args;
    EXPECT_EQ(loaded.find("libavformat"), std::string::npos) << args;
    EXPECT_EQ(loaded.find("collide-video.so"), std::string::npos) << args;
  }
}

TEST_F(VideoModuleGLTest, CommandsWithoutPicturesNeverLoadGl) {
#ifndef COLLIDE_GL_MODULE
  GTEST_SKIP() << "built with COLLIDE_GL_MODULE=OFF: GL is linked into the program";
#endif
  for (const std::string& args : std::vector<std::string>{
           "presets", "check worked-example",
           "data worked-example --csv " + dir_.shellFile("d.csv"),
           "data worked-example --json " + dir_.shellFile("d.json"), "render --help"}) {
    const std::string loaded = loadedBy(args);
    EXPECT_NE(loaded.find("libpng"), std::string::npos) << "no loader log for: " << args;
    EXPECT_EQ(loaded.find("collide-gl.so"), std::string::npos) << args;
    EXPECT_EQ(loaded.find("libOSMesa"), std::string::npos) << args;
    EXPECT_EQ(loaded.find("libLLVM"), std::string::npos) << args;
    EXPECT_EQ(loaded.find("libEGL"), std::string::npos) << args;
  }
}

TEST_F(VideoModuleGLTest, AStillLoadsTheGlModuleAndDraws) {
#ifndef COLLIDE_GL_MODULE
  GTEST_SKIP() << "built with COLLIDE_GL_MODULE=OFF: GL is linked into the program";
#endif
  const std::string still = dir_.file("s.png");
  const std::string loaded =
      loadedBy("still worked-example --at 1 --size 160x90 -o " + test::shellQuoted(still));
  EXPECT_NE(loaded.find("collide-gl.so"), std::string::npos);
  EXPECT_GT(std::filesystem::file_size(still), 1000u) << "a 160x90 picture with bodies and text";
}

TEST_F(VideoModuleGLTest, PicturesWithoutVectorsNeverLoadCairo) {
#ifndef COLLIDE_GL_MODULE
  GTEST_SKIP() << "built with COLLIDE_GL_MODULE=OFF: GL and Cairo are linked into the program";
#endif
  for (const std::string& args : std::vector<std::string>{
           "presets", "still worked-example --at 1 --size 160x90 -o " + dir_.shellFile("s.png"),
           "strobe bouncing-ball --size 160x90 -o " + dir_.shellFile("strobe.png"),
           "chart worked-example --size 160x90 -o " + dir_.shellFile("c.png")}) {
    const std::string loaded = loadedBy(args);
    EXPECT_NE(loaded.find("libpng"), std::string::npos) << "no loader log for: " << args;
    EXPECT_EQ(loaded.find("collide-vector.so"), std::string::npos) << args;
    EXPECT_EQ(loaded.find("libcairo"), std::string::npos) << args;
    EXPECT_EQ(loaded.find("libpixman"), std::string::npos) << args;
    EXPECT_EQ(loaded.find("libX11.so"), std::string::npos) << args;
  }
}

TEST_F(VideoModuleGLTest, AVectorFigureLoadsTheVectorModuleAndCairo) {
#ifndef COLLIDE_GL_MODULE
  GTEST_SKIP() << "built with COLLIDE_GL_MODULE=OFF: GL and Cairo are linked into the program";
#endif
  for (const std::string name : {"f.svg", "f.pdf"}) {
    const std::string figure = dir_.file(name);
    const std::string loaded =
        loadedBy("still worked-example --at 1 -o " + test::shellQuoted(figure));
    EXPECT_NE(loaded.find("collide-vector.so"), std::string::npos) << name;
    EXPECT_NE(loaded.find("libcairo"), std::string::npos) << name;
    EXPECT_EQ(loaded.find("collide-gl.so"), std::string::npos) << name << ": no pixels drawn";
    EXPECT_GT(std::filesystem::file_size(figure), 1000u) << name << ": bodies and text";
  }
  // The module has its own copy of the active language: the program's choice reaches it, with
  // the language's own font for its script (Japanese text in Noto Sans CJK, not in DejaVu Sans).
  const std::string japanese = dir_.file("ja.svg");
  loadedBy("still worked-example --at 1 --lang ja -o " + test::shellQuoted(japanese));
  EXPECT_NE(test::readFileBytes(japanese).find("font-family=\"'Noto Sans CJK JP'"),
            std::string::npos);
}

TEST_F(VideoModuleGLTest, AVideoLoadsTheModuleAndLibav) {
  const std::string loaded =
      loadedBy("render worked-example --duration 0.1 --size 160x90 -o " + dir_.shellFile("v.mp4"));
  EXPECT_NE(loaded.find("collide-video.so"), std::string::npos);
  EXPECT_NE(loaded.find("libavcodec"), std::string::npos);
}

}  // namespace
}  // namespace collide
