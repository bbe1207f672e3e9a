// SPDX-License-Identifier: MIT
#include "render/text/math_typesetter.hpp"

#include <hb-ot.h>
#include <hb.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "render/text/font_set.hpp"
#include "render/text/shaper.hpp"
#include "render/text/utf8.hpp"

namespace collide::render {

using text::Math;
using text::MathKind;

void MathBox::shift(double dx_px, double dy_px) {
  for (PlacedLine& line : lines) {
    for (PlacedGlyph& glyph : line.glyphs) {
      glyph.pen_x_px += dx_px;
      glyph.baseline_px += dy_px;
    }
  }
  for (MathRule& rule : rules) {
    rule.x0 += dx_px;
    rule.x1 += dx_px;
    rule.y0 += dy_px;
    rule.y1 += dy_px;
  }
}

void MathBox::append(const MathBox& other, double dx_px, double dy_px) {
  MathBox moved = other;
  moved.shift(dx_px, dy_px);
  lines.insert(lines.end(), moved.lines.begin(), moved.lines.end());
  rules.insert(rules.end(), moved.rules.begin(), moved.rules.end());
  width_px = std::max(width_px, dx_px + other.width_px);
  ascent_px = std::max(ascent_px, other.ascent_px - dy_px);
  descent_px = std::max(descent_px, other.descent_px + dy_px);
}

namespace {

// The MATH table's constants in pixels at one size (TeX's proportions where there is none).
struct Constants {
  double axis = 0.25, rule = 0.05, num_up = 0.68, den_down = 0.69, num_gap = 0.15, den_gap = 0.15,
         sub_down = 0.25, sup_up = 0.41, script_scale = 0.7, radical_gap = 0.15,
         radical_rule = 0.05, radical_extra = 0.05, space_after_script = 0.05;
};

class Typesetter {
 public:
  Typesetter(FontSet& fonts) : fonts_(fonts), math_(fonts.mathFont()) {}

  MathBox set(const Math& math, double size_px);

 private:
  hb_font_t* hbFont(double size_px) {
    return fonts_.font(math_).shapingFont(std::max(1, static_cast<int>(std::lround(size_px))));
  }
  Constants constants(double size_px);
  MathBox leaf(const std::string& utf8, double size_px, bool italic);
  MathBox mathFontLeaf(const std::u32string& text, double size_px);
  MathBox textFontLeaf(const std::string& utf8, double size_px);
  MathBox row(const Math& math, double size_px);
  MathBox fraction(const Math& math, double size_px);
  MathBox radical(const Math& math, double size_px);
  MathBox scripts(const Math& math, double size_px);
  MathBox fence(const Math& math, double size_px);
  // A glyph of `c` at least `height_px` tall (its size variants), centred on the math axis.
  MathBox stretched(char32_t c, double height_px, double size_px, bool on_axis);

