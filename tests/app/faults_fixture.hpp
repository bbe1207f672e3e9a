#pragma once
// The fixture the fault tests share (faults_gltest.cpp, injected_faults_gltest.cpp): the output
// kinds a user asks for and the commands that write them, a scratch folder per test, snapshots of
// it, and the check that a fault failed cleanly and left the earlier good output as it was.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "faults/child_process.hpp"
#include "progress_lines.hpp"
#include "scratch.hpp"

namespace collide::faults_test {
namespace fs = std::filesystem;
using test::ChildOptions;
using test::ChildResult;

// Every file and directory under a folder: relative path -> bytes ("" and a trailing '/' for a
// directory). Equal snapshots mean nothing was added, removed or changed, hidden files included.
using Snapshot = std::map<std::string, std::string>;

// The output kinds a user asks for, each with the command that writes it.
enum class Kind { kMp4, kWebm, kGif, kPngStill, kPngFrames, kCsv, kJson };

inline std::string kindName(Kind kind);

// For gtest's messages about parameters.
inline void PrintTo(Kind kind, std::ostream* out) {
  *out << kindName(kind);
}

inline std::string kindName(Kind kind) {
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
inline std::string targetName(Kind kind) {
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
inline const std::vector<std::string> kSmallClip = {"--size", "160x90", "--fps", "10"};

// The command that writes `kind` into `out_dir`; videos and frames last `duration_s` seconds.
inline std::vector<std::string> commandFor(Kind kind, const fs::path& out_dir,
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
inline std::vector<std::string> changedCommandFor(Kind kind, const fs::path& out_dir,
                                                  const std::string& duration_s = "0.5") {
  std::vector<std::string> args = commandFor(kind, out_dir, duration_s);
  args.insert(args.end(), {"--set", "restitution=0.9"});
  return args;
}

inline const std::vector<Kind> kAllKinds = {Kind::kMp4,      Kind::kWebm,      Kind::kGif,
                                            Kind::kPngStill, Kind::kPngFrames, Kind::kCsv,
                                            Kind::kJson};

// Writes `text` as the whole of the file at `path`.
inline void writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline std::string testName() {
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
    const bool as_nobody = options.unprivileged && geteuid() == 0;
    const fs::path program = as_nobody ? programForNobody() : fs::path(COLLIDE_BINARY);
    return test::runChild(program.string(), args, options);
  }

  // Why user nobody, who runs the unwritable-directory cases as root, cannot reach this test's
  // folder ("" when it can): a folder above it that others may not enter (TMPDIR under a mode-700
  // home, say).
  std::string whyNobodyCannotEnter() const {
    if (geteuid() != 0) return "";
    for (fs::path folder = dir_.parent_path();; folder = folder.parent_path()) {
      struct stat status {};
      if (::stat(folder.c_str(), &status) == 0 && (status.st_mode & S_IXOTH) == 0) {
        return "user nobody cannot enter " + folder.string() + " (no search permission for " +
               "others), which holds this test's folder; set TMPDIR to a folder nobody may enter";
      }
      if (folder == folder.parent_path()) return "";
    }
  }

  // A copy of collide and of the modules it opens from beside itself (collide-*.so) in this
  // test's folder, where user nobody can run it: the build tree may lie where nobody cannot
  // enter (a clone under /root, mode 700 on Debian).
  fs::path programForNobody() {
    const fs::path built = COLLIDE_BINARY;
    const fs::path folder = dir_ / "program";
    if (fs::exists(folder)) return folder / built.filename();
    fs::create_directory(folder);
    fs::copy_file(built, folder / built.filename());
    for (const auto& entry : fs::directory_iterator(built.parent_path())) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("collide-", 0) == 0 && entry.path().extension() == ".so") {
        fs::copy_file(entry.path(), folder / name);
      }
    }
    for (const auto& entry : fs::directory_iterator(folder)) ::chmod(entry.path().c_str(), 0755);
    ::chmod(folder.c_str(), 0755);
    return folder / built.filename();
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
    // A slow run (a loaded machine) may report its progress before failing: not part of the error.
    const std::string error = test::withoutProgressLines(result.err);
    EXPECT_EQ(std::count(error.begin(), error.end(), '\n'), 1) << "not one line:\n" << result.err;
    EXPECT_EQ(error.rfind("collide: ", 0), 0u) << result.err;
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

}  // namespace collide::faults_test
