// Lines that fit a width (text/text_wrap.hpp): Chinese and Japanese wrap between characters,
// measured with the shaped width of the CJK font; text in scripts written with spaces breaks at
// spaces only, as it always did.
#include "text/text_wrap.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "render/renderer.hpp"
#include "render/text/font_set.hpp"
#include "render/text/glyph_atlas.hpp"
#include "render/text/text.hpp"
#include "render/text/utf8.hpp"

namespace collide::render {
namespace {

constexpr double kWrapSize_px = 20.0;

class TextWrapTest : public ::testing::Test {
 protected:
  FontSet fonts{textFontsFor(defaultFontPath(), "ja")};
  GlyphAtlas atlas{fonts};
  TextPainter painter{atlas};
  const text::TextWidth shaped = [this](std::string_view text, double size_px) {
    return painter.width(text, size_px);
  };
};

std::string joinedLines(const std::vector<std::string>& lines, const std::string& between) {
  std::string all;
  for (const std::string& line : lines) all += (all.empty() ? "" : between) + line;
  return all;
}

TEST_F(TextWrapTest, AJapaneseSentenceWrapsIntoLinesWithinTheWidthAndLosesNothing) {
  const std::string sentence =
      "二つの台車は衝突の後、一緒に動き、運動エネルギーの一部は熱に変わる。";
  const double whole = shaped(sentence, kWrapSize_px);
  const double room = 0.6 * whole;  // too narrow for one line, wide enough for two
  const std::vector<std::string> lines = text::wrapText(sentence, kWrapSize_px, room, shaped);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(joinedLines(lines, ""), sentence);
  for (const std::string& line : lines) EXPECT_LE(shaped(line, kWrapSize_px), room) << line;
  // The first line is as long as it can be: with the next character it would not fit (or the
  // next character is one no line may start with, "、" or "。").
  const std::u32string second = decodeUtf8(lines[1]);
  const std::string longer = lines[0] + encodeUtf8(second.substr(0, 1));
  EXPECT_TRUE(shaped(longer, kWrapSize_px) > room || second[1] == U'、' || second[1] == U'。')
      << lines[0];
  // No line starts with closing punctuation.
  for (const std::string& line : lines) {
    EXPECT_FALSE(line.starts_with("、") || line.starts_with("。")) << line;
  }
}

TEST_F(TextWrapTest, ALineNeverStartsWithAClosingMarkEvenWhereTheWidthWouldAllowIt) {
  // Room for exactly "衝突の後": "、" may not start the next line, so "後、" goes down together.
  const std::string text = "衝突の後、一緒に動く。";
  const double room = shaped("衝突の後", kWrapSize_px) + 0.5;
  const std::vector<std::string> lines = text::wrapText(text, kWrapSize_px, room, shaped);
  ASSERT_GE(lines.size(), 2u);
  EXPECT_EQ(lines[0], "衝突の");
  EXPECT_TRUE(lines[1].starts_with("後、")) << lines[1];
  EXPECT_EQ(joinedLines(lines, ""), text);
}

TEST_F(TextWrapTest, ACaptionThatDoesNotFitItsLinesKeepsTheRestWithoutAddedSpaces) {
  const std::string text = "衝突の後、二つの台車は一緒に動く。運動エネルギーの一部は熱に変わる。";
  const double room = shaped("衝突の後、二つの台車は", kWrapSize_px) + 0.5;
  const std::vector<std::string> lines = painter.wrap(text, kWrapSize_px, room, 2);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "衝突の後、二つの台車は");
  EXPECT_EQ(lines[1].find(' '), std::string::npos) << lines[1];
  EXPECT_TRUE(lines[1].ends_with("\u2026")) << lines[1];
  EXPECT_LE(shaped(lines[1], kWrapSize_px), room);
}

// In scripts written with spaces every break is at a space, and each line takes as many words
// as fit: the lines joined with spaces give the text back, and the next line's first word would
// not have fitted on the line before.
void expectBreaksAtSpacesOnly(const std::string& text, const std::vector<std::string>& lines,
                              double room, const text::TextWidth& width) {
  ASSERT_GE(lines.size(), 2u) << text;
  EXPECT_EQ(joinedLines(lines, " "), text);
  for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
    const std::string next_word = lines[i + 1].substr(0, lines[i + 1].find(' '));
    EXPECT_GT(width(lines[i] + " " + next_word, kWrapSize_px), room) << lines[i];
    EXPECT_LE(width(lines[i], kWrapSize_px), room) << lines[i];
  }
}

