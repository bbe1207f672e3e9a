// One CLI: every command's --help lists what it works on and where the result goes before the
// finer options, and every command takes -q/--quiet. In-process.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace collide {
namespace {

// Where `name` (an option as --help writes it, e.g. "-o,--output") first appears in `help`;
// fails the test when it is missing.
std::size_t placeOf(const std::string& help, const std::string& name) {
  // Appended, not "  " + name: GCC 12 warns falsely (-Wrestrict) on a literal plus a string.
  std::string entry = "  ";
  entry.append(name).append(" ");
  const std::size_t at = help.find(entry);
  EXPECT_NE(at, std::string::npos) << "'" << name << "' missing from:\n" << help;
  return at;
}

struct HelpOrder {
  const char* command;
  std::vector<std::string> first;  // in this order, before `later`
  std::vector<std::string> later;
};

TEST(CliHelpTest, EveryCommandListsTheSceneTheOutputAndTheMainOptionsFirst) {
  const std::vector<std::string> changes = {"--duration", "--set"};
  const std::vector<std::string> styling = {"--theme", "--font", "--backend"};
  std::vector<std::string> picture_later = changes;
  picture_later.insert(picture_later.end(), styling.begin(), styling.end());
  // layout draws nothing, so it has no --backend.
  std::vector<std::string> picture_later_no_backend = changes;
  picture_later_no_backend.insert(picture_later_no_backend.end(), {"--theme", "--font"});
  const std::vector<HelpOrder> orders = {
      {"render", {"SCENE", "-o,--output", "--size", "--fps"}, picture_later},
      {"still", {"SCENE", "-o,--output", "--size", "--at"}, picture_later},
      {"strobe", {"SCENE", "-o,--output", "--size", "--rate"}, picture_later},
      {"chart", {"SCENE", "-o,--output", "--size"}, picture_later},
      {"lesson", {"SCENE", "-o,--output", "--size", "--fps"}, picture_later},
      {"data", {"SCENE", "--json", "--csv"}, changes},
      {"layout", {"SCENE", "--json", "--at", "--fps", "--size"}, picture_later_no_backend},
      {"solve", {"SCENE", "--impact", "--format"}, changes},
      {"check", {"SCENE"}, {"--set"}},
      {"batch", {"SCENE", "-o,--output", "--formats"}, {"--sweep", "--duration"}},
  };
  for (const HelpOrder& order : orders) {
    SCOPED_TRACE(order.command);
    const test::CliResult result = test::run({order.command, "--help"});
    ASSERT_EQ(result.exit_code, 0) << result.err;
    std::size_t previous = 0;
    for (const std::string& name : order.first) {
      const std::size_t at = placeOf(result.out, name);
      EXPECT_GT(at, previous) << name << " is listed too early";
      previous = at;
    }
    for (const std::string& name : order.later) {
      EXPECT_GT(placeOf(result.out, name), previous) << name << " is listed before the main ones";
    }
  }
}

TEST(CliHelpTest, EveryCommandTakesQuiet) {
  for (const char* command : {"render", "still", "strobe", "chart", "lesson", "data", "layout",
                              "solve", "check", "batch", "presets", "info"}) {
    SCOPED_TRACE(command);
    const test::CliResult help = test::run({command, "--help"});
    ASSERT_EQ(help.exit_code, 0) << help.err;
    placeOf(help.out, "-q,--quiet");
  }
  // And it parses: a quiet check prints its result and no note.
  const test::CliResult quiet = test::run({"check", "worked-example", "-q"});
  EXPECT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_TRUE(quiet.err.empty()) << quiet.err;
  const test::CliResult presets = test::run({"presets", "--quiet"});
  EXPECT_EQ(presets.exit_code, 0) << presets.err;
}

TEST(CliHelpTest, AnUnknownCommandNamesTheClosestAndListsThemAll) {
  const test::CliResult result = test::run({"rendr", "worked-example"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err,
            "collide: 'rendr': unknown command; did you mean 'render'?; allowed: render, still, "
            "strobe, chart, lesson, data, layout, solve, presets, check, batch, info\n");
  EXPECT_TRUE(result.out.empty());
}

}  // namespace
}  // namespace collide
