// Issue 8, item 4: faults, through the real `collide` binary. Each fault (a full disk, an
// unwritable directory, SIGINT or SIGTERM mid-render or during a long still, strobe, chart or
// data run (which must also stop within a second), a missing font, a GL context that cannot be
// made, a missing video encoder) must end with one clear stderr line (what failed, what to do), a
// non-zero exit, no hang, no partial or temporary file, and an earlier good output at the same
// path left byte for byte as it was. Faults with no natural trigger come from the preloaded shims
// in tests/faults; none needs a hook in the product.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "faults/child_process.hpp"
#include "scratch.hpp"

namespace collide {
namespace {
namespace fs = std::filesystem;
using test::ChildOptions;
using test::ChildResult;

// Every file and directory under a folder: relative path -> bytes ("" and a trailing '/' for a
// directory). Equal snapshots mean nothing was added, removed or changed, hidden files included.
using Snapshot = std::map<std::string, std::string>;

// The output kinds a user asks for, each with the command that writes it.
enum class Kind { kMp4, kWebm, kGif, kPngStill, kPngFrames, kCsv, kJson };

std::string kindName(Kind kind);

// For gtest's messages about parameters.
void PrintTo(Kind kind, std::ostream* out) {
  *out << kindName(kind);
}

std::string kindName(Kind kind) {
  switch (kind) {
    case Kind::kMp4:
      return "Mp4";
    case Kind::kWebm:
      return "Webm";
    case Kind::kGif:
      return "Gif";
    case Kind::kPngStill:
      return "PngStill";
    case Kind::kPngFrames:
      return "PngFrames";
    case Kind::kCsv:
      return "Csv";
    case Kind::kJson:
      return "Json";
  }
  return "?";
}

// Where each kind goes, relative to the output folder.
std::string targetName(Kind kind) {
  switch (kind) {
    case Kind::kMp4:
      return "clip.mp4";
    case Kind::kWebm:
      return "clip.webm";
    case Kind::kGif:
      return "clip.gif";
    case Kind::kPngStill:
      return "still.png";
    case Kind::kPngFrames:
      return "frames";
    case Kind::kCsv:
      return "table.csv";
    case Kind::kJson:
      return "summary.json";
  }
  return "?";
}

// Small and short: 160x90 at 10 fps (5 frames for the default 0.5 s).
const std::vector<std::string> kSmallClip = {"--size", "160x90", "--fps", "10"};

// The command that writes `kind` into `out_dir`; videos and frames last `duration_s` seconds.
std::vector<std::string> commandFor(Kind kind, const fs::path& out_dir,
                                    const std::string& duration_s = "0.5") {
  const std::string target = (out_dir / targetName(kind)).string();
  std::vector<std::string> args;
  switch (kind) {
    case Kind::kMp4:
    case Kind::kWebm:
    case Kind::kGif:
      args = {"render", "worked-example", "-o", target, "--duration", duration_s};
      args.insert(args.end(), kSmallClip.begin(), kSmallClip.end());
      return args;
    case Kind::kPngFrames:
      args = {"render", "worked-example", "-o", target + "/", "--duration", duration_s};
      args.insert(args.end(), kSmallClip.begin(), kSmallClip.end());
      return args;
    case Kind::kPngStill:
      return {"still", "worked-example", "--at", "1", "--size", "160x90", "-o", target};
    case Kind::kCsv:
      return {"data", "worked-example", "--csv", target};
    case Kind::kJson:
      return {"data", "worked-example", "--json", target, "--events"};
  }
  return {};
}

// The same command for a different scene, so a file it managed to write would differ from the
// good one.
std::vector<std::string> changedCommandFor(Kind kind, const fs::path& out_dir,
                                           const std::string& duration_s = "0.5") {
  std::vector<std::string> args = commandFor(kind, out_dir, duration_s);
  args.insert(args.end(), {"--set", "restitution=0.9"});
  return args;
}

const std::vector<Kind> kAllKinds = {Kind::kMp4,       Kind::kWebm, Kind::kGif, Kind::kPngStill,
                                     Kind::kPngFrames, Kind::kCsv,  Kind::kJson};

std::string testName() {
  std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::replace(name.begin(), name.end(), '/', '_');
  return name;
}

class FaultsGLTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::makeUniqueTempDir("collide_faults_" + testName() + "_");
    fs::create_directories(out_dir_());
    // Readable and enterable by user nobody, who runs the unwritable-directory cases as root.
    fs::permissions(dir_, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                              fs::perms::others_read | fs::perms::others_exec);
  }
  void TearDown() override {
    makeWritable();
    fs::remove_all(dir_);
  }