TEST_F(TextWrapTest, LatinCyrillicArabicDevanagariAndKoreanBreakAtSpacesAsBefore) {
  for (const char* tag : {"de", "ru", "ar", "hi", "ko"}) {
    FontSet script_fonts{textFontsFor(defaultFontPath(), tag)};
    GlyphAtlas script_atlas{script_fonts};
    TextPainter script_painter{script_atlas};
    const text::TextWidth width = [&](std::string_view text, double size_px) {
      return script_painter.width(text, size_px);
    };
    const std::string text =
        std::string(tag) == "de" ? "Nach dem Stoß bewegen sich beide Wagen gemeinsam weiter"
        : std::string(tag) == "ru" ? "После удара обе тележки движутся вместе дальше"
        : std::string(tag) == "ar" ? "بعد التصادم تتحرك العربتان معا إلى الأمام"
        : std::string(tag) == "hi" ? "संघट्ट के बाद दोनों ट्रॉली साथ साथ चलती हैं"
                                   : "충돌 후에 두 수레는 함께 앞으로 움직인다";
    const double room = 0.45 * width(text, kWrapSize_px);
    expectBreaksAtSpacesOnly(text, text::wrapText(text, kWrapSize_px, room, width), room, width);
  }
}

// A label glued to its number ("estroboscópica: 2 imágenes", kept together where a line has room)
// in a column narrower than the three words: broken at their spaces, the number with its unit,
// rather than held on one line that the painter then has to cut short. (A Spanish strobe's
// caption at 640x360 lost ": 2 imágenes" that way.)
TEST_F(TextWrapTest, ANumberGluedToTheWordsBesideItBreaksWhereTheyDoNotFitTogether) {
  const std::string text = "Imagen estroboscópica: 2 imágenes por segundo (6 en total)";
  const double room = shaped("estroboscópica: 2", kWrapSize_px) - 1.0;
  ASSERT_GT(room, shaped("2 imágenes por", kWrapSize_px));
  const std::vector<std::string> lines = text::wrapText(text, kWrapSize_px, room, shaped);
  EXPECT_EQ(joinedLines(lines, " "), text);
  for (const std::string& line : lines) EXPECT_LE(shaped(line, kWrapSize_px), room) << line;
  // The number stays with its unit.
  const auto at = std::find_if(lines.begin(), lines.end(), [](const std::string& line) {
    return line.find("2 imágenes") != std::string::npos;
  });
  EXPECT_NE(at, lines.end()) << joinedLines(lines, " | ");
  // Where the glued words fit, nothing changes: "t = 1.5 s" is never parted.
  const std::string readout = "energy at t = 1.5 s";
  const double wide = shaped("at t = 1.5 s", kWrapSize_px) + 0.5;
  const std::vector<std::string> kept = text::wrapText(readout, kWrapSize_px, wide, shaped);
  EXPECT_NE(std::find(kept.begin(), kept.end(), "t = 1.5 s"), kept.end())
      << joinedLines(kept, " | ");
}

