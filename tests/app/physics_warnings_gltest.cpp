// A physics warning reaches the user from every command that simulates: a scene whose run stops
// early (two disks come to rest stacked under gravity, which the event-driven 2D model does not
// follow) still gets its output, and stderr has one "warning:" line saying where and why. A scene
// without warnings prints nothing on stderr.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "scratch.hpp"

namespace collide {
namespace {
namespace fs = std::filesystem;

using test::CliResult;
using test::run;

// Disk "high" falls 0.2 m onto disk "low", which rests on the floor; with e = 0 it stays there.
constexpr const char* kRestingStack = R"(name = "stack"
dimensions = 2
duration = 2.0
gravity = [0, -9.81]
restitution = 0.0

[box]
min = [-1, 0]
max = [1, 3]

[[body]]
name = "low"
mass = 1
size = 0.2
position = [0, 0.2]
velocity = [0, 0]

[[body]]
name = "high"
mass = 1
size = 0.2
position = [0, 0.8]
velocity = [0, 0]
)";

int countLines(const std::string& text, const std::string& start) {
  int count = 0;
  for (std::size_t at = 0; at < text.size();) {
    if (text.compare(at, start.size(), start) == 0) ++count;
    const std::size_t end = text.find('\n', at);
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return count;
}

class PhysicsWarningsGLTest : public ::testing::TestWithParam<std::vector<std::string>> {
 protected:
  void SetUp() override {
    dir_ = test::makeUniqueTempDir("collide_warnings_");
    std::ofstream(path("stack.toml")) << kRestingStack;
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // The parameter with {dir} replaced by the scratch directory.
  std::vector<std::string> arguments() const {
    std::vector<std::string> args = GetParam();
    for (std::string& arg : args) {
      for (std::size_t at; (at = arg.find("{dir}")) != std::string::npos;) {
        arg.replace(at, 5, dir_.string());
      }
    }
    return args;
  }
  fs::path dir_;
};

TEST_P(PhysicsWarningsGLTest, AnEarlyStopIsReportedOnceAndTheOutputIsStillWritten) {
  std::vector<std::string> args = arguments();
  const CliResult r = run(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(countLines(r.err, "warning: "), 1) << r.err;
  EXPECT_EQ(countLines(r.err, "warning: stopped at t = "), 1) << r.err;
  EXPECT_NE(r.err.find("\"high\""), std::string::npos) << r.err;  // names the disk
  // The output named after -o (data: --json) exists.
  auto o = std::find(args.begin(), args.end(), "-o");
  if (o == args.end()) o = std::find(args.begin(), args.end(), "--json");
  ASSERT_LT(o + 1, args.end()) << "every command here names its output";
  EXPECT_TRUE(fs::is_regular_file(*(o + 1))) << *(o + 1);

  // The same command on a scene that runs to its end says nothing on stderr.
  for (std::string& arg : args) {
    if (arg == path("stack.toml")) arg = "worked-example";
  }
  const CliResult clean = run(args);
  ASSERT_EQ(clean.exit_code, 0) << clean.err;
  EXPECT_EQ(clean.err, "");
}

INSTANTIATE_TEST_SUITE_P(
    Commands, PhysicsWarningsGLTest,
    ::testing::Values(std::vector<std::string>{"still", "{dir}/stack.toml", "--at", "1", "-o",
                                               "{dir}/s.png", "--size", "160x90"},
                      std::vector<std::string>{"render", "{dir}/stack.toml", "-o", "{dir}/v.mp4",
                                               "--size", "160x90", "--fps", "5", "-q"},
                      std::vector<std::string>{"strobe", "{dir}/stack.toml", "-o", "{dir}/b.png",
                                               "--size", "160x90", "--rate", "5"},
                      std::vector<std::string>{"chart", "{dir}/stack.toml", "-o", "{dir}/c.png",
                                               "--size", "160x90"},
                      std::vector<std::string>{"data", "{dir}/stack.toml", "--json",
                                               "{dir}/d.json"}),
    [](const ::testing::TestParamInfo<std::vector<std::string>>& info) {
      return info.param[0] + std::to_string(info.index);
    });

// Comparison panels simulate once each: each panel's warning is printed, named by its heading.
TEST(PhysicsWarningsPanelsGLTest, EachPanelsWarningNamesThePanel) {
  const fs::path dir = test::makeUniqueTempDir("collide_warning_panels_");
  std::ofstream(dir / "stack.toml") << kRestingStack;
  const CliResult r =
      run({"still", (dir / "stack.toml").string(), "--at", "1", "-o", (dir / "p.png").string(),
           "--size", "160x90", "--panels", "restitution=0,0.1"});
  fs::remove_all(dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Every line names its panel (e = 0.1 also meets the collapse guard on its way to rest).
  EXPECT_EQ(countLines(r.err, "warning: "),
            countLines(r.err, "warning: e = 0: ") + countLines(r.err, "warning: e = 0.1: "))
      << r.err;
  EXPECT_EQ(countLines(r.err, "warning: e = 0: stopped at t = "), 1) << r.err;
  EXPECT_EQ(countLines(r.err, "warning: e = 0.1: stopped at t = "), 1) << r.err;
}

}  // namespace
}  // namespace collide