  fs::path out_dir_() const { return dir_ / "out"; }

  ChildResult collide(const std::vector<std::string>& args, const ChildOptions& options = {}) {
    return test::runChild(COLLIDE_BINARY, args, options);
  }

  // Writes the good output of `kind` (before a fault run aims at the same path).
  void writeGood(Kind kind) {
    const ChildResult result = collide(commandFor(kind, out_dir_()));
    ASSERT_EQ(result.exit_code, 0) << test::describe(result) << ": " << result.err;
    ASSERT_TRUE(fs::exists(out_dir_() / targetName(kind)));
  }

  Snapshot snapshot() const {
    Snapshot files;
    for (const auto& entry : fs::recursive_directory_iterator(out_dir_())) {
      const std::string name = fs::relative(entry.path(), out_dir_()).string();
      if (entry.is_directory()) {
        files[name + "/"] = "";
      } else {
        files[name] = test::readFileBytes(entry.path());
      }
    }
    return files;
  }

  // The fault's outcome: `exit_code`, one stderr line holding every needle, nothing on stdout, and
  // the output folder exactly as `before` (the good file intact, no partial or temporary file).
  void expectCleanFailure(const ChildResult& result, int exit_code,
                          const std::vector<std::string>& needles, const Snapshot& before) {
    EXPECT_FALSE(result.timed_out) << "collide hung";
    EXPECT_EQ(result.exit_code, exit_code) << test::describe(result) << ": " << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << "not one line:\n"
                                                                         << result.err;
    EXPECT_EQ(result.err.rfind("collide: ", 0), 0u) << result.err;
    for (const std::string& needle : needles) {
      EXPECT_NE(result.err.find(needle), std::string::npos)
          << "'" << needle << "' missing from: " << result.err;
    }
    EXPECT_EQ(result.out, "");
    const Snapshot after = snapshot();
    EXPECT_EQ(keys(after), keys(before)) << "files were added or removed";
    for (const auto& [name, bytes] : before) {
      const auto found = after.find(name);
      if (found != after.end()) {
        EXPECT_TRUE(found->second == bytes) << name << " changed";
      }
    }
  }

  static std::vector<std::string> keys(const Snapshot& files) {
    std::vector<std::string> names;
    for (const auto& entry : files) names.push_back(entry.first);
    return names;
  }

  // True once a hidden temporary file (".NAME.tmp-PID-N.EXT") exists in `folder`.
  static bool temporaryFileIn(const fs::path& folder) {
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(folder, error)) {
      const std::string name = entry.path().filename().string();
      if (name.front() == '.' && name.find(".tmp-") != std::string::npos) return true;
    }
    return false;
  }

  void makeUnwritable(const fs::path& folder) {
    ::chmod(folder.c_str(), 0555);
    locked_.push_back(folder);
  }
  void makeWritable() {
    for (const fs::path& folder : locked_) ::chmod(folder.c_str(), 0755);
    locked_.clear();
  }

  fs::path dir_;
  std::vector<fs::path> locked_;
};

class FaultPerKindGLTest : public FaultsGLTest, public ::testing::WithParamInterface<Kind> {};

std::string kindParamName(const ::testing::TestParamInfo<Kind>& info) {
  return kindName(info.param);
}

// ---- a full disk ----------------------------------------------------------------------------

// Writes past 512 bytes fail with EFBIG, as a disk that fills up fails with ENOSPC; every output
// here is larger. SIGXFSZ keeps its default action (death), so this also proves collide ignores it.
constexpr long long kFileSizeLimitBytes = 512;

TEST_P(FaultPerKindGLTest, FullDiskFailsCleanlyAndKeepsTheEarlierFile) {
  const Kind kind = GetParam();
  writeGood(kind);
  const Snapshot before = snapshot();
  ChildOptions options;
  options.file_size_limit_bytes = kFileSizeLimitBytes;
  const ChildResult result = collide(changedCommandFor(kind, out_dir_()), options);
  expectCleanFailure(result, 1, {targetName(kind), "File too large", "ulimit -f"}, before);
}