// An Arabic readout writes its numbers in Arabic-Indic digits (٠ to ٩, with the decimal sign ٫)
// and a negative one with the Arabic letter mark before its minus: at every width, a number stays
// on the line of its unit ("٢٠٠ J", "٠٫٠١٩٥ m/s") and of its sign, as an ASCII one does.
TEST_F(TextWrapTest, AnArabicNumberIsNeverPartedFromItsUnitOrSign) {
  FontSet arabic_fonts{textFontsFor(defaultFontPath(), "ar")};
  GlyphAtlas arabic_atlas{arabic_fonts};
  TextPainter arabic_painter{arabic_atlas};
  const text::TextWidth width = [&](std::string_view text, double size_px) {
    return arabic_painter.width(text, size_px);
  };
  const std::string text =
      "الطاقة المفقودة \u0661\u0669\u0668 J من \u0662\u0660\u0660 J؛ v₁′ = "
      "\u0660\u066B\u0660\u0661\u0669\u0665 m/s، \u061C\u2212\u0661\u0664\u0663°";
  const std::u32string arabic_digits =
      U"\u0660\u0661\u0662\u0663\u0664\u0665\u0666\u0667"
      U"\u0668\u0669";
  const double whole = width(text, kWrapSize_px);
  // From the widest piece that stays whole ("=" holds both its sides, a sign the word before
  // it) up to the whole text.
  const double widest =
      width("v₁′ = \u0660\u066B\u0660\u0661\u0669\u0665 m/s، \u061C\u2212\u0661\u0664\u0663°",
            kWrapSize_px) +
      1.0;
  for (double room = widest; room < whole; room += 0.02 * whole) {
    const std::vector<std::string> lines = text::wrapText(text, kWrapSize_px, room, width);
    EXPECT_EQ(joinedLines(lines, " "), text);
    for (std::size_t k = 0; k + 1 < lines.size(); ++k) {
      const std::u32string here = decodeUtf8(lines[k]), next = decodeUtf8(lines[k + 1]);
      const bool ends_in_digit = arabic_digits.find(here.back()) != std::u32string::npos;
      const bool unit_next = next.starts_with(U"J") || next.starts_with(U"m/s");
      EXPECT_FALSE(ends_in_digit && unit_next)
          << "a number parted from its unit: " << joinedLines(lines, " | ");
      EXPECT_FALSE(here.ends_with(U"\u2212") || here.back() == U'\u061C')
          << "a sign parted from its number: " << joinedLines(lines, " | ");
    }
  }
}

// Runs of spaces as one: a clause gap ("a   b") at a break is dropped.
std::string singleSpaced(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (!(c == ' ' && !out.empty() && out.back() == ' ')) out += c;
  }
  return out;
}

// A vector is one value: where the decimal sign is a comma its components are parted by "; "
// ("(2,00; 0) kg·m/s"), which elsewhere parts clauses. At every width from its widest vector with
// its unit up to the whole line, no line ends inside brackets and none starts with the unit.
// (newtons-cradle's German info broke as "Start (2,00;" | "0) kg·m/s".)
TEST_F(TextWrapTest, AVectorAndItsUnitAreNeverParted) {
  for (const std::string text :
       {"Stöße: 4   Σp: Start (2,00; 0) kg·m/s, jetzt (−0,250; 1,25) kg·m/s",
        "collisions: 4   Σp: start (2.00, 0) kg·m/s, now (−0.250, 1.25) kg·m/s"}) {
    const double whole = shaped(text, kWrapSize_px);
    const double widest = shaped("(−0,250; 1,25) kg·m/s", kWrapSize_px) + 1.0;
    for (double room = widest; room < whole; room += 0.02 * whole) {
      const std::vector<std::string> lines = text::wrapText(text, kWrapSize_px, room, shaped);
      EXPECT_EQ(singleSpaced(joinedLines(lines, " ")), singleSpaced(text));
      int depth = 0;
      for (std::size_t k = 0; k < lines.size(); ++k) {
        for (const char c : lines[k]) depth += c == '(' ? 1 : c == ')' ? -1 : 0;
        EXPECT_EQ(depth, 0) << "a line ends inside a vector: " << joinedLines(lines, " | ");
        EXPECT_FALSE(k > 0 && lines[k].starts_with("kg·m/s"))
            << "a vector parted from its unit: " << joinedLines(lines, " | ");
      }
    }
  }
}

