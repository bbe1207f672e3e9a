// SPDX-License-Identifier: MIT
// Issue 38, item 4, through the real `collide` binary: text from a scene that reached past the
// tool, and valid requests with a wrong outcome.
//   - ESC and BEL in a scene never reach the terminal raw (check, data); control characters,
//     non-characters and bytes that are not UTF-8 are exit 2 at load, from a file or --set.
//   - A batch's protocol and manifest carry a title as a JSON string: quotes, backslashes and
//     words that look like report lines change nothing but the title.
//   - Batch stems are unique (a/x b/x c/x-2), `--` before a scene named like an option is kept
//     for the workers, TMPDIR naming no directory is exit 2 before any job, --print with 400
//     digits is exit 2, not an internal error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "faults_fixture.hpp"

namespace collide::faults_test {
namespace {

// A one-body 1D scene with `title` written into its TOML as given (escapes and all).
std::string sceneWithTitle(const std::string& title) {
  return "title = \"" + title + "\"\n[[body]]\nmass = 1\nsize = 0.5\nposition = 0\nvelocity = 1\n";
}

bool hasRawTerminalControl(const std::string& text) {
  return text.find('\x1b') != std::string::npos || text.find('\x07') != std::string::npos;
}

// ---- terminal escapes ------------------------------------------------------------------------

TEST_F(FaultsGLTest, EscapesInAScenesTitleNeverReachTheTerminal) {
  const fs::path scene = out_dir_() / "s.toml";
  writeText(scene, sceneWithTitle("\\u001b]0;owned\\u0007\\u001b[2J"));
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"check", scene.string()},
        std::vector<std::string>{"data", scene.string(), "--json", "-"}}) {
    const ChildResult result = collide(args);
    EXPECT_EQ(result.exit_code, 2) << test::describe(result) << ": " << result.err;
    EXPECT_FALSE(hasRawTerminalControl(result.out + result.err)) << result.err;
    EXPECT_NE(result.err.find("title: "), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("U+001B"), std::string::npos) << result.err;
  }
}

TEST_F(FaultsGLTest, EscapesThroughSetAndInAFileNameNeverReachTheTerminal) {
  const ChildResult set = collide({"check", "worked-example", "--set", "body.1.name=a\x1b[2J\x07"});
  EXPECT_EQ(set.exit_code, 2) << set.err;
  EXPECT_FALSE(hasRawTerminalControl(set.out + set.err)) << set.err;
  EXPECT_NE(set.err.find("body.1.name"), std::string::npos) << set.err;
  // A valid scene whose file name holds ESC and BEL: named, escaped, on stdout.
  const fs::path odd = out_dir_() / "x\x1b]0;t\x07.toml";
  writeText(odd, sceneWithTitle("plain"));
  const ChildResult named = collide({"check", odd.string()});
  EXPECT_EQ(named.exit_code, 0) << named.err;
  EXPECT_FALSE(hasRawTerminalControl(named.out + named.err)) << named.out;
  EXPECT_NE(named.out.find("\\x1B]0;t\\x07.toml"), std::string::npos) << named.out;
}

// ---- characters refused at load ----------------------------------------------------------------

TEST_F(FaultsGLTest, NonCharactersAndBadBytesAreExitTwoNamingTheKeyAndCodePoint) {
  struct Case {
    std::string typed;  // raw UTF-8 (or bytes) in --set title=...
    std::string named;  // what the message names
  };
  for (const Case& c : {Case{"\xEF\xBF\xBE", "U+FFFE"}, Case{"\xEF\xBF\xBF", "U+FFFF"},
                        Case{"\xEF\xB7\x90", "U+FDD0"}, Case{"\xF4\x8F\xBF\xBF", "U+10FFFF"},
                        Case{"\xC2\x85", "U+0085"}, Case{"\xFF", "not UTF-8"}}) {
    for (const std::string command : {"check", "still"}) {
      std::vector<std::string> args = {command, "worked-example", "--set", "title=A" + c.typed};
      if (command == std::string("still")) {
        args.insert(args.end(), {"--size", "64x64", "-o", (out_dir_() / "a.pdf").string()});
      }
      const ChildResult result = collide(args);
      EXPECT_EQ(result.exit_code, 2) << command << " " << c.named << ": " << result.err;
      EXPECT_NE(result.err.find("title"), std::string::npos) << result.err;
      EXPECT_NE(result.err.find(c.named), std::string::npos) << result.err;
      EXPECT_NE(result.err.find("allowed: "), std::string::npos) << result.err;
    }
  }
  EXPECT_TRUE(fs::is_empty(out_dir_()));
}

// ---- the batch protocol and manifest ------------------------------------------------------------