  FontSet& fonts_;
  int math_;
};

char32_t mathItalic(char32_t c) {
  if (c == U'h') return 0x210E;  // Planck's h holds the place of the italic h
  if (c >= U'a' && c <= U'z') return 0x1D44E + (c - U'a');
  if (c >= U'A' && c <= U'Z') return 0x1D434 + (c - U'A');
  if (c >= 0x03B1 && c <= 0x03C9) return 0x1D6FC + (c - 0x03B1);  // α … ω
  return c;
}

Constants Typesetter::constants(double size_px) {
  Constants c;
  if (math_ < 0 || !hb_ot_math_has_data(hb_font_get_face(hbFont(size_px)))) {
    for (double* v :
         {&c.axis, &c.rule, &c.num_up, &c.den_down, &c.num_gap, &c.den_gap, &c.sub_down, &c.sup_up,
          &c.radical_gap, &c.radical_rule, &c.radical_extra, &c.space_after_script}) {
      *v *= size_px;
    }
    return c;
  }
  hb_font_t* font = hbFont(size_px);
  auto px = [&](hb_ot_math_constant_t k) { return hb_ot_math_get_constant(font, k) / 64.0; };
  c.axis = px(HB_OT_MATH_CONSTANT_AXIS_HEIGHT);
  c.rule = px(HB_OT_MATH_CONSTANT_FRACTION_RULE_THICKNESS);
  c.num_up = px(HB_OT_MATH_CONSTANT_FRACTION_NUMERATOR_DISPLAY_STYLE_SHIFT_UP);
  c.den_down = px(HB_OT_MATH_CONSTANT_FRACTION_DENOMINATOR_DISPLAY_STYLE_SHIFT_DOWN);
  c.num_gap = px(HB_OT_MATH_CONSTANT_FRACTION_NUM_DISPLAY_STYLE_GAP_MIN);
  c.den_gap = px(HB_OT_MATH_CONSTANT_FRACTION_DENOM_DISPLAY_STYLE_GAP_MIN);
  c.sub_down = px(HB_OT_MATH_CONSTANT_SUBSCRIPT_SHIFT_DOWN);
  c.sup_up = px(HB_OT_MATH_CONSTANT_SUPERSCRIPT_SHIFT_UP);
  c.script_scale =
      hb_ot_math_get_constant(font, HB_OT_MATH_CONSTANT_SCRIPT_PERCENT_SCALE_DOWN) / 100.0;
  c.radical_gap = px(HB_OT_MATH_CONSTANT_RADICAL_DISPLAY_STYLE_VERTICAL_GAP);
  c.radical_rule = px(HB_OT_MATH_CONSTANT_RADICAL_RULE_THICKNESS);
  c.radical_extra = px(HB_OT_MATH_CONSTANT_RADICAL_EXTRA_ASCENDER);
  c.space_after_script = px(HB_OT_MATH_CONSTANT_SPACE_AFTER_SCRIPT);
  return c;
}

MathBox Typesetter::mathFontLeaf(const std::u32string& text, double size_px) {
  hb_font_t* font = hbFont(size_px);
  hb_buffer_t* buffer = hb_buffer_create();
  hb_buffer_add_utf32(buffer, reinterpret_cast<const std::uint32_t*>(text.data()),
                      static_cast<int>(text.size()), 0, static_cast<int>(text.size()));
  hb_buffer_set_direction(buffer, HB_DIRECTION_LTR);
  hb_buffer_guess_segment_properties(buffer);
  hb_shape(font, buffer, nullptr, 0);
  unsigned count = 0;
  const hb_glyph_info_t* infos = hb_buffer_get_glyph_infos(buffer, &count);
  const hb_glyph_position_t* positions = hb_buffer_get_glyph_positions(buffer, &count);
  MathBox box;
  PlacedLine line;
  line.text = text;
  double x = 0.0;
  const int pixel_size = std::max(1, static_cast<int>(std::lround(size_px)));
  for (unsigned k = 0; k < count; ++k) {
    const std::uint32_t begin = infos[k].cluster;
    const std::uint32_t end = k + 1 < count ? infos[k + 1].cluster : std::uint32_t(text.size());
    PlacedGlyph glyph;
    glyph.font = math_;
    glyph.glyph_id = infos[k].codepoint;
    glyph.drawn = glyph.source = text[begin];
    glyph.cluster_begin = begin;
    glyph.cluster_end = std::max(begin + 1, end);
    glyph.pixel_size = pixel_size;
    glyph.pen_x_px = x + positions[k].x_offset / 64.0;
    glyph.baseline_px = -positions[k].y_offset / 64.0;
    glyph.advance_px = positions[k].x_advance / 64.0;
    hb_glyph_extents_t extents{};
    if (hb_font_get_glyph_extents(font, infos[k].codepoint, &extents)) {
      box.ascent_px = std::max(box.ascent_px, extents.y_bearing / 64.0);
      box.descent_px = std::max(box.descent_px, -(extents.y_bearing + extents.height) / 64.0);
    }
    x += glyph.advance_px;
    line.glyphs.push_back(glyph);
  }
  hb_buffer_destroy(buffer);
  box.width_px = x;
  box.lines.push_back(std::move(line));
  return box;
}

MathBox Typesetter::textFontLeaf(const std::string& utf8, double size_px) {
  const ShapedLine shaped = shapeLine(fonts_, utf8, size_px);
  MathBox box;
  PlacedLine line;
  line.text = shaped.text;
  for (const ShapedGlyph& g : shaped.glyphs) {
    line.glyphs.push_back({g.font, g.glyph_id, g.drawn, shaped.text[g.cluster_begin],
                           g.cluster_begin, g.cluster_end, g.pixel_size, g.x_px, g.shift_px,
                           g.advance_px, g.right_to_left});
  }
  const FontMetrics metrics = fonts_.metrics(std::max(1, static_cast<int>(std::lround(size_px))));
  box.width_px = shaped.width_px;
  box.ascent_px = 0.75 * metrics.ascender_px;
  box.descent_px = 0.5 * metrics.descender_px;
  box.lines.push_back(std::move(line));
  return box;
}

MathBox Typesetter::leaf(const std::string& utf8, double size_px, bool italic) {
  std::u32string text = decodeUtf8(utf8);
  if (italic) {
    for (char32_t& c : text) c = mathItalic(c);
  }
  bool math_font_has_all = math_ >= 0;
  for (char32_t c : text) {
    if (math_font_has_all && !fonts_.font(math_).hasGlyph(c) && c != U'\u0302') {
      math_font_has_all = false;
    }
  }
  return math_font_has_all ? mathFontLeaf(text, size_px) : textFontLeaf(utf8, size_px);
}

std::string primeText(int primes) {
  std::string out;
  for (int k = 0; k < primes; ++k) out += "′";
  return out;
}

bool isBinary(const std::string& op) {
  return op == "+" || op == "−" || op == "·" || op == "×" || op == "=" || op == "≈";
}

MathBox Typesetter::row(const Math& math, double size_px) {
  MathBox box;
  double x = 0.0;
  for (std::size_t k = 0; k < math.parts.size(); ++k) {
    const Math& part = math.parts[k];
    // A relation is spaced even first in a row (the right side of an aligned equation).
    const bool binary = part.kind == MathKind::kOperator && isBinary(part.text) &&
                        (k > 0 || part.text == "=" || part.text == "≈");
    const double around = binary ? (part.text == "=" ? 0.28 : 0.22) * size_px : 0.0;
    if (part.kind == MathKind::kUnit && part.text.rfind("°", 0) != 0) x += 0.17 * size_px;
    x += around;
    const MathBox piece = set(part, size_px);
    box.append(piece, x, 0.0);
    x += piece.width_px + around;
    if (part.kind == MathKind::kOperator && (part.text == "," || part.text == ";")) {
      x += 0.17 * size_px;
    }
    if (part.kind == MathKind::kWord && part.text.size() > 1 && k + 1 < math.parts.size()) {
      x += 0.17 * size_px;  // a function name before its argument
    }
  }
  box.width_px = x;
  return box;
}

MathBox Typesetter::fraction(const Math& math, double size_px) {
  const Constants c = constants(size_px);
  const bool half = math.parts[0].kind == MathKind::kNumber && math.parts[0].text == "1" &&
                    math.parts[1].kind == MathKind::kNumber && math.parts[1].text == "2";
  const double part_px = half ? size_px * c.script_scale : size_px;
  const MathBox top = set(math.parts[0], part_px), bottom = set(math.parts[1], part_px);
  const double up = std::max(half ? 0.6 * c.num_up : c.num_up,
                             top.descent_px + c.axis + 0.5 * c.rule + c.num_gap);
  const double down = std::max(half ? 0.6 * c.den_down : c.den_down,
                               bottom.ascent_px - c.axis + 0.5 * c.rule + c.den_gap);
  const double pad = 0.12 * size_px;
  const double width = std::max(top.width_px, bottom.width_px) + 2.0 * pad;
  MathBox box;
  box.append(top, 0.5 * (width - top.width_px), -up);
  box.append(bottom, 0.5 * (width - bottom.width_px), down);
  box.rules.push_back(
      {0.5 * pad, -c.axis - 0.5 * c.rule, width - 0.5 * pad, -c.axis + 0.5 * c.rule});
  box.width_px = width;
  return box;
}

MathBox Typesetter::stretched(char32_t c, double height_px, double size_px, bool on_axis) {
  MathBox glyph = leaf(encodeUtf8(std::u32string(1, c)), size_px, false);
  if (math_ < 0 || glyph.lines.empty() || glyph.lines[0].glyphs.size() != 1 ||
      glyph.lines[0].glyphs[0].font != math_) {
    return glyph;
  }
  hb_font_t* font = hbFont(size_px);
  PlacedGlyph& placed = glyph.lines[0].glyphs[0];
  hb_ot_math_glyph_variant_t variants[16];
  unsigned count = 16;
  hb_ot_math_get_glyph_variants(font, placed.glyph_id, HB_DIRECTION_BTT, 0, &count, variants);
  for (unsigned k = 0; k < count; ++k) {
    placed.glyph_id = variants[k].glyph;
    if (variants[k].advance / 64.0 >= height_px) break;
  }
  hb_glyph_extents_t extents{};
  hb_font_get_glyph_extents(font, placed.glyph_id, &extents);
  const double top = extents.y_bearing / 64.0, bottom = (extents.y_bearing + extents.height) / 64.0;
  placed.advance_px = hb_font_get_glyph_h_advance(font, placed.glyph_id) / 64.0;
  glyph.width_px = placed.advance_px;
  glyph.ascent_px = top;
  glyph.descent_px = -bottom;
  if (on_axis) {
    const double lift = 0.5 * (top + bottom) - constants(size_px).axis;  // centre onto the axis
    glyph.shift(0.0, lift);
    glyph.ascent_px = top - lift;
    glyph.descent_px = -bottom + lift;
  }
  return glyph;
}

MathBox Typesetter::radical(const Math& math, double size_px) {
  const Constants c = constants(size_px);
  const MathBox inside = set(math.parts[0], size_px);
  const double needed = inside.ascent_px + inside.descent_px + c.radical_gap + c.radical_rule;
  MathBox sign = stretched(U'√', needed, size_px, false);
  // The sign's top meets the rule over the radicand.
  const double rule_top = inside.ascent_px + c.radical_gap + c.radical_rule;
  sign.shift(0.0, sign.ascent_px - rule_top);
  const double sign_descent = sign.descent_px + (sign.ascent_px - rule_top);
  MathBox box;
  box.append(sign, 0.0, 0.0);
  box.ascent_px = rule_top + c.radical_extra;
  box.descent_px = std::max(inside.descent_px, sign_descent);
  box.append(inside, sign.width_px, 0.0);
  box.rules.push_back({sign.width_px - 0.5 * c.radical_rule, -rule_top,
                       sign.width_px + inside.width_px, -rule_top + c.radical_rule});
  box.width_px = sign.width_px + inside.width_px;
  return box;
}

MathBox Typesetter::scripts(const Math& math, double size_px) {
  const Constants c = constants(size_px);
  const double script_px = size_px * c.script_scale;
  MathBox box = set(math.parts[0], size_px);
  const double x = box.width_px;
  double right = x;
  if (!math.parts[1].empty()) {
    const MathBox sub = set(math.parts[1], script_px);
    box.append(sub, x, std::max(c.sub_down, sub.ascent_px - 0.8 * size_px * 0.5));
    right = std::max(right, x + sub.width_px);
  }
  // Primes at the base's size right after it: a math font draws the prime high already.
  if (math.primes > 0) {
    const MathBox primes = leaf(primeText(math.primes), size_px, false);
    box.append(primes, x, 0.0);
    right = std::max(right, x + primes.width_px);
  }
  if (!math.parts[2].empty()) {
    const MathBox sup = set(math.parts[2], script_px);
    box.append(sup, right, -std::max(c.sup_up, sup.descent_px + 0.25 * size_px));
    right += sup.width_px;
  }
  box.width_px = right + c.space_after_script;
  return box;
}

MathBox Typesetter::fence(const Math& math, double size_px) {
  const MathBox body = set(math.parts[0], size_px);
  const Constants c = constants(size_px);
  // Tall enough to reach as far from the axis as the body does, on both sides.
  const double reach = std::max(body.ascent_px - c.axis, body.descent_px + c.axis);
  const MathBox open = stretched(decodeUtf8(math.text).front(), 2.0 * reach, size_px, true);
  const MathBox close = stretched(decodeUtf8(math.close).front(), 2.0 * reach, size_px, true);
  MathBox box;
  box.append(open, 0.0, 0.0);
  box.append(body, open.width_px, 0.0);
  box.append(close, open.width_px + body.width_px, 0.0);
  box.width_px = open.width_px + body.width_px + close.width_px;
  return box;
}

MathBox Typesetter::set(const Math& math, double size_px) {
  switch (math.kind) {
    case MathKind::kRow:
      return row(math, size_px);
    case MathKind::kSymbol:
      return leaf(math.text, size_px, true);
    case MathKind::kFraction:
      return fraction(math, size_px);
    case MathKind::kRoot:
      return radical(math, size_px);
    case MathKind::kScripts:
      return scripts(math, size_px);
    case MathKind::kFence:
      return fence(math, size_px);
    default:
      return leaf(math.text, size_px, false);
  }
}

}  // namespace

MathBox typesetMath(FontSet& fonts, const text::Math& math, double size_px) {
  Typesetter typesetter(fonts);
  return typesetter.set(math, size_px);
}

MathBox placedAt(MathBox box, const core::Vec2& origin_px) {
  box.shift(origin_px.x(), origin_px.y());
  for (PlacedLine& line : box.lines) {
    for (PlacedGlyph& glyph : line.glyphs) glyph.baseline_px = std::round(glyph.baseline_px);
  }
  return box;
}

}  // namespace collide::render
