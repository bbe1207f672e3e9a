// SPDX-License-Identifier: MIT
// Issue 38, item 4, through the real `collide` binary: files left behind and signals not honoured.
//   - A temporary file is removed on every exit the process can see: SIGHUP stops a run as
//     SIGTERM does; SIGQUIT, SIGPIPE, SIGUSR1, SIGALRM and SIGXCPU end it without leaving one; a
//     batch parent removes a SIGKILLed worker's and says what killed it without quoting the worker
//     protocol; a batch's workers end with it; a folder moved mid-render keeps no temporary file.
//   - A render into a folder that holds a longer earlier run leaves only the new run's frames.
//   - A replaced file keeps its mode, and its owner when the tests run as root.
//   - A blocked read or write (a FIFO as output or as --font, JSON into a pipe nobody reads)
//     never outlives one SIGTERM or SIGINT.
// Every FIFO is made in the test's own folder.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "faults_fixture.hpp"

namespace collide::faults_test {
namespace {

using Clock = std::chrono::steady_clock;

// The process id in a temporary file's name in `folder` (".NAME.tmp-PID-N.EXT"), or 0.
pid_t temporaryFileOwner(const fs::path& folder) {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    const std::size_t at = name.find(".tmp-");
    if (name.front() != '.' || at == std::string::npos) continue;
    return static_cast<pid_t>(std::stol(name.substr(at + 5)));
  }
  return 0;
}

bool alive(pid_t pid) {
  return ::kill(pid, 0) == 0 || errno != ESRCH;
}

// Waits up to `limit` for process `pid` to be gone.
bool endsWithin(pid_t pid, std::chrono::seconds limit) {
  const auto deadline = Clock::now() + limit;
  while (alive(pid)) {
    if (Clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

// A batch job that writes one CSV for seconds: 2 million rows.
std::vector<std::string> longCsvBatch(const fs::path& out_dir) {
  return {"batch", "worked-example", "--set",  "duration=1000", "--formats",
          "csv",   "--csv-step",     "0.0005", "--jobs",        "1",
          "-o",    out_dir.string()};
}

// ---- SIGHUP, and every other signal that ends a render ---------------------------------------

TEST_F(FaultsGLTest, SighupStopsARenderLikeSigterm) {
  writeGood(Kind::kMp4);
  const Snapshot before = snapshot();
  ChildOptions options;
  options.signal_number = SIGHUP;
  options.ready_for_signal = [&] { return temporaryFileIn(out_dir_()); };
  const ChildResult result = collide(changedCommandFor(Kind::kMp4, out_dir_(), "600"), options);
  ASSERT_TRUE(result.signal_sent) << result.err;
  expectCleanFailure(result, 128 + SIGHUP, {"stopped by SIGHUP", "clip.mp4"}, before);
}

class EndingSignalGLTest : public FaultsGLTest, public ::testing::WithParamInterface<int> {};

TEST_P(EndingSignalGLTest, EndsTheRenderAsItWouldWithoutLeavingItsTemporaryFile) {
  writeGood(Kind::kMp4);
  const Snapshot before = snapshot();
  ChildOptions options;
  options.signal_number = GetParam();
  options.ready_for_signal = [&] { return temporaryFileIn(out_dir_()); };
  options.no_core_dump = true;  // SIGQUIT and SIGXCPU would dump one
  options.working_directory = dir_.string();
  const ChildResult result = collide(changedCommandFor(Kind::kMp4, out_dir_(), "600"), options);
  ASSERT_TRUE(result.signal_sent) << result.err;
  EXPECT_FALSE(result.timed_out);
  EXPECT_EQ(result.killed_by_signal, GetParam()) << test::describe(result) << ": " << result.err;
  EXPECT_EQ(snapshot(), before) << "a temporary file was left, or the earlier file changed";
}

INSTANTIATE_TEST_SUITE_P(Signals, EndingSignalGLTest,
                         ::testing::Values(SIGQUIT, SIGPIPE, SIGUSR1, SIGALRM, SIGXCPU),
                         [](const auto& info) { return std::string(sigabbrev_np(info.param)); });

// ---- batch workers ---------------------------------------------------------------------------

TEST_F(FaultsGLTest, AKilledWorkersTemporaryFileIsRemovedAndItsEndSaidPlainly) {
  ChildOptions options;
  options.signal_number = SIGKILL;  // sent here to the worker, never to the batch itself
  pid_t worker = 0;
  options.ready_for_signal = [&] {
    if (worker == 0 && (worker = temporaryFileOwner(out_dir_())) != 0) ::kill(worker, SIGKILL);
    return false;
  };
  const ChildResult result = collide(longCsvBatch(out_dir_()), options);
  ASSERT_NE(worker, 0) << "no worker wrote a temporary file: " << result.err;
  EXPECT_EQ(result.exit_code, 1) << test::describe(result) << ": " << result.err;
  EXPECT_EQ(keys(snapshot()), std::vector<std::string>{"manifest.json"});
  EXPECT_NE(result.err.find("killed by signal 9 (Killed)"), std::string::npos) << result.err;
  // Nothing of the protocol between the batch and its workers: report lines, JSON strings.
  for (const std::string protocol : {"scene ", "title ", "lang ", "\"worked-example\""}) {
    EXPECT_EQ(result.err.find(protocol), std::string::npos) << protocol << " in " << result.err;
  }
}

TEST_F(FaultsGLTest, SighupStopsABatchAndItsWorkersAndTheManifestIsWritten) {
  ChildOptions options;
  options.signal_number = SIGHUP;
  pid_t worker = 0;
  options.ready_for_signal = [&] { return (worker = temporaryFileOwner(out_dir_())) != 0; };
  const ChildResult result = collide(longCsvBatch(out_dir_()), options);
  ASSERT_TRUE(result.signal_sent) << result.err;
  EXPECT_EQ(result.exit_code, 128 + SIGHUP) << test::describe(result) << ": " << result.err;
  EXPECT_NE(result.err.find("stopped by SIGHUP"), std::string::npos) << result.err;
  EXPECT_FALSE(alive(worker)) << "worker " << worker << " outlived its batch";
  EXPECT_EQ(keys(snapshot()), std::vector<std::string>{"manifest.json"});
  const nlohmann::json manifest =
      nlohmann::json::parse(test::readFileBytes(out_dir_() / "manifest.json"));
  EXPECT_EQ(manifest["failed"], 1);
}

TEST_F(FaultsGLTest, WorkersOfAKilledBatchEndAndRemoveTheirTemporaryFiles) {
  ChildOptions options;
  options.signal_number = SIGKILL;
  pid_t worker = 0;
  options.ready_for_signal = [&] { return (worker = temporaryFileOwner(out_dir_())) != 0; };
  const ChildResult result = collide(longCsvBatch(out_dir_()), options);
  ASSERT_TRUE(result.signal_sent) << result.err;
  EXPECT_TRUE(endsWithin(worker, std::chrono::seconds(10))) << "worker " << worker << " orphaned";
  EXPECT_FALSE(temporaryFileIn(out_dir_()));
}

// ---- the output's folder moved mid-render ----------------------------------------------------

TEST_F(FaultsGLTest, AFolderMovedMidRenderKeepsNoTemporaryFile) {
  const fs::path folder = out_dir_() / "lesson", moved = out_dir_() / "moved";
  fs::create_directory(folder);
  std::vector<std::string> args = commandFor(Kind::kMp4, folder, "600");
  ChildOptions options;
  options.signal_number = SIGTERM;
  options.ready_for_signal = [&] {
    if (!temporaryFileIn(folder)) return false;
    fs::rename(folder, moved);
    return true;
  };
  const ChildResult result = collide(args, options);
  ASSERT_TRUE(result.signal_sent) << result.err;
  EXPECT_EQ(result.exit_code, 128 + SIGTERM) << test::describe(result) << ": " << result.err;
  EXPECT_EQ(keys(snapshot()), std::vector<std::string>{"moved/"});
}

TEST_F(FaultsGLTest, AFolderMovedMidRenderGetsTheFinishedVideo) {
  const fs::path folder = out_dir_() / "lesson", moved = out_dir_() / "moved";
  fs::create_directory(folder);
  ChildOptions options;
  options.signal_number = SIGTERM;  // never sent: the lambda only moves the folder
  bool renamed = false;
  options.ready_for_signal = [&] {
    if (!renamed && temporaryFileIn(folder)) {
      fs::rename(folder, moved);
      renamed = true;
    }
    return false;
  };
  const ChildResult result = collide(commandFor(Kind::kMp4, folder, "20"), options);
  ASSERT_TRUE(renamed) << "the render ended before its folder could be moved: " << result.err;
  EXPECT_EQ(result.exit_code, 0) << test::describe(result) << ": " << result.err;
  EXPECT_EQ(keys(snapshot()), (std::vector<std::string>{"moved/", "moved/clip.mp4"}));
}

// ---- PNG frames over a longer earlier run; a replaced file's mode ----------------------------

TEST_F(FaultsGLTest, FramesOfALongerEarlierRunAreRemoved) {
  const fs::path frames = out_dir_() / targetName(Kind::kPngFrames);
  ASSERT_EQ(collide(commandFor(Kind::kPngFrames, out_dir_(), "1")).exit_code, 0);  // 10 frames
  writeText(frames / "notes.txt", "mine");  // not a frame: stays
  const ChildResult shorter = collide(commandFor(Kind::kPngFrames, out_dir_(), "0.5"));
  ASSERT_EQ(shorter.exit_code, 0) << shorter.err;
  std::vector<std::string> expected;
  for (int k = 0; k < 5; ++k) expected.push_back("frames/frame_0000" + std::to_string(k) + ".png");
  expected.insert(expected.begin(), "frames/");
  expected.push_back("frames/notes.txt");
  EXPECT_EQ(keys(snapshot()), expected);
}

TEST_F(FaultsGLTest, AReplacedFileKeepsItsModeAndOwner) {
  const fs::path json = out_dir_() / targetName(Kind::kJson);
  writeText(json, "earlier");
  ASSERT_EQ(::chmod(json.c_str(), 0640), 0);
  const bool root = ::geteuid() == 0;
  if (root) {
    ASSERT_EQ(::chown(json.c_str(), 65534, 65534), 0);  // nobody:nogroup
  }
  struct stat old {};
  ASSERT_EQ(::stat(json.c_str(), &old), 0);
  ASSERT_EQ(collide(commandFor(Kind::kJson, out_dir_())).exit_code, 0);
  struct stat now {};
  ASSERT_EQ(::stat(json.c_str(), &now), 0);
  EXPECT_NE(now.st_ino, old.st_ino) << "not replaced";
  EXPECT_EQ(now.st_mode & 07777, 0640u);
  if (root) {
    EXPECT_EQ(now.st_uid, old.st_uid);
    EXPECT_EQ(now.st_gid, old.st_gid);
  }
}

// ---- blocked reads and writes ----------------------------------------------------------------

// Ready once the run has been caught by `signal_number`'s handler (or, with `caught` false, has
// run) for `after`: by then it is blocked where the test put it.
std::function<bool()> readyAfter(std::chrono::milliseconds after) {
  auto start = std::make_shared<std::optional<Clock::time_point>>();
  return [start, after] {
    if (!*start) *start = Clock::now();
    return Clock::now() - **start > after;
  };
}

class BlockedGLTest : public FaultsGLTest, public ::testing::WithParamInterface<int> {};

TEST_P(BlockedGLTest, AFifoNobodyReadsAsTheOutput) {
  const fs::path fifo = out_dir_() / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  ChildOptions options;
  options.signal_number = GetParam();
  options.signal_once_caught = true;  // the render's stop handling is in place
  options.ready_for_signal = readyAfter(std::chrono::milliseconds(300));
  options.timeout = std::chrono::seconds(30);
  const ChildResult result =
      collide({"render", "worked-example", "--size", "64x64", "-o", fifo.string()}, options);
  ASSERT_TRUE(result.signal_sent) << result.err;
  EXPECT_FALSE(result.timed_out) << "blocked past the signal";
  EXPECT_EQ(result.exit_code, 128 + GetParam()) << test::describe(result) << ": " << result.err;
  EXPECT_NE(result.err.find("stopped by"), std::string::npos) << result.err;
}

TEST_P(BlockedGLTest, AFifoNobodyWritesAsTheFont) {
  const fs::path fifo = out_dir_() / "font.ttf";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  ChildOptions options;
  options.signal_number = GetParam();
  options.ready_for_signal = readyAfter(std::chrono::milliseconds(300));
  options.timeout = std::chrono::seconds(30);
  const ChildResult result = collide({"still", "worked-example", "--size", "64x64", "--font",
                                      fifo.string(), "-o", (out_dir_() / "a.png").string()},
                                     options);
  ASSERT_TRUE(result.signal_sent) << result.err;
  EXPECT_FALSE(result.timed_out) << "blocked past the signal";
  EXPECT_TRUE(result.killed_by_signal == GetParam() || result.exit_code == 128 + GetParam())
      << test::describe(result) << ": " << result.err;
  fs::remove(fifo);  // a snapshot would read it, and wait for a writer
  EXPECT_TRUE(fs::is_empty(out_dir_())) << "the picture was written";
}

TEST_P(BlockedGLTest, JsonIntoAPipeNobodyReads) {
  ChildOptions options;
  options.stdout_to = test::ChildStdout::kStalledPipe;
  options.signal_number = GetParam();
  options.signal_once_caught = true;
  // 3.1 million collisions: the pipe is full long before the JSON ends.
  options.ready_for_signal = readyAfter(std::chrono::milliseconds(1500));
  options.timeout = std::chrono::seconds(60);
  const ChildResult result =
      collide({"data", "pi-blocks", "--set", "digits=7", "--events", "--json", "-"}, options);
  ASSERT_TRUE(result.signal_sent) << result.err;
  EXPECT_FALSE(result.timed_out) << "blocked past the signal";
  EXPECT_EQ(result.exit_code, 128 + GetParam()) << test::describe(result) << ": " << result.err;
  EXPECT_LT(result.signal_to_exit, std::chrono::seconds(10));
}

INSTANTIATE_TEST_SUITE_P(OneSignal, BlockedGLTest, ::testing::Values(SIGTERM, SIGINT),
                         [](const auto& info) { return std::string(sigabbrev_np(info.param)); });

}  // namespace
}  // namespace collide::faults_test
