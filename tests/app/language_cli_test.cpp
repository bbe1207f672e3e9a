// --lang and the scene key `lang`: an unknown language is exit 2 listing the shipped ones, before
// anything is written; a preset shown in a language carries its words and its `lang`.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "scratch.hpp"
#include "text/language.hpp"

namespace collide {
namespace {

namespace fs = std::filesystem;
using test::run;

TEST(LanguageCliTest, AnUnknownLanguageIsExitTwoListingTheShippedOnes) {
  const test::ScratchDir dir("collide_lang_cli_");
  const std::string shipped = text::shippedLanguageList();
  for (const std::vector<std::string>& command :
       std::vector<std::vector<std::string>>{{"still", "worked-example", "-o", dir.file("a.png")},
                                             {"render", "worked-example", "-o", dir.file("a.mp4")},
                                             {"strobe", "worked-example", "-o", dir.file("b.png")},
                                             {"chart", "worked-example", "-o", dir.file("c.png")},
                                             {"presets"}}) {
    std::vector<std::string> args = command;
    args.insert(args.end(), {"--lang", "xx-YY"});
    const test::CliResult r = run(args);
    EXPECT_EQ(r.exit_code, 2) << command[0];
    EXPECT_EQ(r.err, "collide: --lang 'xx-YY': not a shipped language; shipped languages: " +
                         shipped + "\n")
        << command[0];
  }
  EXPECT_TRUE(fs::is_empty(dir.path()));
  EXPECT_NE(shipped.find("de (Deutsch)"), std::string::npos);
}

TEST(LanguageCliTest, ASceneFileNamesItsLanguageOrIsRefusedWithTheShippedOnes) {
  const test::ScratchDir dir("collide_lang_scene_");
  const std::string scene = dir.file("s.toml");
  std::ofstream(scene) << "lang = \"klingon\"\n[[body]]\nmass = 1\nvelocity = 1\n";
  const test::CliResult bad = run({"still", scene, "-o", dir.file("s.png")});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("s.toml:1:8: lang: \"klingon\": not a shipped language; allowed: " +
                         text::shippedLanguageList()),
            std::string::npos)
      << bad.err;
  EXPECT_FALSE(fs::exists(dir.file("s.png")));
}

TEST(LanguageCliTest, PresetsAreListedAndShownInTheLanguage) {
  const test::CliResult english = run({"presets"});
  const test::CliResult german = run({"presets", "--lang", "de"});
  ASSERT_EQ(german.exit_code, 0) << german.err;
  EXPECT_NE(english.out.find("(the default)"), std::string::npos);
  EXPECT_NE(german.out.find("(die Voreinstellung)"), std::string::npos) << german.out;

  const test::CliResult shown = run({"presets", "show", "worked-example", "--lang", "de"});
  ASSERT_EQ(shown.exit_code, 0) << shown.err;
  EXPECT_NE(shown.out.find("lang = \"de\""), std::string::npos) << shown.out;
  EXPECT_NE(shown.out.find("title = \"Unelastischer Stoß, e = {restitution}\""), std::string::npos)
      << shown.out;
  EXPECT_NE(shown.out.find("name = \"Wagen 1\""), std::string::npos) << shown.out;
  // Without --lang the preset names no language, and its words are English again.
  const test::CliResult again = run({"presets", "show", "worked-example"});
  EXPECT_EQ(again.out.find("lang ="), std::string::npos);
  EXPECT_NE(again.out.find("name = \"cart 1\""), std::string::npos) << again.out;
}

// A run's --lang is that run's: the next run in the same process, and code that draws without
// the command line, write in the language that was active before it.
TEST(LanguageCliTest, ARunsLanguageEndsWithTheRun) {
  const test::ScratchDir dir("collide_lang_scope_");
  const std::string before = text::activeLanguage().tag;
  ASSERT_NE(before, "ar");
  const test::CliResult r =
      run({"still", "worked-example", "--lang", "ar", "--size", "160x90", "-o", dir.file("a.png")});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(text::activeLanguage().tag, before);
}

}  // namespace
}  // namespace collide