// ---- an unwritable directory ----------------------------------------------------------------

TEST_P(FaultPerKindGLTest, UnwritableDirectoryFailsCleanlyAndKeepsTheEarlierFile) {
  const Kind kind = GetParam();
  writeGood(kind);
  const Snapshot before = snapshot();
  makeUnwritable(out_dir_());
  if (kind == Kind::kPngFrames) makeUnwritable(out_dir_() / targetName(kind));
  ChildOptions options;
  options.unprivileged = true;  // root writes anywhere; user nobody does not
  const ChildResult result = collide(changedCommandFor(kind, out_dir_()), options);
  expectCleanFailure(result, 1,
                     {targetName(kind), "Permission denied", "choose a directory you may write to"},
                     before);
}

INSTANTIATE_TEST_SUITE_P(EveryKind, FaultPerKindGLTest, ::testing::ValuesIn(kAllKinds),
                         kindParamName);

// ---- SIGINT and SIGTERM during a render ------------------------------------------------------

struct StopCase {
  int signal_number;
  Kind kind;
};

void PrintTo(const StopCase& stop, std::ostream* out) {
  *out << strsignal(stop.signal_number) << " during " << kindName(stop.kind);
}

class StopSignalGLTest : public FaultsGLTest, public ::testing::WithParamInterface<StopCase> {};

std::string stopCaseName(const ::testing::TestParamInfo<StopCase>& info) {
  return std::string(info.param.signal_number == SIGINT ? "Sigint" : "Sigterm") +
         kindName(info.param.kind);
}

TEST_P(StopSignalGLTest, StopsCleanlyAndKeepsTheEarlierFile) {
  const auto [signal_number, kind] = GetParam();
  writeGood(kind);
  const Snapshot before = snapshot();
  // Ten minutes of video: the signal arrives mid-render, once frames are being written.
  const std::vector<std::string> args = changedCommandFor(kind, out_dir_(), "600");
  const fs::path folder = kind == Kind::kPngFrames ? out_dir_() / targetName(kind) : out_dir_();
  ChildOptions options;
  options.signal_number = signal_number;
  options.ready_for_signal = [&] { return temporaryFileIn(folder); };
  const ChildResult result = collide(args, options);
  ASSERT_TRUE(result.signal_sent) << "the render never wrote a temporary file: " << result.err;
  const std::string name = signal_number == SIGINT ? "SIGINT" : "SIGTERM";
  expectCleanFailure(result, 128 + signal_number, {"stopped by " + name, targetName(kind)}, before);
}

INSTANTIATE_TEST_SUITE_P(MidRender, StopSignalGLTest,
                         ::testing::Values(StopCase{SIGINT, Kind::kMp4},
                                           StopCase{SIGTERM, Kind::kMp4},
                                           StopCase{SIGINT, Kind::kPngFrames},
                                           StopCase{SIGTERM, Kind::kPngFrames}),
                         stopCaseName);

// ---- SIGINT and SIGTERM during still, strobe, chart and data ---------------------------------

// A long run of a command other than render, named by where the stop signal meets it.
enum class LongRun {
  kStillSimulating,   // pi-blocks digits=9: 101 million collisions, 2.5 s of physics (Release)
  kStrobeSimulating,  // the same scene
  kChartSimulating,   // the same scene
  kDataSimulating,    // the same scene
  kJsonEvents,        // pi-blocks digits=7: 3.1 million collisions streamed as JSON (about 1 GB)
  kCsvRows,           // worked-example for 1000 s at --dt 0.0005: 2 million rows (about 350 MB)
};

std::string longRunName(LongRun run) {
  switch (run) {
    case LongRun::kStillSimulating:
      return "StillSimulating";
    case LongRun::kStrobeSimulating:
      return "StrobeSimulating";
    case LongRun::kChartSimulating:
      return "ChartSimulating";
    case LongRun::kDataSimulating:
      return "DataSimulating";
    case LongRun::kJsonEvents:
      return "JsonEvents";
    case LongRun::kCsvRows:
      return "CsvRows";
  }
  return "?";
}

