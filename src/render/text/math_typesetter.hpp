// SPDX-License-Identifier: MIT
#pragma once
// Private: mathematics (text/math.hpp) set in two dimensions with an OpenType MATH font through
// HarfBuzz's hb-ot-math: the font's constants place fractions (numerator shift, rule thickness,
// gaps about the math axis), radicals (gap, rule, the radical glyph's size variant tall enough),
// sub- and superscripts (their scale and shifts) and stretch fences to what they enclose. Letters
// of symbols are the font's mathematical italics (𝑚, 𝑣, 𝜇), numbers and units upright. A leaf the
// math font cannot write (a symbol in another script) is shaped with the text fonts.
//
// The result is glyph lines (PlacedLine, drawn by either painter as text is) and rules
// (rectangles), relative to the formula's origin on its baseline.
#include <vector>

#include "frame/layout.hpp"
#include "render/text/text.hpp"
#include "text/math.hpp"

namespace collide::render {

struct MathRule {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;  // pixels from the origin, y downwards
};

struct MathBox {
  double width_px = 0.0;
  double ascent_px = 0.0;         // above the baseline, > 0 up
  double descent_px = 0.0;        // below the baseline, > 0 down
  std::vector<PlacedLine> lines;  // glyph positions from the origin (pen_x, baseline)
  std::vector<MathRule> rules;

  // The box moved by (dx, dy) pixels.
  void shift(double dx_px, double dy_px);
  // Appends `other` at horizontal offset dx and vertical offset dy (down positive).
  void append(const MathBox& other, double dx_px, double dy_px);
};

// Sets `math` at `size_px` (em) with `fonts` (its math font; the text fonts where there is none,
// with TeX's default proportions).
MathBox typesetMath(FontSet& fonts, const text::Math& math, double size_px);

// A box placed with its origin at `origin_px` (whole pixels for the baselines).
MathBox placedAt(MathBox box, const core::Vec2& origin_px);

}  // namespace collide::render
