// Where Chinese and Japanese may be broken (text/line_breaks.hpp). The expected breaks come from
// UAX #14's classes, spelled out in the test: Han and kana are ideographic (a break is allowed on
// either side), "、" "。" "）" "」" are closing (no break before), "（" "「" opening (no break
// after), small kana and "ー" non-starters (no break before). Scripts written with spaces get none.
#include "text/line_breaks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace collide::text {
namespace {

// The byte offsets of every character boundary of `text` (all code points here are 3 bytes in
// UTF-8) where UAX #14 allows a break: neither before a closing mark or non-starter nor after an
// opening mark.
std::vector<std::size_t> expectedBreaks(const std::u32string& text) {
  const std::set<char32_t> no_break_before = {U'、', U'。', U'）', U'」',
                                              U'，', U'ょ', U'ー', U'っ'};
  const std::set<char32_t> no_break_after = {U'（', U'「'};
  std::vector<std::size_t> breaks;
  for (std::size_t i = 1; i < text.size(); ++i) {
    if (no_break_before.contains(text[i]) || no_break_after.contains(text[i - 1])) continue;
    breaks.push_back(3 * i);
  }
  return breaks;
}

TEST(LineBreaksTest, JapaneseBreaksBetweenCharactersButNeverBeforeClosingMarks) {
  const std::u32string sentence = U"衝突の後、二つの台車は一緒に動く。";
  const std::string utf8 = "衝突の後、二つの台車は一緒に動く。";
  ASSERT_EQ(utf8.size(), 3 * sentence.size());
  EXPECT_EQ(ideographicLineBreaks(utf8), expectedBreaks(sentence));
}

TEST(LineBreaksTest, NoBreakAfterAnOpeningBracketOrBeforeSmallKanaAndTheLengthMark) {
  const std::u32string text = U"「ちょっとエネルギー」（熱）";
  const std::string utf8 = "「ちょっとエネルギー」（熱）";
  const std::vector<std::size_t> breaks = ideographicLineBreaks(utf8);
  EXPECT_EQ(breaks, expectedBreaks(text));
  // Spelled out for two of them: not between "ち" and "ょ", not after "「".
  EXPECT_FALSE(std::count(breaks.begin(), breaks.end(), 3u));
  EXPECT_FALSE(std::count(breaks.begin(), breaks.end(), 6u));
}

TEST(LineBreaksTest, ChineseBreaksBetweenHanButNotBeforeItsCommaAndFullStop) {
  const std::u32string sentence = U"两个小车碰撞后，一起运动。";
  EXPECT_EQ(ideographicLineBreaks("两个小车碰撞后，一起运动。"), expectedBreaks(sentence));
}

TEST(LineBreaksTest, NumbersUnitsAndSpacesInsideJapaneseAreLeftToTheCaller) {
  // "速さ v = 1.25 m/s": a break only between "速" and "さ"; none at the spaces (the caller
  // breaks there by its own rules) and none inside "m/s".
  EXPECT_EQ(ideographicLineBreaks("速さ v = 1.25 m/s"), std::vector<std::size_t>{3});
  // Latin letters glued to kana: a break between the ideographic and the Latin character.
  EXPECT_EQ(ideographicLineBreaks("KEは"), std::vector<std::size_t>{2});
}

TEST(LineBreaksTest, ScriptsWrittenWithSpacesGetNoBreaksInsideWords) {
  for (const std::string text :
       {"energy lost 0.68 J of 1.38 J; inelastic-collision m/s", "потери энергии 0,68 Дж",
        "الطاقة المفقودة 0.68 J", "ऊर्जा क्षय 0.68 J", "에너지 손실 0.68 J; 비탄성 충돌", ""}) {
    EXPECT_TRUE(ideographicLineBreaks(text).empty()) << text;
  }
}

TEST(LineBreaksTest, SymbolsOfOtherScriptsGetNoBreaksAndJapaneseAfterThemStillDoes) {
  // Subscripts, primes, the minus sign, the middle dot and accented letters are not
  // ideographic, so no break is found around them, whatever was broken before or after.
  for (int round = 0; round < 2; ++round) {
    for (const std::string text : {"v\u2081\u2032 = \u22120.250 m/s", "N\u00b7s", "\u00e9nergie",
                                   "\u0394E = 1.25\u00a0J", "\u2248"}) {
      EXPECT_TRUE(ideographicLineBreaks(text).empty()) << text;
    }
    const std::u32string sentence = U"衝突の後、二つの台車は一緒に動く。";
    EXPECT_EQ(ideographicLineBreaks("衝突の後、二つの台車は一緒に動く。"),
              expectedBreaks(sentence));
  }
}

TEST(LineBreaksTest, ThreadsBreakTheSameTextAlikeAtTheSameTime) {
  const std::u32string sentence = U"两个小车碰撞后，一起运动。";
  const std::vector<std::size_t> expected = expectedBreaks(sentence);
  std::vector<std::vector<std::size_t>> found(4);
  std::vector<std::thread> threads;
  for (auto& result : found) {
    threads.emplace_back([&result] {
      for (int i = 0; i < 50; ++i) result = ideographicLineBreaks("两个小车碰撞后，一起运动。");
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (const auto& result : found) EXPECT_EQ(result, expected);
}

}  // namespace
}  // namespace collide::text
