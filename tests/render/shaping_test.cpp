// Text shaped for every script (render/text/shaper.hpp): Arabic letters join and read from the
// right, a Devanagari conjunct is one cluster, CJK comes from the CJK font, Latin keeps the
// advances it is rasterized with. The expected glyphs come from HarfBuzz shaping each letter
// alone (its isolated form), never from the code under test's own output for the word.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "render/text/font_set.hpp"
#include "render/text/shaper.hpp"
#include "render/text/text.hpp"
#include "render/text/text_metrics.hpp"

namespace collide::render {
namespace {

constexpr double kSize_px = 32.0;

FontSet fontsFor(const char* tag) {
  return FontSet(textFontsFor(defaultFontPath(), tag));
}

// The glyph HarfBuzz gives `letter` shaped alone: its isolated form.
std::uint32_t isolatedGlyph(FontSet& fonts, const std::string& letter) {
  const ShapedLine alone = shapeLine(fonts, letter, kSize_px);
  EXPECT_EQ(alone.glyphs.size(), 1u) << letter;
  return alone.glyphs.empty() ? 0 : alone.glyphs.front().glyph_id;
}

TEST(ShapingTest, ArabicLettersJoinAndTheFirstIsDrawnRightmost) {
  FontSet fonts = fontsFor("ar");
  ASSERT_EQ(fonts.size(), 2) << "Arabic needs its script font";
  // كتلة (mass): kaf, teh, lam, teh marbuta; the first three join to the next letter, so kaf
  // takes its initial form, teh and lam their medial forms, teh marbuta its final form.
  const std::vector<std::string> letters = {"ك", "ت", "ل", "ة"};
  std::string word;
  for (const std::string& letter : letters) word += letter;
  const ShapedLine line = shapeLine(fonts, word, kSize_px);
  ASSERT_EQ(line.text.size(), 4u);
  ASSERT_EQ(line.glyphs.size(), 4u);
  for (const ShapedGlyph& glyph : line.glyphs) {
    EXPECT_TRUE(glyph.right_to_left);
    EXPECT_EQ(glyph.font, 1) << "drawn in the Arabic font";
    EXPECT_EQ(glyph.cluster_end, glyph.cluster_begin + 1);
  }
  // Visual order is left to right: the clusters run 3, 2, 1, 0 and x grows.
  for (std::size_t k = 0; k < 4; ++k) {
    const ShapedGlyph& glyph = line.glyphs[k];
    EXPECT_EQ(glyph.cluster_begin, 3 - k);
    EXPECT_NE(glyph.glyph_id, isolatedGlyph(fonts, letters[glyph.cluster_begin]))
        << "letter " << glyph.cluster_begin << " is drawn in its isolated form";
    if (k > 0) {
      EXPECT_GT(glyph.x_px, line.glyphs[k - 1].x_px);
    }
  }
  const auto first = std::find_if(line.glyphs.begin(), line.glyphs.end(),
                                  [](const ShapedGlyph& g) { return g.cluster_begin == 0; });
  const double rightmost =
      std::max_element(line.glyphs.begin(), line.glyphs.end(),
                       [](const ShapedGlyph& a, const ShapedGlyph& b) { return a.x_px < b.x_px; })
          ->x_px;
  EXPECT_EQ(first->x_px, rightmost);
}

TEST(ShapingTest, NumbersAndSymbolsInArabicKeepTheirOwnOrder) {
  FontSet fonts = fontsFor("ar");
  // "mass 2.5 kg" in an Arabic sentence: the word reads from the right, at the right end; the
  // number keeps its digits left to right, in the default font.
  const ShapedLine line = shapeLine(fonts, "الكتلة 2.5 kg", kSize_px);
  const std::u32string& text = line.text;
  const auto x_of = [&](char32_t c) {
    const std::size_t at = text.find(c);
    for (const ShapedGlyph& g : line.glyphs) {
      if (g.cluster_begin == at) return g.x_px;
    }
    ADD_FAILURE() << "no glyph for character " << at;
    return 0.0;
  };
  EXPECT_LT(x_of(U'2'), x_of(U'.'));
  EXPECT_LT(x_of(U'.'), x_of(U'5'));
  EXPECT_LT(x_of(U'k'), x_of(U'g'));
  EXPECT_GT(x_of(text[0]), x_of(U'5')) << "the Arabic word, first in the text, is rightmost";
  for (const ShapedGlyph& g : line.glyphs) {
    if (text[g.cluster_begin] == U'2') {
      EXPECT_EQ(g.font, 0) << "digits in the default font";
    }
  }
}

TEST(ShapingTest, AnArabicMinusStaysBeforeItsDigitsInALeftToRightLine) {
  FontSet fonts = fontsFor("ar");
  // Arabic writes a negative number with the Arabic letter mark before its minus sign (CLDR:
  // U+061C U+2212); a line of symbols and numbers reads left to right, as in a physics book, so
  // the sign stands left of the digits: "v = −١٤٣°" and a ruler's "−٠٫٥", never "١٤٣−".
  for (const std::string& shown : {std::string("v = \u061C\u2212\u0661\u0664\u0663\u00B0"),
                                   std::string("\u061C\u2212\u0660\u066B\u0665")}) {
    const ShapedLine line = shapeLine(fonts, shown, kSize_px);
    const std::u32string& text = line.text;
    std::vector<std::pair<char32_t, double>> xs;  // each visible character and its x
    for (const ShapedGlyph& g : line.glyphs) xs.emplace_back(text[g.cluster_begin], g.x_px);
    const auto x_of = [&](char32_t c) {
      for (const auto& [ch, x] : xs) {
        if (ch == c) return x;
      }
      ADD_FAILURE() << "no glyph for U+" << std::hex << static_cast<int>(c);
      return 0.0;
    };
    const char32_t first_digit = text[text.find(U'\u2212') + 1];
    const char32_t last_digit = text[text.size() - (shown.ends_with("\u00B0") ? 2 : 1)];
    EXPECT_LT(x_of(U'\u2212'), x_of(first_digit)) << shown << ": the minus after its digits";
    EXPECT_LT(x_of(first_digit), x_of(last_digit)) << shown << ": the digits reversed";
  }
}

TEST(ShapingTest, AnArabicNumberStandsLeftOfItsUnitInAnArabicSentence) {
  FontSet fonts = fontsFor("ar");
  // "lost ١٩٨ J of ٢٠٠ J" (ballistic-pendulum's caption): in a right-to-left sentence each
  // quantity is one left-to-right piece, as docs/translations.md writes it ("٢٠٠ J"): its digits
  // in order and its unit at their right, read after them. The bidirectional algorithm alone would
  // put the Latin unit at the digits' left ("J ١٩٨"), read before them. And the sentence still
  // reads from the right: the first quantity stands right of the second.
  const ShapedLine line = shapeLine(
      fonts,
      "\u0627\u0644\u0645\u0641\u0642\u0648\u062F\u0629 \u0661\u0669\u0668 J \u0645\u0646 "
      "\u0662\u0660\u0660 J",
      kSize_px);
  const std::u32string& text = line.text;
  const auto x_at = [&](std::size_t at) {
    for (const ShapedGlyph& g : line.glyphs) {
      if (g.cluster_begin <= at && at < g.cluster_end) return g.x_px;
    }
    ADD_FAILURE() << "no glyph for character " << at;
    return 0.0;
  };
  const std::size_t first_one = text.find(U'\u0661'), first_j = text.find(U'J');
  const std::size_t first_two = text.find(U'\u0662'), second_j = text.rfind(U'J');
  EXPECT_LT(x_at(first_one), x_at(first_one + 2)) << "the digits of 198 in order";
  EXPECT_LT(x_at(first_one + 2), x_at(first_j)) << "J right of 198";
  EXPECT_LT(x_at(first_two + 2), x_at(second_j)) << "J right of 200";
  EXPECT_GT(x_at(first_one), x_at(second_j)) << "the first quantity right of the second";
}

// The x of the glyph drawing character `at` of the line.
double xOfCharacter(const ShapedLine& line, std::size_t at) {
  for (const ShapedGlyph& g : line.glyphs) {
    if (g.cluster_begin <= at && at < g.cluster_end) return g.x_px;
  }
  ADD_FAILURE() << "no glyph for character " << at;
  return 0.0;
}

TEST(ShapingTest, AnArabicVectorReadsLeftToRightWithItsUnitAfterIt) {
  FontSet fonts = fontsFor("ar");
  // A vector's components are kept apart by the Arabic semicolon (docs/translations.md,
  // "(٢٫٠٠؛ ٠)"), a right-to-left character. The vector with its unit is one left-to-right
  // piece, written as the docs write it: its first component at the left, then "؛", the second,
  // ")" and the unit at the right; on a line of numbers and symbols, and in an Arabic sentence
  // ("Σp: at the start (٠٫٣٦٠؛ −٠٫٢٦٦) kg·m/s، now"), whose words still read from the right.
  const std::string vector =
      "(\u0660\u066B\u0663\u0666\u0660\u061B \u061C\u2212\u0660\u066B"
      "\u0662\u0666\u0666) kg\u00B7m/s";
  const std::string at_start = "\u0641\u064A \u0627\u0644\u0628\u062F\u0627\u064A\u0629";
  const std::string now = "\u0627\u0644\u0622\u0646";
  for (const std::string& shown :
       {vector, "\u03A3p: " + at_start + " " + vector + "\u060C " + now}) {
    const ShapedLine line = shapeLine(fonts, shown, kSize_px);
    const std::u32string& text = line.text;
    const std::size_t open = text.find(U'('), semicolon = text.find(U'\u061B');
    const std::size_t second = text.find(U'\u2212'), close = text.find(U')');
    const std::size_t unit = text.find(U'k');
    const auto x = [&](std::size_t at) { return xOfCharacter(line, at); };
    EXPECT_LT(x(open), x(open + 1)) << shown << ": \"(\" left of the first component";
    EXPECT_LT(x(open + 1), x(open + 4)) << shown << ": the first component's digits in order";
    EXPECT_LT(x(open + 4), x(semicolon)) << shown << ": the first component left of \"؛\"";
    EXPECT_LT(x(semicolon), x(second)) << shown << ": the second component right of \"؛\"";
    EXPECT_LT(x(second), x(second + 1)) << shown << ": the minus before its digits";
    EXPECT_LT(x(close - 1), x(close)) << shown << ": \")\" after the second component";
    EXPECT_LT(x(close), x(unit)) << shown << ": the unit right of the vector";
    if (shown != vector) {
      EXPECT_GT(x(text.find(U'\u0641')), x(unit)) << shown << ": \"at the start\" before it";
      EXPECT_LT(x(text.find(U'\u0622')), x(open)) << shown << ": \"now\" after it";
    }
  }
}

TEST(ShapingTest, AFormulasSymbolStaysLeftOfItsEqualsSignBeforeArabicWords) {
  FontSet fonts = fontsFor("ar");
  // A strobe's span in Arabic, "t = من ٠ إلى ٤ s" (t = from 0 to 4 s): "t =" is read as written,
  // the symbol left of its "=", never "= t"; the Arabic words after it stand left of it.
  const ShapedLine line =
      shapeLine(fonts, "t = \u0645\u0646 \u0660 \u0625\u0644\u0649 \u0664 s", kSize_px);
  const std::u32string& text = line.text;
  const auto x = [&](std::size_t at) { return xOfCharacter(line, at); };
  EXPECT_LT(x(text.find(U't')), x(text.find(U'='))) << "t left of =";
  EXPECT_LT(x(text.find(U'\u0645')), x(text.find(U't'))) << "the words after t = at its left";
  EXPECT_LT(x(text.find(U'\u0664')), x(text.find(U's'))) << "4 left of its unit";
}

TEST(ShapingTest, AHindiConjunctIsOneCluster) {
  FontSet fonts = fontsFor("hi");
  ASSERT_EQ(fonts.size(), 2) << "Hindi needs its script font";
  // क्ष: ka, virama, ssa; one conjunct (kssa), one cluster of three characters.
  for (const char* conjunct : {"क्ष", "त्र"}) {
    const ShapedLine line = shapeLine(fonts, conjunct, kSize_px);
    ASSERT_EQ(line.text.size(), 3u) << conjunct;
    ASSERT_FALSE(line.glyphs.empty());
    EXPECT_LT(line.glyphs.size(), 3u) << conjunct << ": the letters are not drawn one by one";
    for (const ShapedGlyph& g : line.glyphs) {
      EXPECT_EQ(g.cluster_begin, 0u) << conjunct;
      EXPECT_EQ(g.cluster_end, 3u) << conjunct;
      EXPECT_EQ(g.font, 1) << conjunct;
      EXPECT_FALSE(g.right_to_left);
    }
  }
  // The vowel sign i (ि) comes after its consonant in the text and is drawn before it.
  const ShapedLine ki = shapeLine(fonts, "कि", kSize_px);
  ASSERT_EQ(ki.glyphs.size(), 2u);
  EXPECT_EQ(ki.glyphs[0].cluster_begin, 0u);
  EXPECT_EQ(ki.glyphs[0].cluster_end, 2u);
  EXPECT_NE(ki.glyphs[0].glyph_id, fonts.font(1).glyphIndex(U'क'));
}

TEST(ShapingTest, JapaneseComesFromTheCjkFontAndLatinFromTheDefaultOne) {
  FontSet fonts = fontsFor("ja");
  ASSERT_EQ(fonts.size(), 2);
  const ShapedLine line = shapeLine(fonts, "衝突 v = 1.5 m/s", kSize_px);
  ASSERT_EQ(line.glyphs.size(), line.text.size());
  for (const ShapedGlyph& g : line.glyphs) {
    const char32_t c = line.text[g.cluster_begin];
    if (c == U'衝' || c == U'突') {
      EXPECT_EQ(g.font, 1);
      // A CJK ideograph is as wide as it is high (one em).
      EXPECT_NEAR(g.advance_px, kSize_px, 1.0);
    }
    if (c == U'v' || c == U'1') {
      EXPECT_EQ(g.font, 0);
    }
  }
}

TEST(ShapingTest, LatinAdvancesAreTheRasterizedOnesAndSubscriptsShrink) {
  FontSet fonts = fontsFor("en");
  ASSERT_EQ(fonts.size(), 1);
  const ShapedLine line = shapeLine(fonts, "mv₁", kSize_px);
  ASSERT_EQ(line.glyphs.size(), 3u);
  Font& font = fonts.primary();
  EXPECT_EQ(line.glyphs[0].advance_px, font.rasterizeGlyph(font.glyphIndex(U'm'), 32).advance_px);
  EXPECT_EQ(line.glyphs[1].x_px, line.glyphs[0].advance_px);
  EXPECT_EQ(line.glyphs[2].glyph_id, font.glyphIndex(U'1')) << "₁ is drawn as a small 1";
  EXPECT_LT(line.glyphs[2].pixel_size, 32);
  EXPECT_GT(line.glyphs[2].shift_px, 0.0) << "below the baseline";
  EXPECT_EQ(line.text[line.glyphs[2].cluster_begin], U'\u2081');
}

TEST(ShapingTest, APainterShapesEachStringOnce) {
  FontSet fonts = fontsFor("ar");
  GlyphAtlas atlas(fonts);
  TextPainter painter(atlas);
  const ShapedLine& first = painter.shaped("السرعة", kSize_px);
  const ShapedLine& again = painter.shaped("السرعة", kSize_px);
  EXPECT_EQ(&first, &again) << "the second call is answered from the cache";
  EXPECT_NE(&painter.shaped("السرعة", 20.0), &first) << "another size is another shape";
}

}  // namespace
}  // namespace collide::render
