// Every kind of bad input, through the real `collide` binary as a user types it: exit 2, exactly
// one line on stderr that names what is wrong and what is allowed, nothing on stdout, and no
// output file (nor a temporary one) left behind.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "bad_input_cases.hpp"
#include "scratch.hpp"

namespace collide {
namespace {
namespace fs = std::filesystem;
using bad_input::BadInput;

std::string replaced(std::string text, const std::string& dir) {
  for (std::size_t at; (at = text.find("{dir}")) != std::string::npos;) text.replace(at, 5, dir);
  return text;
}

class BadInputMatrixTest : public ::testing::TestWithParam<BadInput> {
 protected:
  void SetUp() override {
    dir_ = test::makeUniqueTempDir(std::string("collide_bad_input_") + GetParam().name + "_");
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// Every entry under `dir` with its type and, for a regular file, its bytes (for a link, where it
// points): what must not change. Links are never followed (a case makes a link loop).
void snapshotInto(const fs::path& dir, const fs::path& root,
                  std::map<std::string, std::string>& entries) {
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    const fs::file_status status = entry.symlink_status();
    std::string state = std::to_string(static_cast<int>(status.type()));
    if (status.type() == fs::file_type::regular) state += ":" + test::readFileBytes(entry.path());
    if (status.type() == fs::file_type::symlink) state += ":" + fs::read_symlink(entry).string();
    if (status.type() == fs::file_type::directory) snapshotInto(entry.path(), root, entries);
    entries[entry.path().lexically_relative(root).string()] = state;
  }
}

std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> entries;
  snapshotInto(dir, dir, entries);
  return entries;
}

TEST_P(BadInputMatrixTest, ExitsTwoWithOneLineAndWritesNothing) {
  const BadInput& input = GetParam();
  if (!input.scene_text.empty()) std::ofstream(dir_ / "scene.toml") << input.scene_text;
  if (!input.prepare.empty()) {
    const std::string prepare = "cd " + test::shellQuoted(dir_.string()) + " && " +
                                replaced(input.prepare, test::shellQuoted(dir_.string()));
    const int prepared = test::runShellBounded(prepare, std::chrono::seconds(10));
    // 77: what the case needs cannot be made here (mknod refused): skipped, saying so.
    if (prepared == 77) GTEST_SKIP() << "cannot prepare here: " << prepare;
    ASSERT_EQ(prepared, 0) << prepare;
  }
  const std::map<std::string, std::string> before = snapshot(dir_);
  const fs::path logs =
      test::makeUniqueTempDir(std::string("collide_bad_input_log_") + input.name + "_");
  // {dir} as one shell word: '/tmp/x'/a.mp4 is one word to the shell.
  const std::string command = test::shellQuoted(COLLIDE_BINARY) + " " +
                              replaced(input.arguments, test::shellQuoted(dir_.string())) + " >" +
                              test::shellQuoted((logs / "out").string()) + " 2>" +
                              test::shellQuoted((logs / "err").string());
  const int status = test::runShellBounded(command, std::chrono::seconds(60));
  const std::string out = test::readFileBytes(logs / "out"),
                    err = test::readFileBytes(logs / "err");
  fs::remove_all(logs);

  EXPECT_EQ(status, 2) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  // Whatever was typed, the line stays readable: values are cut at 80 characters.
  EXPECT_LT(err.size(), 1000u) << err.substr(0, 300);
  for (const std::string& needle : input.needles) {
    EXPECT_NE(err.find(replaced(needle, dir_.string())), std::string::npos)
        << "missing '" << needle << "' in: " << err;
  }
  EXPECT_TRUE(out.empty()) << out;
  // Only what the test made, byte for byte: no output, no temporary file, earlier files intact.
  const std::map<std::string, std::string> after = snapshot(dir_);
  for (const auto& [name, state] : after) {
    EXPECT_TRUE(before.count(name) == 1 && before.at(name) == state) << "changed or new: " << name;
  }
  EXPECT_EQ(before.size(), after.size());
}

INSTANTIATE_TEST_SUITE_P(Cases, BadInputMatrixTest, ::testing::ValuesIn(bad_input::cases()),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace

// For gtest's messages about a case (found by argument-dependent lookup, so beside BadInput).
namespace bad_input {
void PrintTo(const BadInput& input, std::ostream* out) {
  *out << input.name;
}
}  // namespace bad_input
}  // namespace collide