// What a long run writes, a quick command writing a good file at the same path first, and when
// the signal comes.
struct LongRunPlan {
  std::string target;                 // file name in the output folder
  std::vector<std::string> good;      // writes a good `target` in well under a second
  std::vector<std::string> long_run;  // writes `target` for seconds
  // The signal comes 200 ms into the simulation (nothing opened yet), else once the temporary
  // file exists (the output half written).
  bool while_simulating = false;
};

LongRunPlan planFor(LongRun run, const fs::path& out_dir) {
  const auto in = [&](const std::string& name) { return (out_dir / name).string(); };
  const std::vector<std::string> small = {"--size", "160x90"};
  const std::vector<std::string> pi9 = {"pi-blocks", "--set", "digits=9"};
  const auto picture = [&](const std::string& command, const std::string& file) {
    std::vector<std::string> good = {command, "worked-example", "-o", in(file)};
    good.insert(good.end(), small.begin(), small.end());
    std::vector<std::string> slow = {command};
    slow.insert(slow.end(), pi9.begin(), pi9.end());
    slow.insert(slow.end(), {"-o", in(file)});
    slow.insert(slow.end(), small.begin(), small.end());
    return LongRunPlan{file, good, slow, true};
  };
  switch (run) {
    case LongRun::kStillSimulating: {
      LongRunPlan plan = picture("still", targetName(Kind::kPngStill));
      plan.good = commandFor(Kind::kPngStill, out_dir);
      plan.long_run.insert(plan.long_run.end(), {"--at", "1"});
      return plan;
    }
    case LongRun::kStrobeSimulating:
      return picture("strobe", "strobe.png");
    case LongRun::kChartSimulating:
      return picture("chart", "chart.png");
    case LongRun::kDataSimulating: {
      const std::string file = targetName(Kind::kJson);
      std::vector<std::string> slow = {"data"};
      slow.insert(slow.end(), pi9.begin(), pi9.end());
      slow.insert(slow.end(), {"--json", in(file)});
      return {file, commandFor(Kind::kJson, out_dir), slow, true};
    }
    case LongRun::kJsonEvents: {
      const std::string file = targetName(Kind::kJson);
      return {file,
              commandFor(Kind::kJson, out_dir),
              {"data", "pi-blocks", "--set", "digits=7", "--json", in(file), "--events"},
              false};
    }
    case LongRun::kCsvRows: {
      const std::string file = targetName(Kind::kCsv);
      return {
          file,
          commandFor(Kind::kCsv, out_dir),
          {"data", "worked-example", "--set", "duration=1000", "--csv", in(file), "--dt", "0.0005"},
          false};
    }
  }
  return {};
}

struct LongRunStop {
  int signal_number;
  LongRun run;
};

void PrintTo(const LongRunStop& stop, std::ostream* out) {
  *out << strsignal(stop.signal_number) << " during " << longRunName(stop.run);
}

class LongRunStopGLTest : public FaultsGLTest, public ::testing::WithParamInterface<LongRunStop> {};

std::string longRunStopName(const ::testing::TestParamInfo<LongRunStop>& info) {
  return std::string(info.param.signal_number == SIGINT ? "Sigint" : "Sigterm") +
         longRunName(info.param.run);
}

// A stop is shown by the exit status (128 + the signal) and the message: each long run here would
// go on for many minutes, and one that ignored the signal is killed as hung after the child's
// timeout. How long the stop took is printed, not asserted: a wall-clock limit fails on a loaded
// machine (the sanitizer build's exit-time leak check alone takes a good part of a second).

TEST_P(LongRunStopGLTest, StopsPromptlyAndKeepsTheEarlierFile) {
  const auto [signal_number, run] = GetParam();
  const LongRunPlan plan = planFor(run, out_dir_());
  const ChildResult good = collide(plan.good);
  ASSERT_EQ(good.exit_code, 0) << test::describe(good) << ": " << good.err;
  ASSERT_TRUE(fs::exists(out_dir_() / plan.target));
  const Snapshot before = snapshot();

  ChildOptions options;
  options.signal_number = signal_number;
  options.signal_once_caught = true;
  std::optional<std::chrono::steady_clock::time_point> caught;
  options.ready_for_signal = [&] {
    if (!plan.while_simulating) return temporaryFileIn(out_dir_());
    if (!caught) caught = std::chrono::steady_clock::now();
    return std::chrono::steady_clock::now() - *caught > std::chrono::milliseconds(200);
  };
  const ChildResult result = collide(plan.long_run, options);
  ASSERT_TRUE(result.signal_sent) << test::describe(result) << " before the signal: " << result.err;
  const std::string name = signal_number == SIGINT ? "SIGINT" : "SIGTERM";
  const std::string consequence =
      plan.while_simulating ? "nothing was written to" : "removed the partly written file";
  expectCleanFailure(result, 128 + signal_number,
                     {"stopped by " + name + "; " + consequence, plan.target}, before);
  EXPECT_FALSE(result.timed_out) << "still running " << options.timeout.count() << " s on";
  std::cout << "[          ] stopped " << result.signal_to_exit.count() * 1000.0
            << " ms after the signal\n";
}

