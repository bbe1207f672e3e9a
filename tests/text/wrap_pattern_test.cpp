// SPDX-License-Identifier: MIT
// Text wrapped like its shot's pattern (text/wrap_pattern.hpp), measured with a monospace width
// (one pixel a byte) so every expected break is counted by hand.
#include "text/wrap_pattern.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "text/text_wrap.hpp"

namespace collide::text {
namespace {

double monospace(std::string_view text, double /*size_px*/) {
  return static_cast<double>(text.size());
}

TEST(WrapPatternTest, WordsAreCountedBetweenSpaces) {
  EXPECT_EQ(wordCount("now (1, 2) kg"), 4u);
  EXPECT_EQ(wordCount("collisions: 4   p"), 5u);  // two empty words between three spaces
  EXPECT_EQ(wordCount(""), 1u);
}

TEST(WrapPatternTest, ThePatternKeepsEachWordAtItsWidest) {
  EXPECT_EQ(widerWords("v = 0 m/s, 1.5", "v = 0.25 m/s, 3", 10.0, monospace), "v = 0.25 m/s, 1.5");
  EXPECT_EQ(widerWords("", "v = 1", 10.0, monospace), "v = 1");
  EXPECT_EQ(widerWords("v = 1", "v = 1 m/s", 10.0, monospace), "");  // other words
}

TEST(WrapPatternTest, AVectorIsTakenWholeFromOneText) {
  // Components at their widest each, "(1.25, 2.75)", would be a vector neither text shows:
  // the wider vector is taken whole, "(1, 2.755)" (10) over "(1.25, 2)" (9).
  EXPECT_EQ(widerWords("p (1.25, 2) kg", "p (1, 2.755) kg", 10.0, monospace), "p (1, 2.755) kg");
  EXPECT_EQ(widerWords("p (1.25, 2) kg", "p (1, 2.75) kg", 10.0, monospace), "p (1.25, 2) kg");
}

TEST(WrapPatternTest, TheTextBreaksBeforeThePatternsWords) {
  // "now (0.00419, 0.00242) kg" in 13 px: "now (0.00419," | "0.00242) kg"; a frame showing
  // (0, 0) breaks before the same words, though it would fit on one line.
  const std::string pattern = "now (0.00419, 0.00242) kg";
  const std::vector<std::string> lines = wrapLike("now (0, 0) kg", pattern, 10.0, 13.0, monospace);
  const std::vector<std::string> expected =
      breakLike("now (0, 0) kg", pattern, wrapText(pattern, 10.0, 13.0, monospace)).value();
  EXPECT_EQ(lines, expected);
  EXPECT_EQ(lines.size(), wrapText(pattern, 10.0, 13.0, monospace).size());
  EXPECT_GT(lines.size(), wrapText("now (0, 0) kg", 10.0, 13.0, monospace).size());
}

TEST(WrapPatternTest, AChineseCommaEndsAWordAsASpaceDoes) {
  // "，" (3 bytes) closes up to the next word: "初始(2, 0) kg，当前(1, 2) kg" has the words
  // 初始(2, | 0) | kg， | 当前(1, | 2) | kg. A pattern broken after "，" maps onto a frame's
  // text, which breaks there too (ballistic-pendulum's Chinese info re-wrapped mid-shot, its
  // unit parted from its vector, where it could not).
  EXPECT_EQ(wordCount("初始(2, 0) kg，当前(1, 2) kg"), 6u);
  EXPECT_EQ(widerWords("kg，当前(1, 2)", "kg，当前(1.5, 2)", 10.0, monospace), "kg，当前(1.5, 2)");
  const std::vector<std::string> lines =
      breakLike("初始(2, 0) kg，当前(1, 2) kg", "初始(2, 0) kg，当前(1.5, 2) kg",
                {"初始(2, 0) kg，", "当前(1.5, 2) kg"})
          .value();
  EXPECT_EQ(lines, (std::vector<std::string>{"初始(2, 0) kg，", "当前(1, 2) kg"}));
}

TEST(WrapPatternTest, LinesOfOtherWordsAreNoPattern) {
  EXPECT_FALSE(breakLike("ab cd ef", "ab cd", {"ab", "cd"}).has_value());     // other words
  EXPECT_FALSE(breakLike("ab cd", "ab cd", {"ab", "cd", "ef"}).has_value());  // other lines
  const std::vector<std::string> lines = breakLike("a  b c", "aa  bb c", {"aa", "bb c"}).value();
  EXPECT_EQ(lines, (std::vector<std::string>{"a", "b c"}));  // spaces at the break dropped
}

TEST(WrapPatternTest, ATextOfOtherWordsKeepsThePatternsLines) {
  // The pattern takes three lines of 6 px; a text of other words that wraps in two at 6 px
  // is wrapped narrower, into three.
  const std::string pattern = "aaaa bbbb cccc";
  ASSERT_EQ(wrapText(pattern, 10.0, 6.0, monospace).size(), 3u);
  const std::string text = "aa bb c d";
  ASSERT_EQ(wrapText(text, 10.0, 6.0, monospace).size(), 2u);
  const std::vector<std::string> lines = wrapLike(text, pattern, 10.0, 6.0, monospace);
  EXPECT_EQ(lines.size(), 3u);
  for (const std::string& line : lines) EXPECT_LE(line.size(), 6u) << line;
}

TEST(WrapPatternTest, TextsOfOneShapeDifferOnlyInTheirNumbers) {
  EXPECT_EQ(wordShape("t = 0.001 s: no energy lost"), "t = # s: no energy lost");
  EXPECT_EQ(wordShape("t = 12.5 s: no energy lost"), "t = # s: no energy lost");
  // Signs, decimal marks and a vector's components: "(#, #)".
  EXPECT_EQ(wordShape("now (−0.0158, 2) kg"), "now (#, #) kg");
  EXPECT_EQ(wordShape("v₁ = +1,25 m/s"), "v₁ = # m/s");  // a subscript is no digit
  EXPECT_EQ(wordShape("١٫٥ J"), "# J");                  // Arabic-Indic "1٫5"
  EXPECT_NE(wordShape("t = 1 s: no energy lost"), wordShape("t = 1 s: energy lost 2 J"));
}

TEST(WrapPatternTest, AVectorIsTheWidestPieceThatStaysWhole) {
  // "now" (loose before a number) | "(1.5, 2.5) kg" (a vector with its unit): 13 px at a pixel
  // a byte.
  EXPECT_EQ(widestUnbrokenPx("now (1.5, 2.5) kg", 10.0, monospace), 13.0);
  EXPECT_EQ(widestUnbrokenPx("t = 1.5 s", 10.0, monospace), 9.0);  // "=" holds both sides
}

TEST(WrapPatternTest, ATextSpreadsOverAsManyLinesAsItsShotTakes) {
  // One line of 11 px by itself; in two, as even as they go: 5 and 5.
  EXPECT_EQ(wrapLike("aa bb cc dd", "", 10.0, 11.0, monospace),
            (std::vector<std::string>{"aa bb cc dd"}));
  EXPECT_EQ(wrapLike("aa bb cc dd", "", 10.0, 11.0, monospace, 2),
            (std::vector<std::string>{"aa bb", "cc dd"}));
  // Spread, a vector stays whole with its unit: the lines are never narrower than "(1.5, 2.5) kg"
  // (13), which leaves two lines, not the three asked for with "kg" alone on the last.
  EXPECT_EQ(wrapLike("now (1.5, 2.5) kg", "", 10.0, 17.0, monospace, 3),
            (std::vector<std::string>{"now", "(1.5, 2.5) kg"}));
  // Texts of one pattern are spread alike, where their pattern's spread breaks ("aa bb cc" |
  // "dddddd"), not each as evenly as it goes by itself ("aaaaaa" | "b c d").
  EXPECT_EQ(wrapLike("aaaaaa b c d", "aa bb cc dddddd", 10.0, 15.0, monospace, 2),
            (std::vector<std::string>{"aaaaaa b c", "d"}));
  EXPECT_EQ(wrapLike("aaaaaa b c d", "", 10.0, 15.0, monospace, 2),
            (std::vector<std::string>{"aaaaaa", "b c d"}));
}

TEST(WrapPatternTest, APatternKeepsASpeedWithItsDirection) {
  // "a v = 0.0195 m/s, −143°" (26 bytes) in 24: "a" | "v = 0.0195 m/s, −143°" (24), a speed
  // and its direction on one line; a frame of the same words breaks there too, never after
  // "m/s," with its angle alone below.
  const std::string pattern = "a v = 0.0195 m/s, \u2212143\u00B0";
  EXPECT_EQ(wrapText(pattern, 10.0, 24.0, monospace),
            (std::vector<std::string>{"a", "v = 0.0195 m/s, \u2212143\u00B0"}));
  EXPECT_EQ(wrapLike("a v = 1.98 m/s, 2\u00B0", pattern, 10.0, 24.0, monospace),
            (std::vector<std::string>{"a", "v = 1.98 m/s, 2\u00B0"}));
}

TEST(WrapPatternTest, AChineseWordBrokenBetweenItsCharactersBreaksAlike) {
  // The pattern's line breaks between 当 and 前 (3 bytes into the word "当前(1.5,"): a text whose
  // word begins with the same characters breaks there too.
  const std::vector<std::string> lines =
      breakLike("当前(1, 2) kg", "当前(1.5, 2) kg", {"当", "前(1.5, 2) kg"}).value();
  EXPECT_EQ(lines, (std::vector<std::string>{"当", "前(1, 2) kg"}));
}

TEST(WrapPatternTest, AWordThePatternPartsBreaksAfterItsWholeValue) {
  // newtons-cradle's "(−0.00997, −0.000000526)" is wider than its column and parted between
  // its digits: a frame's vector, which fits, breaks after its bracket, before the unit.
  const std::string pattern = "now (\u22120.00997, \u22120.000000526) kg";
  EXPECT_EQ(breakLike("now (0.5, \u22120.02) kg", pattern,
                      {"now", "(\u22120.00997, \u22120.0000005", "26) kg"})
                .value(),
            (std::vector<std::string>{"now", "(0.5, \u22120.02)", "kg"}));
  // Never inside a vector, nor between a number and its unit: where no such break follows, the
  // text does not break like the pattern.
  EXPECT_FALSE(breakLike("x (1.5, 2)", "x (1.25, 2)", {"x (1.2", "5, 2)"}).has_value());
  EXPECT_FALSE(breakLike("x 1.5 J", "x 1.25 J", {"x 1.2", "5 J"}).has_value());
}

}  // namespace
}  // namespace collide::text