TEST_F(FaultsGLTest, ABatchTitleThatLooksLikeReportLinesChangesOnlyTheTitle) {
  const std::string title = "a \\\"q\\\" \\\\ output mp4 ../../etc/passwd parameter x y";
  const std::string expected = "a \"q\" \\ output mp4 ../../etc/passwd parameter x y";
  const fs::path scene = dir_ / "lesson.toml";
  writeText(scene, sceneWithTitle(title));
  const ChildResult result =
      collide({"batch", scene.string(), "--formats", "json", "-o", out_dir_().string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json manifest =
      nlohmann::json::parse(test::readFileBytes(out_dir_() / "manifest.json"));
  const nlohmann::json& job = manifest["jobs"][0];
  EXPECT_EQ(job["title"], expected);
  EXPECT_EQ(job["outputs"],
            nlohmann::json::parse(R"([{"format": "json", "path": "lesson.json"}])"));
  EXPECT_TRUE(job["parameters"].empty());
}

// ---- batch outcomes --------------------------------------------------------------------------

TEST_F(FaultsGLTest, ScenesOfOneStemInABatchWriteDistinctFiles) {
  for (const std::string folder : {"a", "b", "c"}) fs::create_directory(dir_ / folder);
  const std::vector<fs::path> scenes = {dir_ / "a" / "x.toml", dir_ / "b" / "x.toml",
                                        dir_ / "c" / "x-2.toml"};
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    writeText(scenes[i], sceneWithTitle("scene " + std::to_string(i)));
  }
  const ChildResult result =
      collide({"batch", scenes[0].string(), scenes[1].string(), scenes[2].string(), "--formats",
               "json", "-o", out_dir_().string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json manifest =
      nlohmann::json::parse(test::readFileBytes(out_dir_() / "manifest.json"));
  std::set<std::string> files;
  for (const nlohmann::json& job : manifest["jobs"]) {
    const std::string file = job["outputs"][0]["path"];
    EXPECT_TRUE(files.insert(file).second) << file << " written twice";
    // Each file holds its own job's scene.
    const nlohmann::json written = nlohmann::json::parse(test::readFileBytes(out_dir_() / file));
    EXPECT_EQ(written["scene"], job["name"]);
  }
  EXPECT_EQ(files.size(), 3u);
  EXPECT_EQ(manifest["jobs"][2]["stem"], "x-2") << "a scene keeps its own stem where it can";
}

// Values that start with '-' reach the workers as they were meant: a scene after "--", an output
// folder, a negative speed.
TEST_F(FaultsGLTest, ValuesNamedLikeOptionsReachTheWorkers) {
  writeText(dir_ / "-s.toml", sceneWithTitle("dash"));
  ChildOptions options;
  options.working_directory = dir_.string();
  const ChildResult result =
      collide({"batch", "-o", "-out", "--formats", "json", "--v1", "-3", "--", "-s.toml"}, options);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json summary =
      nlohmann::json::parse(test::readFileBytes(dir_ / "-out" / "-s.json"));
  EXPECT_EQ(summary["bodies"][0]["initial_velocity"][0], -3.0);
}

TEST_F(FaultsGLTest, ATmpdirThatIsNoDirectoryIsExitTwoBeforeAnyJob) {
  ChildOptions options;
  options.environment = {"TMPDIR=" + (dir_ / "missing").string()};
  const ChildResult result =
      collide({"batch", "worked-example", "--formats", "json", "-o", out_dir_().string()}, options);
  EXPECT_EQ(result.exit_code, 2) << test::describe(result) << ": " << result.err;
  EXPECT_EQ(result.err.rfind("collide: TMPDIR: ", 0), 0u) << result.err;
  EXPECT_EQ(result.err.find("internal error"), std::string::npos) << result.err;
  EXPECT_TRUE(fs::is_empty(out_dir_()));
}

// A batch refused before its first job takes back the -o folder it made: a bad TMPDIR (checked
// before the folder is made) and an output past the size rule (checked after).
TEST_F(FaultsGLTest, ARefusedBatchLeavesNoOutputFolderBehind) {
  const fs::path fresh = dir_ / "fresh";
  ChildOptions bad_tmpdir;
  bad_tmpdir.environment = {"TMPDIR=" + (dir_ / "missing").string()};
  const ChildResult tmpdir_result =
      collide({"batch", "worked-example", "--formats", "json", "-o", fresh.string()}, bad_tmpdir);
  EXPECT_EQ(tmpdir_result.exit_code, 2) << tmpdir_result.err;
  EXPECT_FALSE(fs::exists(fresh));
  const ChildResult oversized =
      collide({"batch", "worked-example", "--formats", "mp4", "--size", "7680x4320", "--fps", "240",
               "--set", "duration=3600", "-o", fresh.string()});
  EXPECT_EQ(oversized.exit_code, 2) << oversized.err;
  EXPECT_NE(oversized.err.find("more than the 10 GB"), std::string::npos) << oversized.err;
  EXPECT_FALSE(fs::exists(fresh));
}

// ---- numbers past a double's range -------------------------------------------------------------

TEST_F(FaultsGLTest, FourHundredDigitsAreExitTwoNotAnInternalError) {
  const std::string digits(400, '9');
  const std::string pdf = (out_dir_() / "a.pdf").string();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"still", "worked-example", "--print", digits + "cm", "-o", pdf},
        std::vector<std::string>{"still", "worked-example", "--print", "8cm@" + digits, "-o", pdf},
        std::vector<std::string>{"still", "worked-example", "--print", "0." + digits + "mm", "-o",
                                 pdf},
        std::vector<std::string>{"still", "worked-example", "--panels",
                                 "body." + digits + ".mass=1,2", "-o", pdf},
        std::vector<std::string>{"batch", "worked-example", "--sweep",
                                 "restitution=" + digits + ":1:0.5", "-o", out_dir_().string()}}) {
    const ChildResult result = collide(args);
    EXPECT_EQ(result.exit_code, 2) << args[2] << ": " << result.err;
    EXPECT_EQ(result.err.find("internal error"), std::string::npos) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  }
  EXPECT_TRUE(fs::is_empty(out_dir_()));
}

}  // namespace
}  // namespace collide::faults_test
