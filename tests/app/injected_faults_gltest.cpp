// Issue 8, item 4: faults with no natural trigger, injected by the preloaded shims in
// tests/faults (a missing font, a GL context that cannot be made, a missing video encoder): each
// ends with one clear stderr line naming what to do, and the earlier good output kept as it was.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "faults_fixture.hpp"

namespace collide::faults_test {
namespace {

// ---- faults injected by a preloaded shim (tests/faults) --------------------------------------

// The render kinds that draw: a video and a still.
const std::vector<Kind> kDrawnKinds = {Kind::kMp4, Kind::kPngStill};

// Runs `kind`'s changed command over its good output with `options` and extra arguments.
class InjectedFaultGLTest : public FaultsGLTest {
 protected:
  void expectFaultKeepsGoodFiles(const std::vector<Kind>& kinds, ChildOptions options,
                                 const std::vector<std::string>& extra_args, int exit_code,
                                 const std::vector<std::string>& needles) {
    for (const Kind kind : kinds) {
      SCOPED_TRACE(kindName(kind));
      writeGood(kind);
      const Snapshot before = snapshot();
      std::vector<std::string> args = changedCommandFor(kind, out_dir_());
      args.insert(args.end(), extra_args.begin(), extra_args.end());
      const ChildResult result = collide(args, options);
      expectCleanFailure(result, exit_code, needles, before);
    }
  }

