// SPDX-License-Identifier: MIT
// The math typesetter (issue 41) with the OpenType MATH font: fractions stack about the math
// axis with the font's rule, scripts drop and rise, a radical covers what it encloses, fences
// stretch, and letters of symbols are the font's mathematical italics.
#include "render/text/math_typesetter.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "render/renderer.hpp"
#include "render/text/font_set.hpp"
#include "render/text/script_fonts.hpp"

namespace collide::render {
namespace {

using text::Math;

constexpr double kMathEmPx = 40.0;  // em, pixels

class MathTypesetterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!findMathFont()) {
      GTEST_SKIP()
          << "no OpenType MATH font (scripts/install-packages installs fonts-dejavu-extra)";
    }
  }
  FontSet fonts{textFontsFor(defaultFontPath(), "en")};
};

// The lowest and highest baseline of a box's glyphs, and its glyphs' fonts.
struct Baselines {
  double top = 1e9, bottom = -1e9;
};
Baselines baselines(const MathBox& box) {
  Baselines b;
  for (const PlacedLine& line : box.lines) {
    for (const PlacedGlyph& glyph : line.glyphs) {
      b.top = std::min(b.top, glyph.baseline_px);
      b.bottom = std::max(b.bottom, glyph.baseline_px);
    }
  }
  return b;
}

TEST_F(MathTypesetterTest, SymbolsAreTheMathFontsItalics) {
  const MathBox m = typesetMath(fonts, text::symbol("m"), kMathEmPx);
  ASSERT_EQ(m.lines.size(), 1u);
  ASSERT_EQ(m.lines[0].glyphs.size(), 1u);
  EXPECT_EQ(m.lines[0].glyphs[0].font, fonts.mathFont());
  EXPECT_EQ(m.lines[0].text, std::u32string(1, U'\U0001D45A'));  // 𝑚
  const MathBox digits = typesetMath(fonts, text::number("1.25"), kMathEmPx);
  EXPECT_EQ(digits.lines[0].text, U"1.25");  // numbers upright
}

TEST_F(MathTypesetterTest, AFractionStacksAboutOneRule) {
  const Math fraction = text::fraction(text::symbol("a"), text::symbol("b"));
  const MathBox box = typesetMath(fonts, fraction, kMathEmPx);
  ASSERT_EQ(box.rules.size(), 1u);
  const MathRule& rule = box.rules[0];
  const double thickness = rule.y1 - rule.y0;
  EXPECT_GT(thickness, 0.02 * kMathEmPx);  // the font's FractionRuleThickness: a few hundredths
  EXPECT_LT(thickness, 0.12 * kMathEmPx);
  EXPECT_LT(rule.y1, 0.0);  // on the math axis, above the baseline
  ASSERT_EQ(box.lines.size(), 2u);
  const double numerator = box.lines[0].glyphs[0].baseline_px;
  const double denominator = box.lines[1].glyphs[0].baseline_px;
  EXPECT_LT(numerator, rule.y0);    // above the rule
  EXPECT_GT(denominator, rule.y1);  // below it
  EXPECT_GT(box.ascent_px, -numerator);
  EXPECT_GT(box.descent_px, denominator);
}

TEST_F(MathTypesetterTest, ScriptsAreSmallerAndOffTheBaseline) {
  const Math v = text::scripts(text::symbol("v"), text::row({text::number("1")}),
                               text::row({text::number("2")}));
  const MathBox box = typesetMath(fonts, v, kMathEmPx);
  ASSERT_EQ(box.lines.size(), 3u);
  EXPECT_EQ(box.lines[0].glyphs[0].baseline_px, 0.0);
  EXPECT_GT(box.lines[1].glyphs[0].baseline_px, 0.0);  // the subscript drops
  EXPECT_LT(box.lines[2].glyphs[0].baseline_px, 0.0);  // the superscript rises
  EXPECT_LT(box.lines[1].glyphs[0].pixel_size, box.lines[0].glyphs[0].pixel_size);
}

TEST_F(MathTypesetterTest, ARadicalAndFencesReachOverWhatTheyEnclose) {
  const Math tall = text::fraction(text::symbol("h"), text::symbol("g"));
  const MathBox inside = typesetMath(fonts, tall, kMathEmPx);
  const MathBox root = typesetMath(fonts, text::root(tall), kMathEmPx);
  EXPECT_GT(root.ascent_px, inside.ascent_px);  // the rule over the radicand
  EXPECT_GT(root.width_px, inside.width_px);
  const MathBox plain = typesetMath(fonts, text::fenced(text::symbol("x")), kMathEmPx);
  const MathBox around = typesetMath(fonts, text::fenced(tall), kMathEmPx);
  EXPECT_GT(around.ascent_px + around.descent_px, plain.ascent_px + plain.descent_px);
  EXPECT_GE(around.ascent_px + around.descent_px, inside.ascent_px + inside.descent_px);
  const Baselines b = baselines(root);
  EXPECT_LT(b.top, 0.0);
}

}  // namespace
}  // namespace collide::render
