// Scene files, --set, shortcuts, `collide check` and `collide presets show` through the CLI,
// in-process. Bad input: exit 2, one line on stderr naming the place, the key and what is
// allowed, nothing on stdout and no file written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "scene/scene_desc.hpp"
#include "scene/scene_io.hpp"
#include "scratch.hpp"

namespace collide {
namespace {
namespace fs = std::filesystem;

using test::CliResult;
using test::run;

int lines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

// A valid two-cart scene, lines 1 to 11.
const std::string kCarts = R"(name = "carts"
restitution = 0.5
[[body]]
mass = 1
size = 0.5
position = -1
velocity = 1
[[body]]
mass = 2
size = 0.5
position = 1
)";

// kCarts without its two top-level lines, for tests that write their own.
std::string bodiesOnly() {
  return kCarts.substr(kCarts.find("[[body]]"));
}

class SceneCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::makeUniqueTempDir(
        "collide_scene_cli_" +
        std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_");
    fs::create_directories(dir_ / "in");
    fs::create_directories(dir_ / "out");
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / "in" / name;
    std::ofstream(path) << text;
    return path.string();
  }
  std::string out(const std::string& name) const { return (dir_ / "out" / name).string(); }

  // Every rendering command refuses `scene_args` the same way, and writes nothing.
  void expectBadInput(const std::vector<std::string>& scene_args, const std::string& needle) {
    const std::vector<std::vector<std::string>> commands = {
        {"render", "-o", out("a.mp4")},
        {"still", "--at", "0", "-o", out("a.png")},
        {"data", "--json", out("a.json")},
        {"check"}};
    for (std::vector<std::string> args : commands) {
      args.insert(args.begin() + 1, scene_args.begin(), scene_args.end());
      const CliResult result = run(args);
      SCOPED_TRACE(args.front() + " " + scene_args.front());
      EXPECT_EQ(result.exit_code, 2) << result.err;
      EXPECT_EQ(lines(result.err), 1) << result.err;
      EXPECT_NE(result.err.find(needle), std::string::npos) << result.err;
      EXPECT_TRUE(result.out.empty()) << result.out;
      EXPECT_TRUE(fs::is_empty(dir_ / "out"));
    }
  }

  fs::path dir_;
};

TEST_F(SceneCliTest, BadSceneFilesAreRefusedWithTheirPlace) {
  const std::string bad_mass =
      write("m.toml", kCarts + "[[body]]\nmass = 0\nsize = 1\nposition = 5\n");
  expectBadInput({bad_mass}, bad_mass + ":13:8: body.3.mass: 0: out of range; allowed: a mass");
  expectBadInput({write("e.toml", "restitution = 1.5\n" + bodiesOnly())},
                 ":1:15: restitution: 1.5: out of range; allowed: a coefficient of restitution "
                 "from 0 to 1");
  expectBadInput({write("neg.toml", "restitution = -0.5\n" + bodiesOnly())},
                 ":1:15: restitution: -0.5: out of range");
  expectBadInput({write("nan.toml", kCarts + "[view]\ntrail = nan\n")},
                 ":13:9: view.trail: nan: not a finite number");
  expectBadInput({write("inf.toml", "gravity = inf\n" + kCarts)},
                 ":1:11: gravity: inf: not a finite number");
  expectBadInput({write("overlap.toml", kCarts + "[[body]]\nmass = 1\nsize = 1\nposition = 1.2\n")},
                 ":15:12: body.3.position: 1.2: overlaps body 2 ('body 2') at t = 0");
  expectBadInput({write("key.toml", kCarts + "velocty = 3\n")},
                 ":12:1: body.2.velocty: 3: unknown key; did you mean 'velocity'?");
  expectBadInput({write("type.toml", "duration = [4]\n" + kCarts)},
                 ":1:12: duration: [4]: wrong type (an array); allowed: a duration in s");
  expectBadInput({write("unit.toml", "duration = \"4 kg\"\n" + kCarts)},
                 ":1:12: duration: \"4 kg\": a mass, not a time; allowed: a time in s, ms, min, h");
  expectBadInput({write("zero.toml", "duration = 0\n" + kCarts)},
                 ":1:12: duration: 0: out of range");
  expectBadInput({write("long.toml", "duration = 1e6\n" + kCarts)}, "at most 3600");
  std::string crowd;
  for (int i = 0; i <= scene::kMaxBodies; ++i) {
    crowd += "[[body]]\nmass = 1\nsize = 0.5\nposition = " + std::to_string(i) + "\n";
  }
  expectBadInput({write("crowd.toml", crowd)}, "1001 bodies; allowed: at most 1000");
  expectBadInput({write("broken.toml", "restitution = [0.5\n")}, ":1:20: malformed TOML:");
}

