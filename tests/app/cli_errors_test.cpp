// SPDX-License-Identifier: MIT
// The command-line parser's mistakes in collide's words (app/cli_errors.hpp), in-process: each
// is exit 2 and one line naming what was typed, what is wrong and what is allowed, none in the
// parser's own phrasing; the scene options of the picture commands taken alike by data and
// check, the drawing ones refused naming the commands that take them.
#include "app/cli_errors.hpp"

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace collide {
namespace {

using test::CliResult;
using test::run;

// Phrases CLI11 2.1 writes; none may reach the user.
const char* const kParserPhrases[] = {"not expected",
                                      "required but received",
                                      "Could not convert",
                                      "is required",
                                      "A subcommand",
                                      "missing (run",
                                      "run 'collide --help'",
                                      "Expected exactly",
                                      "At Most",
                                      "At least",
                                      "excludes",
                                      "requires",
                                      "not an allowed value"};

struct Mistake {
  std::vector<std::string> args;
  std::vector<std::string> said;  // each in the line
};

void expectCollidesWords(const Mistake& mistake) {
  std::string typed;
  for (const std::string& arg : mistake.args) typed += arg + " ";
  SCOPED_TRACE(typed);
  const CliResult result = run(mistake.args);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_TRUE(result.out.empty()) << result.out;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_EQ(result.err.rfind("collide: ", 0), 0u) << result.err;
  EXPECT_NE(result.err.find("allowed: "), std::string::npos) << result.err;
  for (const std::string& words : mistake.said) {
    EXPECT_NE(result.err.find(words), std::string::npos) << words << " in " << result.err;
  }
  for (const char* phrase : kParserPhrases) {
    EXPECT_EQ(result.err.find(phrase), std::string::npos) << phrase << " in " << result.err;
  }
}

TEST(CliErrorsTest, EveryParserMistakeIsOneLineInCollidesWords) {
  const std::vector<Mistake> mistakes = {
      // An option another command has: which ones take it, and what this one takes.
      {{"data", "worked-example", "--csv", "-", "--theme", "dark"},
       {"'--theme': not an option of 'collide data'", "still", "--csv"}},
      {{"batch", "worked-example", "-o", "out", "--lang", "de"}, {"'--lang'", "'--langs'"}},
      {{"still", "worked-example", "-o", "a.png", "--sizee", "3x3"}, {"'--sizee'", "'--size'"}},
      {{"info", "--foo"}, {"'--foo'", "'collide info'"}},
      {{"--bogus"}, {"'--bogus'", "render, still"}},
      {{}, {"no command given", "render, still"}},
      // One argument too many.
      {{"still", "worked-example", "-o", "a.png", "extra"}, {"'extra'", "'worked-example'"}},
      {{"presets", "extra"}, {"'extra'", "'collide presets' takes no arguments"}},
      // A value missing, or not of the option's kind.
      {{"data", "worked-example", "--csv"}, {"--csv: no value after it", "output path"}},
      {{"still", "worked-example", "-o", "a.png", "--at"}, {"--at: no value"}},
      {{"data", "worked-example", "--csv", "-", "--dt", "abc"},
       {"--dt: 'abc' is not a number", "0.0005 to 0.05"}},
      {{"render", "worked-example", "-o", "a.mp4", "--fps", "1.5x"},
       {"--fps: '1.5x' is not a whole number", "1 to 240"}},
      // Given twice, or a value for a flag.
      {{"still", "worked-example", "-o", "a.png", "--m1", "1", "--m1", "2"},
       {"--m1: given 2 times", "once"}},
      {{"render", "worked-example", "-o", "a.mp4", "-q=3"}, {"'-q=3'", "-q takes no value"}},
      // What must be there, named as --help names it.
      {{"still", "worked-example"}, {"'collide still': -o/--output is missing", "Output path"}},
      {{"data"}, {"'collide data': SCENE is missing", "Preset name"}},
      {{"presets", "show"}, {"'collide presets show': NAME is missing"}},
  };
  for (const Mistake& mistake : mistakes) expectCollidesWords(mistake);
}

// No command of collide ties options together with the parser's needs/excludes yet; a command
// line of its own shows those errors put in collide's words too.
std::string explained(CLI::App& root, std::vector<std::string> args) {
  std::vector<const char*> argv = {"collide"};
  for (const std::string& arg : args) argv.push_back(arg.c_str());
  try {
    root.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError& e) {
    return app::explainParseError(e, root, args);
  }
  return "";
}

TEST(CliErrorsTest, NeedsAndExcludesNameBothOptionsAsTyped) {
  CLI::App root{"test", "collide"};
  CLI::App* demo = root.add_subcommand("demo", "a command");
  demo->group("Commands");
  std::string a, b, c;
  CLI::Option* first = demo->add_option("-a,--alpha", a, "first");
  CLI::Option* second = demo->add_option("--beta", b, "second");
  CLI::Option* third = demo->add_option("--gamma", c, "third");
  first->needs(second);
  third->excludes(second);
  EXPECT_EQ(explained(root, {"demo", "-a", "1"}),
            "-a: needs --beta; allowed: see 'collide demo --help'");
  CLI::App again{"test", "collide"};
  CLI::App* other = again.add_subcommand("demo", "a command");
  other->group("Commands");
  CLI::Option* b2 = other->add_option("--beta", b, "second");
  other->add_option("--gamma", c, "third")->excludes(b2);
  // The parser ties the two both ways and names either first.
  const std::string both = explained(again, {"demo", "--beta", "1", "--gamma", "2"});
  EXPECT_TRUE(both == "--gamma: cannot go with --beta; allowed: see 'collide demo --help'" ||
              both == "--beta: cannot go with --gamma; allowed: see 'collide demo --help'")
      << both;
}

TEST(CliErrorsTest, DataAndCheckTakeTheSceneOptionsOfThePictureCommands) {
  // --lang on data is checked and changes nothing: the numbers are the same in every language.
  const CliResult plain = run({"data", "worked-example", "--csv", "-", "--dt", "0.05"});
  const CliResult german =
      run({"data", "worked-example", "--csv", "-", "--dt", "0.05", "--lang", "de"});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  ASSERT_EQ(german.exit_code, 0) << german.err;
  EXPECT_EQ(german.out, plain.out);
  EXPECT_TRUE(german.err.empty()) << german.err;
  const CliResult unknown = run({"data", "worked-example", "--csv", "-", "--lang", "xx"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("--lang 'xx'"), std::string::npos) << unknown.err;
  // check reads the scene in the language and with the duration asked for.
  const CliResult check = run({"check", "worked-example", "--lang", "de", "--duration", "3"});
  ASSERT_EQ(check.exit_code, 0) << check.err;
  EXPECT_NE(check.out.find("'Unelastischer Stoß, e = 0,5'"), std::string::npos) << check.out;
  EXPECT_NE(check.out.find(", 3 s"), std::string::npos) << check.out;
  EXPECT_EQ(run({"check", "worked-example", "--duration", "-3"}).exit_code, 2);
}

}  // namespace
}  // namespace collide