INSTANTIATE_TEST_SUITE_P(LongRuns, LongRunStopGLTest,
                         ::testing::Values(LongRunStop{SIGINT, LongRun::kStillSimulating},
                                           LongRunStop{SIGTERM, LongRun::kStillSimulating},
                                           LongRunStop{SIGINT, LongRun::kStrobeSimulating},
                                           LongRunStop{SIGTERM, LongRun::kChartSimulating},
                                           LongRunStop{SIGINT, LongRun::kDataSimulating},
                                           LongRunStop{SIGTERM, LongRun::kDataSimulating},
                                           LongRunStop{SIGINT, LongRun::kJsonEvents},
                                           LongRunStop{SIGTERM, LongRun::kJsonEvents},
                                           LongRunStop{SIGINT, LongRun::kCsvRows},
                                           LongRunStop{SIGTERM, LongRun::kCsvRows}),
                         longRunStopName);

// Batch keeps its own stop handling inside the commands' (StopSignals nest): it stops its workers
// (which stop cleanly themselves) and still writes the manifest, listing the jobs cut short.
TEST_F(FaultsGLTest, SigintStopsABatchWhichStillWritesItsManifest) {
  ChildOptions options;
  options.signal_number = SIGINT;
  options.signal_once_caught = true;
  std::optional<std::chrono::steady_clock::time_point> caught;
  options.ready_for_signal = [&] {  // 200 ms in: the workers are simulating
    if (!caught) caught = std::chrono::steady_clock::now();
    return std::chrono::steady_clock::now() - *caught > std::chrono::milliseconds(200);
  };
  const ChildResult result = collide({"batch", "pi-blocks", "--set", "digits=9", "--formats", "png",
                                      "--jobs", "1", "--size", "160x90", "-o", out_dir_().string()},
                                     options);
  ASSERT_TRUE(result.signal_sent) << test::describe(result) << ": " << result.err;
  EXPECT_EQ(result.exit_code, 130) << test::describe(result) << ": " << result.err;
  EXPECT_NE(result.err.find("collide: stopped by SIGINT"), std::string::npos) << result.err;
  EXPECT_FALSE(result.timed_out) << "still running " << options.timeout.count() << " s on";
  const Snapshot after = snapshot();
  EXPECT_EQ(keys(after), std::vector<std::string>{"manifest.json"});
  const auto manifest = after.find("manifest.json");
  ASSERT_NE(manifest, after.end());
  EXPECT_NE(manifest->second.find("\"failed\""), std::string::npos) << manifest->second;
}

// A worker stopped while writing a long CSV removes its temporary file: the folder then holds only
// the manifest.
TEST_F(FaultsGLTest, SigintStopsABatchWorkerMidWriteWithoutLeavingItsTemporaryFile) {
  ChildOptions options;
  options.signal_number = SIGINT;
  options.signal_once_caught = true;
  options.ready_for_signal = [&] { return temporaryFileIn(out_dir_()); };
  const ChildResult result =
      collide({"batch", "worked-example", "--set", "duration=1000", "--formats", "csv",
               "--csv-step", "0.0005", "--jobs", "1", "-o", out_dir_().string()},
              options);
  ASSERT_TRUE(result.signal_sent) << test::describe(result) << ": " << result.err;
  EXPECT_EQ(result.exit_code, 130) << test::describe(result) << ": " << result.err;
  EXPECT_FALSE(result.timed_out) << "still running " << options.timeout.count() << " s on";
  EXPECT_EQ(keys(snapshot()), std::vector<std::string>{"manifest.json"});
}

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
}  // namespace collide