// The width of text in the fonts of language `tag`.
class ScriptWidth {
 public:
  explicit ScriptWidth(const char* tag) : fonts_(textFontsFor(defaultFontPath(), tag)) {}
  text::TextWidth width() {
    return [this](std::string_view text, double size_px) { return painter_.width(text, size_px); };
  }

 private:
  FontSet fonts_;
  GlyphAtlas atlas_{fonts_};
  TextPainter painter_{atlas_};
};

std::string withoutSpaces(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c != ' ') out += c;
  }
  return out;
}

// Chinese closes its commas up to the next word ("kg·m/s，当前(1.05, 0.589)"), so the vector after
// one stands apart from the unit before it: at every width that holds each vector with its unit
// and mark, no line ends inside a vector and none starts with a unit (ballistic-pendulum's
// Chinese info broke "当前(1.05," | "0.589) kg·m/s" and "初始(2.00, 0)" | "kg·m/s，当前").
TEST_F(TextWrapTest, AChineseVectorStaysWholeWithItsUnit) {
  ScriptWidth chinese("zh-Hans");
  const text::TextWidth width = chinese.width();
  const std::string text = "碰撞次数：1   Σp：初始(2.00, 0) kg·m/s，当前(1.05, 0.589) kg·m/s";
  const double whole = width(text, kWrapSize_px);
  const double widest = std::max(width("初始(2.00, 0) kg·m/s，", kWrapSize_px),
                                 width("当前(1.05, 0.589) kg·m/s", kWrapSize_px)) +
                        1.0;
  for (double room = widest; room < whole; room += 0.02 * whole) {
    const std::vector<std::string> lines = text::wrapText(text, kWrapSize_px, room, width);
    EXPECT_EQ(withoutSpaces(joinedLines(lines, "")), withoutSpaces(text));
    int depth = 0;
    for (std::size_t k = 0; k < lines.size(); ++k) {
      EXPECT_LE(width(lines[k], kWrapSize_px), room) << lines[k];
      for (const char c : lines[k]) depth += c == '(' ? 1 : c == ')' ? -1 : 0;
      EXPECT_EQ(depth, 0) << "a line ends inside a vector: " << joinedLines(lines, " | ");
      EXPECT_FALSE(lines[k].starts_with("kg·m/s"))
          << "a vector parted from its unit: " << joinedLines(lines, " | ");
    }
  }
}

// A list's last item, a number with its unit, does not stand alone where the item before it can
// join it on its line (ballistic-pendulum's caption at t = 0 in German: "v₁ = 0 m/s, v₂ = 200
// m/s," | "0°"). At a width that holds the list but its last item, the last line holds the last
// two items, in every script's marks.
TEST_F(TextWrapTest, ANumberEndingAListDoesNotStandAloneWhereTheItemBeforeCanJoinIt) {
  ScriptWidth latin("de"), chinese("zh-Hans");
  struct Case {
    text::TextWidth width;
    std::string text, list_but_last, last_two;
  };
  const std::vector<Case> cases = {
      {latin.width(),
       "t = 0,000 s: keine Energie verloren (gesamt 200 J); v₁ = 0 m/s, v₂ = 200 m/s, 0°",
       "v₁ = 0 m/s, v₂ = 200 m/s,", "v₂ = 200 m/s, 0°"},
      {chinese.width(), "t = 0.000 s：没有能量损失；v₁ = 0 m/s，v₂ = 200 m/s，−5°",
       "v₁ = 0 m/s，v₂ = 200 m/s，", "v₂ = 200 m/s，−5°"}};
  for (const Case& c : cases) {
    const double room = c.width(c.list_but_last, kWrapSize_px) + 1.0;
    ASSERT_GT(c.width(c.list_but_last + " 0°", kWrapSize_px), room);
    const std::vector<std::string> lines = text::wrapText(c.text, kWrapSize_px, room, c.width);
    ASSERT_FALSE(lines.empty());
    EXPECT_EQ(lines.back(), c.last_two) << joinedLines(lines, " | ");
  }
}

}  // namespace
}  // namespace collide::render