  // The child's environment plus `setting` (NAME=VALUE).
  static ChildOptions withVariable(const std::string& setting) {
    ChildOptions options;
    options.environment = {setting};
    return options;
  }
  // `library` preloaded, told by `setting` which fault to inject.
  static ChildOptions shim(const std::string& library, const std::string& setting) {
    ChildOptions options = withVariable(setting);
    options.preload = library;
    return options;
  }
};

// ---- a missing font -------------------------------------------------------------------------

TEST_F(InjectedFaultGLTest, MissingFontFileIsBadInput) {
  expectFaultKeepsGoodFiles(
      kDrawnKinds, {}, {"--font", "/nonexistent.ttf"}, 2,
      {"--font: '/nonexistent.ttf'", "cannot be opened", "allowed: a TrueType or OpenType file"});
}

TEST_F(InjectedFaultGLTest, MissingDefaultFontSaysWhichPackageToInstall) {
  expectFaultKeepsGoodFiles(
      kDrawnKinds,
      shim(COLLIDE_FAULT_HIDDEN_FILES_SHIM, "COLLIDE_FAULT_HIDDEN_FILES=DejaVuSans.ttf"), {}, 1,
      {"default font", "DejaVuSans.ttf", "install fonts-dejavu-core or pass --font FILE"});
}

// fontconfig given a configuration with no font directories: as on a machine without Noto.
TEST_F(InjectedFaultGLTest, MissingScriptFontIsBadInputNamingTheDebianPackage) {
  const fs::path no_fonts = dir_ / "no-fonts.conf";
  std::ofstream(no_fonts) << "<?xml version=\"1.0\"?>\n<fontconfig></fontconfig>\n";
  const std::string setting = "FONTCONFIG_FILE=" + no_fonts.string();
  expectFaultKeepsGoodFiles(kDrawnKinds, withVariable(setting), {"--lang", "ar"}, 2,
                            {"language ar: its text needs the font Noto Sans Arabic",
                             "install the Debian package fonts-noto-core"});
  expectFaultKeepsGoodFiles(kDrawnKinds, withVariable(setting), {"--lang", "ja"}, 2,
                            {"Noto Sans CJK JP", "install the Debian package fonts-noto-cjk"});
}

// ---- a GL context that cannot be made ---------------------------------------------------------

#ifdef COLLIDE_HAVE_OSMESA
TEST_F(InjectedFaultGLTest, FailingOsmesaContextNamesTheBackendAndTheAlternative) {
  expectFaultKeepsGoodFiles(kDrawnKinds, shim(COLLIDE_FAULT_GL_SHIM, "COLLIDE_FAULT_GL=osmesa"),
                            {"--backend", "osmesa"}, 1,
                            {"GL backend osmesa: cannot create an OpenGL 3.3 core context",
                             "try --backend egl or --backend auto"});
}

TEST_F(InjectedFaultGLTest, FailingEglContextNamesTheBackendAndTheAlternative) {
  expectFaultKeepsGoodFiles(
      kDrawnKinds, shim(COLLIDE_FAULT_GL_SHIM, "COLLIDE_FAULT_GL=egl"), {"--backend", "egl"}, 1,
      {"GL backend egl: eglInitialize failed", "try --backend osmesa or --backend auto"});
}

// The natural trigger: glvnd finds no EGL vendor library, as on a machine without Mesa's EGL.
const char* const kNoEglVendor = "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json";

TEST_F(InjectedFaultGLTest, EglWithoutAnyDriverNamesTheBackendAndTheAlternative) {
  expectFaultKeepsGoodFiles(kDrawnKinds, withVariable(kNoEglVendor), {"--backend", "egl"}, 1,
                            {"GL backend egl:", "try --backend osmesa or --backend auto"});
}

TEST_F(InjectedFaultGLTest, AutoFallsBackToOsmesaWhenEglFails) {
  for (const ChildOptions& options :
       {shim(COLLIDE_FAULT_GL_SHIM, "COLLIDE_FAULT_GL=egl"), withVariable(kNoEglVendor)}) {
    std::vector<std::string> args = commandFor(Kind::kPngStill, out_dir_());
    args.insert(args.end(), {"--backend", "auto"});
    const ChildResult result = collide(args, options);
    EXPECT_EQ(result.exit_code, 0) << test::describe(result) << ": " << result.err;
    EXPECT_EQ(result.err, "");
    EXPECT_TRUE(fs::exists(out_dir_() / targetName(Kind::kPngStill)));
    fs::remove(out_dir_() / targetName(Kind::kPngStill));
  }
}

TEST_F(InjectedFaultGLTest, AutoWithNoWorkingBackendListsEveryReason) {
  expectFaultKeepsGoodFiles(kDrawnKinds, shim(COLLIDE_FAULT_GL_SHIM, "COLLIDE_FAULT_GL=osmesa,egl"),
                            {"--backend", "auto"}, 1,
                            {"GL backend auto: no backend works", "gpu: ", "egl: eglInitialize",
                             "osmesa: cannot create", "install Mesa"});
}
#endif

// ---- a missing video encoder ------------------------------------------------------------------

TEST_F(InjectedFaultGLTest, MissingH264EncoderSaysWhatToInstallOrUseInstead) {
  expectFaultKeepsGoodFiles(
      {Kind::kMp4}, shim(COLLIDE_FAULT_ENCODER_SHIM, "COLLIDE_FAULT_ENCODERS=libx264"), {}, 1,
      {"clip.mp4", "H.264 encoder libx264 is not available",
       "install an FFmpeg libavcodec built with libx264",
       "choose another output: .mp4, .webm, .gif"});
}

TEST_F(InjectedFaultGLTest, MissingVp9AndGifEncodersFailCleanly) {
  expectFaultKeepsGoodFiles({Kind::kWebm},
                            shim(COLLIDE_FAULT_ENCODER_SHIM, "COLLIDE_FAULT_ENCODERS=libvpx-vp9"),
                            {}, 1, {"clip.webm", "VP9 encoder libvpx-vp9 is not available"});
  expectFaultKeepsGoodFiles({Kind::kGif},
                            shim(COLLIDE_FAULT_ENCODER_SHIM, "COLLIDE_FAULT_ENCODERS=gif"), {}, 1,
                            {"clip.gif", "GIF encoder gif is not available"});
}

TEST_F(InjectedFaultGLTest, MissingAudioEncoderSuggestsLeavingOutSound) {
  expectFaultKeepsGoodFiles(
      {Kind::kMp4}, shim(COLLIDE_FAULT_ENCODER_SHIM, "COLLIDE_FAULT_ENCODERS=aac"), {"--sound"}, 1,
      {"audio encoder aac is not available", "or leave out --sound"});
}

}  // namespace
}  // namespace collide::faults_test
