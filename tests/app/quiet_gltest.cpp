// SPDX-License-Identifier: MIT
// -q/--quiet through the real binary: nothing on stderr but errors, the libraries' notes
// included. Mesa says "Failed to create ... for shader cache" where XDG_CACHE_HOME's parent is
// missing (render/gl/mesa_shader_cache.hpp); fontconfig prints the warnings of its configuration
// files (render/text/script_fonts.hpp). Each check is shown to bite: the same mistake without the
// fix's help prints the library's message.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "scratch.hpp"

namespace collide {
namespace {

class QuietGLTest : public ::testing::Test {
 protected:
  test::ScratchDir dir{"collide-quiet-"};

  void SetUp() override {
    std::filesystem::create_directory(dir / "home");
    // The system's configuration and one element fontconfig does not know: a warning.
    std::ofstream(dir / "fonts.conf")
        << "<?xml version=\"1.0\"?>\n<fontconfig>\n"
           "  <include ignore_missing=\"yes\">/etc/fonts/fonts.conf</include>\n"
           "  <unknown-to-fontconfig/>\n</fontconfig>\n";
  }

  // collide ARGS in a home of its own, its cache folder's parent missing, the fonts.conf above.
  test::ShellRun collide(const std::string& args, const std::string& mesa = "") {
    const std::string environment =
        "env -u MESA_SHADER_CACHE_DISABLE -u MESA_SHADER_CACHE_DIR -u MESA_GLSL_CACHE_DIR "
        "-u FC_DEBUG HOME=" +
        dir.shellFile("home") + " XDG_CACHE_HOME=" + dir.shellFile("missing/cache") +
        " FONTCONFIG_FILE=" + dir.shellFile("fonts.conf") + " " + mesa + " ";
    return test::runShellCaptured(dir.path(), "cd " + dir.shellFile("") + " && " + environment +
                                                  test::shellQuoted(COLLIDE_BINARY) + " " + args);
  }
};

TEST_F(QuietGLTest, QuietRunsPrintNothingOnStderr) {
  for (const std::string args :
       {"still worked-example --size 64x36 --lang ar -o ar.png -q",
        "render worked-example --size 64x36 --duration 0.1 --fps 10 -o r.mp4 -q",
        "data worked-example --csv c.csv --json j.json -q",
        "batch worked-example --formats png,csv --size 64x36 --jobs 1 -o batch -q"}) {
    SCOPED_TRACE(args);
    const test::ShellRun run = collide(args);
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_EQ(run.err, "");
  }
  // An error still shows.
  EXPECT_NE(collide("still worked-example --size 64x36 -o s.jpg -q").err, "");
}

TEST_F(QuietGLTest, TheLibrariesSpeakWithoutTheHelp) {
  // Mesa told to keep its cache (so left alone) complains of the missing folder...
  const test::ShellRun mesa =
      collide("still worked-example --size 64x36 -o s.png -q", "MESA_SHADER_CACHE_DISABLE=false");
  EXPECT_EQ(mesa.exit_code, 0);
  EXPECT_NE(mesa.err.find("shader cache"), std::string::npos) << mesa.err;
  // ... and fontconfig's warning, caught, is passed on when not asked for quiet.
  const test::ShellRun fonts = collide("still worked-example --size 64x36 --lang ar -o ar.png");
  EXPECT_EQ(fonts.exit_code, 0);
  EXPECT_NE(fonts.err.find("unknown-to-fontconfig"), std::string::npos) << fonts.err;
}

}  // namespace
}  // namespace collide