TEST_F(SceneCliTest, MissingUnreadableAndUnknownScenes) {
  expectBadInput({out("missing.toml")},
                 "missing.toml': cannot read: No such file or directory; allowed: a preset name");
  expectBadInput({(dir_ / "in").string() + "/"}, "is a directory");
  expectBadInput({"elastik"}, "no such preset or file; did you mean 'elastic'?");
}

TEST_F(SceneCliTest, BadOverridesAreRefusedByHowTheyWereWritten) {
  expectBadInput({"worked-example", "--set", "restitution"}, "--set: 'restitution': not KEY=VALUE");
  expectBadInput({"worked-example", "--set", "restitution=2"},
                 "--set restitution=2: restitution: 2: out of range");
  expectBadInput({"worked-example", "--set", "body.3.mass=1"},
                 "--set body.3.mass=1: body.3.mass: 1: no body.3 in this scene; allowed: an index "
                 "from 1 to 2");
  expectBadInput({"worked-example", "--m2", "-1"}, "--m2 -1: body.2.mass: -1: out of range");
  expectBadInput({"worked-example", "--e", "nan"}, "--e nan: restitution: nan: not a finite");
  expectBadInput({"worked-example", "--theta1", "45"},
                 "--theta1 45: body.1: 45: this is a 1D scene");
  expectBadInput({"pi-blocks", "--set", "digits=10"},
                 "--set digits=10: digits: 10: allowed: digits of pi");
}

