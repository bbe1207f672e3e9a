// collide(1): the roff escaping (text from --help must reach man(1) as text, never as requests,
// and options must read and copy as ASCII hyphen-minus) and `collide help-man` run in-process, so
// the page generator also runs under the sanitizers.
#include "app/man_page.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace collide::app {
namespace {

TEST(RoffEscapeTest, HyphensBecomeMinusSigns) {
  EXPECT_EQ(roffEscape("--set body.2.mass=3"), "\\-\\-set body.2.mass=3");
}

TEST(RoffEscapeTest, BackslashesArePrintedNotInterpreted) {
  EXPECT_EQ(roffEscape("C:\\fonts\\a.ttf"), "C:\\efonts\\ea.ttf");
}

TEST(RoffEscapeTest, ALineStartingWithAControlCharacterStaysText) {
  EXPECT_EQ(roffEscape(".toml files"), "\\&.toml files");
  EXPECT_EQ(roffEscape("'quoted'"), "\\&'quoted'");
  EXPECT_EQ(roffEscape("a\n.b\nc.d"), "a\n\\&.b\nc.d");
}

TEST(RoffEscapeTest, PlainTextIsUnchanged) {
  EXPECT_EQ(roffEscape("Render one instant"), "Render one instant");
}

// The commands `collide --help` lists, read from its "Subcommands:" block.
std::vector<std::string> listedCommands() {
  std::istringstream help(test::run({"--help"}).out);
  std::vector<std::string> commands;
  bool listing = false;
  for (std::string line; std::getline(help, line);) {
    if (line == "Subcommands:") {
      listing = true;
    } else if (line.empty()) {
      listing = false;
    } else if (listing && line.rfind("  ", 0) == 0) {
      commands.push_back(line.substr(2, line.find(' ', 2) - 2));
    }
  }
  return commands;
}

TEST(ManPageCliTest, HelpManPrintsAPageWithASectionPerListedCommand) {
  const test::CliResult result = test::run({"help-man"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(result.out.rfind(".\\\"", 0), 0u) << "starts with a roff comment";
  EXPECT_NE(result.out.find("\n.TH COLLIDE 1 "), std::string::npos);
  for (const char* section :
       {"NAME", "SYNOPSIS", "DESCRIPTION", "OPTIONS", "COMMANDS", "EXIT STATUS"}) {
    EXPECT_NE(result.out.find(std::string("\n.SH ") + section + "\n"), std::string::npos)
        << section;
  }
  const std::vector<std::string> commands = listedCommands();
  ASSERT_GE(commands.size(), 5u);
  for (const std::string& command : commands) {
    EXPECT_NE(result.out.find("\n.SS \"collide " + command + " "), std::string::npos) << command;
  }
  EXPECT_NE(result.out.find("\n.SS \"collide presets show "), std::string::npos)
      << "subcommands of commands get their own section";
  EXPECT_EQ(result.out.find("help\\-man"), std::string::npos) << "the hidden command stays hidden";
}

TEST(ManPageCliTest, HelpManIsHiddenFromHelp) {
  const std::vector<std::string> commands = listedCommands();
  EXPECT_EQ(std::count(commands.begin(), commands.end(), "help-man"), 0);
  EXPECT_EQ(std::count(commands.begin(), commands.end(), "render"), 1);
}

}  // namespace
}  // namespace collide::app
