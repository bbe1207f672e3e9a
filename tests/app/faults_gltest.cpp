// Issue 8, item 4: faults, through the real `collide` binary. Each fault (a full disk, an
// unwritable directory, SIGINT or SIGTERM mid-render or during a long still, strobe, chart or
// data run, which must also stop within a second) must end with one clear stderr line (what
// failed, what to do), a non-zero exit, no hang, no partial or temporary file, and an earlier good
// output at the same path left byte for byte as it was. The faults a preloaded shim injects (a
// missing font, a GL context that cannot be made, a missing encoder): injected_faults_gltest.cpp.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "faults_fixture.hpp"

namespace collide::faults_test {
namespace {

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
  if (const std::string why = whyNobodyCannotEnter(); !why.empty()) GTEST_SKIP() << why;
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
  // On a machine whose disk is busy a frame's write can stall past the stop's grace
  // (output/stop_signals.hpp); the watchdog then ends the run with its own line, which is as clean
  // (same exit code, temporary files removed, the earlier file kept) but cannot name the output.
  const bool watchdog = result.err.find("did not reach a point to stop at") != std::string::npos;
  std::vector<std::string> needles = {"stopped by " + name};
  if (!watchdog) needles.push_back(targetName(kind));
  expectCleanFailure(result, 128 + signal_number, needles, before);
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

}  // namespace
}  // namespace collide::faults_test
