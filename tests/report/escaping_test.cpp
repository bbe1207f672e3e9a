// SPDX-License-Identifier: MIT
// Issue 38: text reaches every format escaped for it, whatever it holds (the scene loader refuses
// control characters, but alt text has line breaks of its own and file names are bytes): JSON
// stays valid and reads back the same, a LaTeX snippet's comments cannot end early and nothing in
// its caption is a command, a Markdown image stays one line. And issue 45: a table's size is known
// before anything is simulated.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "physics/simulate.hpp"
#include "report/csv_table.hpp"
#include "report/figure_bundle.hpp"
#include "report/json_writer.hpp"
#include "report_test_scenes.hpp"

namespace collide::report {
namespace {

// Every kind of text a value may hold: quotes, backslashes, each line end, ESC and BEL, a C1
// control, the JavaScript line separators, an astral character.
const std::string kAwkward =
    "q\"b\\s/n\nr\rt\te\x1b]0;x\x07 c1\xC2\x9B ls\xE2\x80\xA8 ps\xE2\x80\xA9 \xF0\x9F\x98\x80";

const std::string kLineSeparator = "\u2028";

TEST(EscapingTest, JsonStringsReadBackAsWritten) {
  const std::string quoted = jsonQuoted(kAwkward);
  EXPECT_EQ(quoted.find('\n'), std::string::npos);
  EXPECT_EQ(quoted.find('\x1b'), std::string::npos);
  EXPECT_EQ(quoted.find(kLineSeparator), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(quoted).get<std::string>(), kAwkward);
  std::size_t used = 0;
  const std::optional<std::string> back = jsonUnquoted(quoted + " rest", used);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(*back, kAwkward);
  EXPECT_EQ(used, quoted.size());
}

TEST(EscapingTest, BytesThatAreNotUtf8StillMakeValidJson) {
  const std::string quoted = jsonQuoted(
      "a\xFF"
      "b\xC0");
  EXPECT_EQ(nlohmann::json::parse(quoted).get<std::string>(),
            "a\xEF\xBF\xBD"
            "b\xEF\xBF\xBD");
}

TEST(EscapingTest, JsonUnquotedRefusesWhatIsNoWholeString) {
  std::size_t used = 0;
  for (const std::string bad : {"x", "\"open", "\"a\nb\"", "\"\\q\"", "\"\\ud800\"", "\"\\u12\""}) {
    EXPECT_FALSE(jsonUnquoted(bad, used).has_value()) << bad;
  }
  const std::optional<std::string> pair = jsonUnquoted("\"\\ud83d\\ude00\"", used);
  ASSERT_TRUE(pair.has_value());
  EXPECT_EQ(*pair, "\xF0\x9F\x98\x80");
}

FigureBundle awkwardBundle() {
  return {"dir/fig.png",
          "Caption " + kAwkward + " 50% #1 $x$ {y} \\input{/etc/passwd} ~^&_",
          "Alt " + kAwkward + "\nsecond line \\input{/etc/passwd}",
          std::nullopt,
          "",
          ""};
}

TEST(EscapingTest, LatexCommentsCannotEndAndTheCaptionHasNoCommand) {
  const std::string tex = latexFigure(awkwardBundle());
  EXPECT_EQ(tex.find('\r'), std::string::npos);
  EXPECT_EQ(tex.find('\x1b'), std::string::npos);
  EXPECT_EQ(tex.find('\x07'), std::string::npos);
  std::istringstream lines(tex);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("%", 0) == 0) continue;  // a comment: the alt text, the header
    // Outside comments, the only commands are the figure's own.
    for (std::size_t at = line.find('\\'); at != std::string::npos; at = line.find('\\', at + 1)) {
      const std::string rest = line.substr(at);
      const bool own =
          rest.rfind("\\begin{figure}", 0) == 0 || rest.rfind("\\end{figure}", 0) == 0 ||
          rest.rfind("\\centering", 0) == 0 || rest.rfind("\\includegraphics", 0) == 0 ||
          rest.rfind("\\caption{", 0) == 0 || rest.rfind("\\label{", 0) == 0 ||
          rest.rfind("\\linewidth", 0) == 0 || rest.rfind("\\textbackslash{}", 0) == 0 ||
          rest.rfind("\\textasciitilde{}", 0) == 0 || rest.rfind("\\textasciicircum{}", 0) == 0 ||
          (rest.size() > 1 && std::string("{}$&%#_").find(rest[1]) != std::string::npos);
      EXPECT_TRUE(own) << "a command from the text: " << line;
    }
  }
  EXPECT_NE(tex.find("\\textbackslash{}input\\{/etc/passwd\\}"), std::string::npos) << tex;
}

TEST(EscapingTest, MarkdownImageIsOneLine) {
  const std::string md = markdownFigure(awkwardBundle());
  EXPECT_EQ(md.find('\n'), md.size() - 1) << md;
  EXPECT_EQ(md.find('\r'), std::string::npos);
  EXPECT_EQ(md.find('\x1b'), std::string::npos);
  EXPECT_EQ(md.find(kLineSeparator), std::string::npos);
  EXPECT_EQ(md.rfind("![", 0), 0u) << md;
  EXPECT_NE(md.find("](fig.png \""), std::string::npos) << md;
}

TEST(EscapingTest, LatexNamesOnlyFilesItCanRead) {
  EXPECT_TRUE(latexNamesFile("out/fig-1_a.b.pdf"));
  for (const std::string bad : {"a}b.pdf", "a%b.pdf", "a#b.pdf", "a\\b.pdf", "a\rb.pdf"}) {
    EXPECT_FALSE(latexNamesFile(bad)) << bad;
  }
}

// The size estimate counts what the table will hold: one row per step and the duration (closed
// form: floor(duration / step) + 1), as many columns as its header names.
TEST(EscapingTest, CsvSizeIsKnownBeforeTheSimulation) {
  const physics::WorldDef world = test::twoBlocks(0.5, 3.0);
  const CsvSize size = estimateCsvSize(world.dimensions, world.bodies.size(), 3.0, 0.01);
  EXPECT_EQ(size.rows, 301);
  const physics::Timeline timeline = physics::simulate(world);
  const std::string header = csvBooksHeader(timeline);  // version 2, the default
  EXPECT_EQ(size.columns, std::count(header.begin(), header.end(), ',') + 1);
  const std::string header_v1 = csvHeader(world);
  EXPECT_EQ(estimateCsvSize(world.dimensions, world.bodies.size(), 3.0, 0.01, false, 1).columns,
            std::count(header_v1.begin(), header_v1.end(), ',') + 1);
  std::ostringstream table;
  writeCsv(table, timeline, 0.01);
  const std::string text = table.str();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), size.rows + 1);  // and the header
  // The bytes are an estimate from above, for refusing requests of terabytes: never less than what
  // is written (blocks at rest have short fields: "0", "1.5"), and no more than a field of a
  // double's longest shortest form ("-1.2345678901234567e-100", 24 characters) and its comma.
  EXPECT_GE(size.bytes, static_cast<double>(text.size()));
  EXPECT_LE(size.bytes, 25.0 * static_cast<double>(size.rows * size.columns));
}

}  // namespace
}  // namespace collide::report
