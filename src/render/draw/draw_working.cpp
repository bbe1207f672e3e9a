// SPDX-License-Identifier: MIT
// The working panel (issue 41): the title, each step's heading in small text, and its equations
// typeset with the math font (render/text/math_typesetter.hpp), the equals signs of each step on
// one vertical line. The size shrinks until the whole working fits its place.
#include <algorithm>
#include <cmath>

#include "render/draw/frame_drawing.hpp"
#include "render/text/math_typesetter.hpp"
#include "text/number_format.hpp"

namespace collide::render {
namespace {

constexpr double kSmallestShare = 0.35;  // the working's size never falls below this of text_px
constexpr int kFitTries = 6;

struct TypesetLine {
  std::string heading;
  int step = 0;         // the lines of one step align their equals signs; the next step's may not
  MathBox left, right;  // sides[0]; "= sides[1] = ..."
  double height_px = 0.0;
};

double lineHeight(const TypesetLine& line, double size_px) {
  return std::max(line.left.ascent_px, line.right.ascent_px) +
         std::max(line.left.descent_px, line.right.descent_px) + 0.2 * size_px;
}

// The working's own whole numbers, written in ASCII (the 2 of a square, the 1 and 2 of ½, the 1
// of 1 + e), in the frame's digits, as the formatted numbers beside them are: Arabic-Indic in
// Arabic. Subscripts stay: they name bodies (m₁), as the scene's labels write them.
text::Math withFrameDigits(text::Math math, const text::NumberStyle& numbers) {
  if (math.kind == text::MathKind::kNumber) {
    math.text = text::withLocalDigits(math.text, numbers);
    return math;
  }
  for (std::size_t k = 0; k < math.parts.size(); ++k) {
    const bool subscript = math.kind == text::MathKind::kScripts && k == 1;
    if (!subscript) math.parts[k] = withFrameDigits(std::move(math.parts[k]), numbers);
  }
  return math;
}

// "= a = b" from sides [first, last) of an equation.
text::Math rightSides(const std::vector<text::Math>& sides, std::size_t first, std::size_t last) {
  text::Math right = text::row({});
  for (std::size_t k = first; k < last; ++k) {
    right.parts.push_back(text::op("="));
    right.parts.push_back(sides[k]);
  }
  return right;
}

// `split`: an equation of three sides or more puts each side after the second on a line of its
// own, under the first equals sign (narrower, taller).
std::vector<TypesetLine> typesetLines(const frame::WorkingModel& working,
                                      const text::NumberStyle& numbers, FontSet& fonts,
                                      double size_px, double heading_px, bool split) {
  std::vector<TypesetLine> lines;
  int step = -1;
  for (frame::WorkingLine line : working.lines) {
    TypesetLine set;
    if (line.sides.empty()) ++step;
    set.step = std::max(0, step);
    if (line.sides.empty()) {
      set.heading = line.heading;
      set.height_px = std::round(frame::kLineSpacing * heading_px);
      lines.push_back(std::move(set));
      continue;
    }
    if (!numbers.digits.empty()) {
      for (text::Math& side : line.sides) side = withFrameDigits(std::move(side), numbers);
    }
    const std::size_t first_end =
        split ? std::min<std::size_t>(2, line.sides.size()) : line.sides.size();
    set.left = typesetMath(fonts, line.sides[0], size_px);
    set.right = typesetMath(fonts, rightSides(line.sides, 1, first_end), size_px);
    set.height_px = lineHeight(set, size_px);
    const int line_step = set.step;
    lines.push_back(std::move(set));
    for (std::size_t k = first_end; k < line.sides.size(); ++k) {
      TypesetLine more;
      more.step = line_step;
      more.right = typesetMath(fonts, rightSides(line.sides, k, k + 1), size_px);
      more.height_px = lineHeight(more, size_px);
      lines.push_back(std::move(more));
    }
  }
  return lines;
}

// The widest left side of each step's lines: where that step's equals signs stand. Aligning
// step by step, not the whole panel, keeps one wide law from pushing every result right.
std::vector<double> stepLeftWidths(const std::vector<TypesetLine>& lines) {
  std::vector<double> left_w;
  for (const TypesetLine& line : lines) {
    if (std::size_t(line.step) >= left_w.size()) left_w.resize(line.step + 1, 0.0);
    left_w[line.step] = std::max(left_w[line.step], line.left.width_px);
  }
  return left_w;
}

// How much the lines must shrink (< 1) or may grow (> 1) to fit `room`.
double fitScale(const std::vector<TypesetLine>& lines, const frame::PixelRect& room) {
  const std::vector<double> left_w = stepLeftWidths(lines);
  double height = 0.0, width = 0.0;
  for (const TypesetLine& line : lines) {
    height += line.height_px;
    width = std::max(width, left_w[line.step] + line.right.width_px);
  }
  return std::min(room.height() / height, room.width() / std::max(1.0, width));
}

void drawBox(const MathBox& box, const core::Vec2& origin, const frame::Rgba& color,
             Canvas& canvas) {
  const MathBox placed = placedAt(box, origin);
  for (const MathRule& rule : placed.rules) {
    canvas.shapes().addRect({rule.x0, rule.y0, rule.x1, rule.y1}, color);
  }
  for (const PlacedLine& line : placed.lines) canvas.glyphs(line, color);
}

}  // namespace

void drawWorking(const frame::WorkingModel& working, const frame::FrameStyle& style,
                 const frame::PixelRect& where, const frame::FrameLayout& layout, Canvas& canvas) {
  const double pad = std::round(0.5 * layout.gap_px);
  canvas.shapes().addRectFrame(where, layout.bar_frame_px, style.bar_frame);
  const double inner_w = where.width() - 2.0 * pad;
  // Words start at the right edge in a language read from the right; the math reads left to right
  // in every language.
  const double words_x = style.right_to_left ? where.x1 - pad : where.x0 + pad;
  const HAlign words_align = style.right_to_left ? HAlign::kRight : HAlign::kLeft;
  // The title names the impact, the bodies and the time: two lines rather than a cut.
  double y = where.y0 + pad;
  for (const std::string& title_line :
       canvas.painter().wrap(working.title, layout.small_px, inner_w, 2)) {
    canvas.text(title_line, {words_x, y}, layout.small_px, style.text, words_align, VAlign::kTop);
    y += std::round(frame::kLineSpacing * layout.small_px);
  }
  FontSet& fonts = canvas.painter().fonts();
  const frame::PixelRect room{where.x0 + pad, y, where.x1 - pad, where.y1 - pad};
  double size_px = layout.text_px;
  std::vector<TypesetLine> lines;
  for (int attempt = 0; attempt < kFitTries; ++attempt) {
    const double heading_px = std::max(1.0, std::round(std::min(layout.small_px, size_px)));
    // Whichever arrangement lets the working be set larger.
    std::vector<TypesetLine> whole =
        typesetLines(working, style.numbers, fonts, size_px, heading_px, false);
    std::vector<TypesetLine> split =
        typesetLines(working, style.numbers, fonts, size_px, heading_px, true);
    const double whole_scale = fitScale(whole, room);
    const double split_scale = fitScale(split, room);
    const bool use_split = split_scale > whole_scale;
    lines = use_split ? std::move(split) : std::move(whole);
    const double scale = std::max(whole_scale, split_scale);
    if (scale >= 1.0 || size_px <= kSmallestShare * layout.text_px) break;
    size_px =
        std::max(kSmallestShare * layout.text_px, std::floor(size_px * std::min(0.97, scale)));
  }
  const double heading_px = std::max(1.0, std::round(std::min(layout.small_px, size_px)));
  const std::vector<double> left_w = stepLeftWidths(lines);
  // Lines of the equations of one working line share its index: typesetLines splits some.
  std::size_t source_line = 0;
  for (const TypesetLine& line : lines) {
    if (!line.heading.empty() || line.left.width_px > 0.0) ++source_line;
    if (working.shown_lines >= 0 && source_line > std::size_t(working.shown_lines)) break;
    if (y + line.height_px > where.y1 - pad + 0.5) break;  // what does not fit is left out
    if (!line.heading.empty()) {
      canvas.text(line.heading, {words_x, y}, heading_px, style.muted_text, words_align,
                  VAlign::kTop);
    } else {
      const double equals_x = std::round(where.x0 + pad + left_w[line.step]);
      const double baseline =
          std::round(y + std::max(line.left.ascent_px, line.right.ascent_px) + 0.1 * size_px);
      drawBox(line.left, {equals_x - line.left.width_px, baseline}, style.text, canvas);
      drawBox(line.right, {equals_x, baseline}, style.text, canvas);
    }
    y += line.height_px;
  }
}

}  // namespace collide::render