TEST_F(SceneCliTest, CheckListsEveryProblem) {
  const std::string path = write(
      "three.toml", "restitution = 3\n[[body]]\nmass = -1\nsize = 1\nposition = 0\ncolour = 1\n");
  const CliResult result = run({"check", path, "worked-example"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(lines(result.err), 4) << result.err;  // three problems and the count
  EXPECT_NE(result.err.find(path + ":1:15: restitution: 3: "), std::string::npos) << result.err;
  EXPECT_NE(result.err.find(path + ":6:1: body.1.colour: 1: unknown key; did you mean 'color'?"),
            std::string::npos)
      << result.err;
  EXPECT_NE(result.err.find(path + ":3:8: body.1.mass: -1: "), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("1 of 2 scenes have problems"), std::string::npos) << result.err;
  EXPECT_NE(result.out.find("ok: worked-example: 'Inelastic collision, e = 0.5', 1D, 2 bodies"),
            std::string::npos)
      << result.out;
}

TEST_F(SceneCliTest, CheckListsAScreenfulOfEachKindAndCountsTheRest) {
  // 2,000 unknown top-level tables (lines 12 to 2,011, in file order) and 12 unknown keys in the
  // first body: ten of each kind are listed, in file order, then how many more of each kind.
  std::string text = kCarts;
  text.insert(text.find("mass = 1\n"), [] {
    std::string keys;
    for (int k = 0; k < 12; ++k) keys += "extra" + std::to_string(k) + " = 1\n";
    return keys;
  }());
  for (int k = 0; k < 2000; ++k) text += "[table" + std::to_string(k) + "]\n";
  const std::string path = write("many.toml", text);
  const CliResult result = run({"check", path});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(lines(result.err), 10 + 10 + 2) << result.err;
  EXPECT_LT(result.err.size(), 8000u);
  // table0 to table9 (lines 24 to 33: after the 11 lines of kCarts and the 12 keys).
  for (int k = 0; k < 10; ++k) {
    EXPECT_NE(result.err.find(path + ":" + std::to_string(24 + k) + ":2: table" +
                              std::to_string(k) + ": "),
              std::string::npos)
        << k << result.err;
  }
  EXPECT_EQ(result.err.find("table10:"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find(path + ": 1990 more problems of this kind, not listed: unknown key"),
            std::string::npos)
      << result.err;
  EXPECT_NE(result.err.find(path + ": 2 more problems of this kind, not listed: unknown key"),
            std::string::npos)
      << result.err;
}

TEST_F(SceneCliTest, EveryPresetShowsAsAFileThatChecksAndMatches) {
  for (const scene::PresetInfo& preset : scene::presetList()) {
    SCOPED_TRACE(preset.name);
    const CliResult shown = run({"presets", "show", preset.name});
    ASSERT_EQ(shown.exit_code, 0) << shown.err;
    const std::string path = write(preset.name + ".toml", shown.out);
    const CliResult checked = run({"check", path});
    EXPECT_EQ(checked.exit_code, 0) << checked.err << shown.out;
    // The file renders the same numbers as the preset.
    const CliResult from_file = run({"data", path, "--json", "-"});
    const CliResult from_preset = run({"data", preset.name, "--json", "-"});
    EXPECT_EQ(from_file.exit_code, 0) << from_file.err;
    EXPECT_EQ(from_file.out, from_preset.out);
  }
  EXPECT_EQ(run({"presets", "show", "nope"}).exit_code, 2);
}

TEST_F(SceneCliTest, OverridesReachThePhysics) {
  // Elastic equal carts exchange velocities: no energy lost.
  const CliResult elastic =
      run({"data", "worked-example", "--set", "restitution=1", "--json", "-"});
  ASSERT_EQ(elastic.exit_code, 0) << elastic.err;
  EXPECT_EQ(nlohmann::json::parse(elastic.out).at("energy_lost").get<double>(), 0.0) << elastic.out;
  // Galperin's blocks with 4 digits collide 3141 times.
  const CliResult pi = run({"data", "pi-blocks", "--set", "digits=4", "--json", "-"});
  ASSERT_EQ(pi.exit_code, 0) << pi.err;
  EXPECT_EQ(nlohmann::json::parse(pi.out).at("collision_count"), 3141) << pi.out;
  // Shortcuts: 2 kg at 3 m/s onto 1 kg at rest, e = 0: together at 2 m/s.
  const CliResult merged = run(
      {"data", "worked-example", "--m1", "2", "--v1", "3", "--v2", "0", "--e", "0", "--json", "-"});
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  const nlohmann::json bodies = nlohmann::json::parse(merged.out).at("bodies");
  ASSERT_EQ(bodies.size(), 2u) << merged.out;
  for (const nlohmann::json& body : bodies) {
    EXPECT_NEAR(body.at("final_velocity")[0].get<double>(), 2.0, 1e-14) << merged.out;
    EXPECT_EQ(body.at("final_velocity")[1].get<double>(), 0.0) << merged.out;
  }
}

TEST_F(SceneCliTest, HelpShowsTheNewCommandsAndOptions) {
  EXPECT_NE(run({"check", "--help"}).out.find("FILE:LINE:COLUMN"), std::string::npos);
  EXPECT_NE(run({"presets", "show", "--help"}).out.find("Examples"), std::string::npos);
  EXPECT_NE(run({"batch", "--help"}).out.find("--shard"), std::string::npos);
  const std::string render_help = run({"render", "--help"}).out;
  for (const char* option : {"--set", "--m1", "--v2", "--theta1", "--e"}) {
    EXPECT_NE(render_help.find(option), std::string::npos) << option;
  }
}

}  // namespace
}  // namespace collide
