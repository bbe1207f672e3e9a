// SPDX-License-Identifier: MIT
// The working panel (issue 41): the title, each step's heading in small text, and its equations
// typeset with the math font (render/text/math_typesetter.hpp), the equals signs of each step on
// one vertical line. The math is set as large as the labels beside the scene where the working
// fits so, and not much smaller than the captions where it can be read otherwise: long lines break
// before an equals sign or an operator (draw_working_layout.hpp), the given values and short
// equations stand several to a row, a result the lines above already end in gives way, and where
// even so the working does not fit, the given values give way (a note says so: the substituted
// numbers and the scene's labels show them). A piece of an equation no line holds (a long fraction)
// is set smaller alone; only a working too long for all that is set smaller as a whole. The size
// and the places are chosen for the whole working, so nothing moves in a video as its steps appear.
#include <algorithm>
#include <cmath>

#include "render/draw/draw_working_layout.hpp"
#include "render/draw/frame_drawing.hpp"

namespace collide::render {
namespace {

// The smallest size a working is set at whole, a share of the captions' (at 1280x720: 22 px
// beside the captions' 24); the last resort's, a share of the labels'.
constexpr double kReadableShare = 0.9;
constexpr double kSmallestShare = 0.35;

struct WorkingChoice {
  double size_px = 0.0;
  bool skip_repeats = false, skip_given = false;
};

double headingPx(const frame::FrameLayout& layout, double size_px) {
  return std::max(1.0, std::round(std::min(layout.small_px, size_px)));
}

class SizeChooser {
 public:
  SizeChooser(const frame::WorkingModel& working, const frame::FrameStyle& style,
              const frame::FrameLayout& layout, const frame::PixelRect& room, Canvas& canvas)
      : working_(working), layout_(layout), room_(room), canvas_(canvas) {
    reference_ = setWorkingLines(working, style.numbers, canvas.painter().fonts(), layout.text_px);
  }

  // The largest size from the labels' down to about the captions' at which the working fits,
  // leaving out the repeated results where that lets it be larger; then without the given values;
  // then, the last resort, smaller.
  WorkingChoice choose() const {
    const double largest = std::round(layout_.text_px);
    const double floor = std::round(kReadableShare * layout_.small_px);
    for (double size = largest; size >= floor; size -= 1.0) {
      for (const bool repeats : {false, true}) {
        if (fits({size, repeats, false})) return {size, repeats, false};
      }
    }
    for (double size = largest; size >= floor; size -= 1.0) {
      if (fits({size, true, true})) return {size, true, true};
    }
    const double least = std::max(1.0, std::round(kSmallestShare * layout_.text_px));
    for (double size = floor - 1.0; size > least; size -= 1.0) {
      if (fits({size, true, true})) return {size, true, true};
    }
    return {least, true, true};
  }

  PlanOptions options(const WorkingChoice& choice, double scale) const {
    PlanOptions o;
    o.scale = scale;
    o.size_px = choice.size_px / scale;
    o.heading_px = headingPx(layout_, choice.size_px);
    o.width_px = room_.width();
    o.skip_repeats = choice.skip_repeats;
    o.skip_given = choice.skip_given;
    if (choice.skip_given) {
      o.note = canvas_.painter().wrap(working_.given_left_out, o.heading_px, room_.width(), 2);
    }
    return o;
  }

 private:
  bool fits(const WorkingChoice& choice) const {
    const WorkingPlan plan =
        planWorking(reference_, options(choice, choice.size_px / layout_.text_px));
    return !plan.overflows && plan.height_px <= room_.height();
  }

  const frame::WorkingModel& working_;
  const frame::FrameLayout& layout_;
  frame::PixelRect room_;
  Canvas& canvas_;
  std::vector<SetLine> reference_;
};

void drawBox(const MathBox& box, const core::Vec2& origin, const frame::Rgba& color,
             Canvas& canvas) {
  const MathBox placed = placedAt(box, origin);
  for (const MathRule& rule : placed.rules) {
    canvas.shapes().addRect({rule.x0, rule.y0, rule.x1, rule.y1}, color);
  }
  for (const PlacedLine& line : placed.lines) canvas.glyphs(line, color);
}

// Whether the line `source` of the working shows in this frame (a video reveals them in turn).
bool shown(const frame::WorkingModel& working, std::size_t source) {
  return working.shown_lines < 0 || source < static_cast<std::size_t>(working.shown_lines);
}

// The title names the impact, the bodies and the time: two lines rather than a cut. Returns the
// y under it.
double drawTitle(const frame::WorkingModel& working, const frame::FrameStyle& style, double y,
                 double words_x, double width_px, const frame::FrameLayout& layout,
                 Canvas& canvas) {
  const HAlign align = style.right_to_left ? HAlign::kRight : HAlign::kLeft;
  for (const std::string& line :
       canvas.painter().wrap(working.title, layout.small_px, width_px, 2)) {
    canvas.text(line, {words_x, y}, layout.small_px, style.text, align, VAlign::kTop);
    y += std::round(frame::kLineSpacing * layout.small_px);
  }
  return y;
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
  const double y = drawTitle(working, style, where.y0 + pad, words_x, inner_w, layout, canvas);
  const frame::PixelRect room{where.x0 + pad, y, where.x1 - pad, where.y1 - pad};
  const SizeChooser chooser(working, style, layout, room, canvas);
  const WorkingChoice choice = chooser.choose();
  FontSet& fonts = canvas.painter().fonts();
  PlanOptions options = chooser.options(choice, 1.0);
  // Set once to find the lines too wide for the panel, then again with those set smaller.
  const PieceScales piece_scales =
      planWorking(setWorkingLines(working, style.numbers, fonts, choice.size_px), options)
          .piece_scales;
  const std::vector<SetLine> lines =
      setWorkingLines(working, style.numbers, fonts, choice.size_px, piece_scales);
  options.squeeze = false;
  const WorkingPlan plan = planWorking(lines, options);
  for (const PlacedWords& words : plan.words) {
    if (!shown(working, words.source)) continue;
    if (room.y0 + words.y_px + options.heading_px > room.y1 + 0.5) break;
    canvas.text(words.text, {words_x, room.y0 + words.y_px}, options.heading_px, style.muted_text,
                words_align, VAlign::kTop);
  }
  for (const PlacedMath& math : plan.math) {
    if (!shown(working, math.source)) continue;
    // What does not fit (the last resort's smallest size) is left out.
    if (room.y0 + math.baseline_px + math.box->descent_px > room.y1 + 0.5) continue;
    drawBox(*math.box, {std::round(room.x0 + math.x_px), room.y0 + math.baseline_px}, style.text,
            canvas);
  }
}

}  // namespace collide::render
