// A readout wrapped into a narrow column (text::wrapText) keeps each of its parts whole where that
// part fits a line, even when another part must break: measured here with a width of one unit per
// character, so every expected line follows from counting characters.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "text/most_lines.hpp"
#include "text/text_wrap.hpp"

namespace collide::text {
namespace {

// One unit per character (UTF-8 code point) at size 1: "Σp" is 2 wide.
double charactersWide(std::string_view text, double size_px) {
  double count = 0.0;
  for (const char c : text) {
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) count += 1.0;
  }
  return count * size_px;
}

constexpr std::string_view kCollisions = "collisions: 32, last e = 0.8";    // 28 wide
constexpr std::string_view kMomentumStart = "Σp: start (1.36, 0) kg·m/s,";  // 27 wide
constexpr std::string_view kMomentumNow = "now (0.247, −0.587) kg·m/s";     // 26 wide

std::string readout() {
  return std::string(kCollisions) + "   " + std::string(kMomentumStart) + " " +
         std::string(kMomentumNow);
}

TEST(ReadoutWrapTest, AClauseThatFitsALineStaysWholeWhenTheNextOneMustBreak) {
  // 30 wide: the collisions clause (28) fits; the momentum clause (54) does not, so it breaks at
  // its comma outside the brackets, each half (27, 26) on a line of its own.
  const std::vector<std::string> lines = wrapText(readout(), 1.0, 30.0, charactersWide);
  const std::vector<std::string> expected{std::string(kCollisions), std::string(kMomentumStart),
                                          std::string(kMomentumNow)};
  EXPECT_EQ(lines, expected);
}

TEST(ReadoutWrapTest, AClauseWiderThanALineBreaksAtItsOwnCommaNotAcrossTheNextClause) {
  // 27 wide: the collisions clause (28) breaks at its comma ("collisions: 32," 15, "last e = 0.8"
  // 12; together with a space 28); the momentum clause starts a line of its own, so "e = 0.8"
  // never shares a line with "Σp" (which read as "last" belonging to nothing).
  const std::vector<std::string> lines = wrapText(readout(), 1.0, 27.0, charactersWide);
  const std::vector<std::string> expected{"collisions: 32,", "last e = 0.8",
                                          std::string(kMomentumStart), std::string(kMomentumNow)};
  EXPECT_EQ(lines, expected);
}

// The words of `text` in order (split at spaces, however many).
std::vector<std::string> wordsOf(const std::vector<std::string>& lines) {
  std::vector<std::string> words;
  for (const std::string& line : lines) {
    std::size_t start = 0;
    while (start < line.size()) {
      const std::size_t end = std::min(line.find(' ', start), line.size());
      if (end > start) words.push_back(line.substr(start, end - start));
      start = end + 1;
    }
  }
  return words;
}

TEST(ReadoutWrapTest, ACommaInsideBracketsIsNeverWhereAClauseBreaksAndNothingIsLost) {
  // 20 wide: "Σp: start (1.36, 0) kg·m/s," (27) is wider than a line, so it breaks at spaces; the
  // pair of coordinates "(1.36, 0)" (9) stays on one line.
  const std::vector<std::string> lines = wrapText(readout(), 1.0, 20.0, charactersWide);
  for (const std::string& line : lines) {
    EXPECT_LE(charactersWide(line, 1.0), 20.0) << line;
    EXPECT_FALSE(line.ends_with("(1.36,")) << line;
  }
  EXPECT_EQ(wordsOf(lines), wordsOf({readout()}));
}

TEST(ReadoutWrapTest, ClausesThatAllFitShareLinesAsBefore) {
  // 9 wide: "a b" (3) + gap (3) + "c d" (3) = 9 fits, another gap and "e f" do not.
  const std::vector<std::string> wide = wrapText("a b   c d   e f", 1.0, 9.0, charactersWide);
  EXPECT_EQ(wide, (std::vector<std::string>{"a b   c d", "e f"}));
  // "a b;" (4) + " " + "c d;" (4) = 9: the semicolon stays with what it ends.
  const std::vector<std::string> semi = wrapText("a b; c d; e f", 1.0, 9.0, charactersWide);
  EXPECT_EQ(semi, (std::vector<std::string>{"a b; c d;", "e f"}));
}

TEST(ReadoutWrapTest, ATextWithoutClausesBreaksAtItsCommasFirst) {
  // "m = 1.00 kg, v = +2.00 m/s" (26) in 16: the comma's halves (12, 13), each on a line.
  const std::vector<std::string> lines =
      wrapText("m = 1.00 kg, v = +2.00 m/s", 1.0, 16.0, charactersWide);
  EXPECT_EQ(lines, (std::vector<std::string>{"m = 1.00 kg,", "v = +2.00 m/s"}));
}

TEST(ReadoutWrapTest, ASpeedKeepsItsDirection) {
  // "a v = 1.98 m/s, 2°" (18) in 16: "v = 1.98 m/s, 2°" (16) is one quantity, a speed and its
  // direction, so the line breaks before it, not after "m/s," with "2°" alone below.
  EXPECT_EQ(wrapText("a v = 1.98 m/s, 2°", 1.0, 16.0, charactersWide),
            (std::vector<std::string>{"a", "v = 1.98 m/s, 2°"}));
  // Only where the two are wider than a line does the direction go on the next.
  EXPECT_EQ(wrapText("v = 1.98 m/s, 2°", 1.0, 15.0, charactersWide),
            (std::vector<std::string>{"v = 1.98 m/s,", "2°"}));
}

TEST(ReadoutWrapTest, AVectorKeepsItsUnitWhereALineHoldsBoth) {
  // "Σp: now (0.225, 0.0202) kg·m/s" (30) in 24: "(0.225, 0.0202) kg·m/s" (22) fits a line, so
  // the break comes before the vector ("Σp: now" 7), never between it and its unit, though
  // "Σp: now (0.225, 0.0202)" (23) would fit the first line.
  EXPECT_EQ(wrapText("Σp: now (0.225, 0.0202) kg·m/s", 1.0, 24.0, charactersWide),
            (std::vector<std::string>{"Σp: now", "(0.225, 0.0202) kg·m/s"}));
}

TEST(MostLinesTest, TheMostAnyTextTakesCountedOncePerSizeAndWidth) {
  // In 4 wide, "aaaa aaaa" (9) takes two lines of four, "b b b b b" (9) three: "b b", "b b", "b".
  int measured = 0;
  const TextWidth counting = [&measured](std::string_view text, double size_px) {
    ++measured;
    return charactersWide(text, size_px);
  };
  const MostLines most({"aaaa aaaa", "b b b b b"});
  EXPECT_EQ(most.captionLines(1.0, 4.0, 0.0, counting), 3u);
  EXPECT_GT(measured, 0);
  // Asked again at the same size and width (a video's next frame), nothing is measured.
  const int first = measured;
  EXPECT_EQ(most.captionLines(1.0, 4.0, 0.0, counting), 3u);
  EXPECT_EQ(measured, first);
  // In 9 wide each takes one line; another width is counted anew.
  EXPECT_EQ(most.captionLines(1.0, 9.0, 0.0, counting), 1u);
  EXPECT_GT(measured, first);
}

TEST(ReadoutWrapTest, AUnitKeepsItsVectorsLastComponentWhereTheyAreWiderThanALine) {
  // "Σp: now (0.229, −0.00567) kg·m/s" (32) in 18: the vector and its unit (24) are wider than a
  // line. The vector alone (17) fits one, but under it "kg·m/s" (6) would stand alone; parted
  // inside the vector, the unit keeps its last component ("−0.00567) kg·m/s", 16) and "(0.229,"
  // (7) ends the first line ("Σp: now (0.229,", 15).
  EXPECT_EQ(wrapText("Σp: now (0.229, −0.00567) kg·m/s", 1.0, 18.0, charactersWide),
            (std::vector<std::string>{"Σp: now (0.229,", "−0.00567) kg·m/s"}));
  // In 14 the last component and the unit (16) are wider than a line: they part there, and the
  // rest as before ("(0.229," 7, "−0.00567)" 9, "kg·m/s" 6).
  EXPECT_EQ(wrapText("Σp: now (0.229, −0.00567) kg·m/s", 1.0, 14.0, charactersWide),
            (std::vector<std::string>{"Σp: now", "(0.229,", "−0.00567)", "kg·m/s"}));
}

}  // namespace
}  // namespace collide::text
