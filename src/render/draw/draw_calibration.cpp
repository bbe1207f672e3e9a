// SPDX-License-Identifier: MIT
// What Tracker's calibration tools are set on (render --calibration): a stick of a round length
// lying on the x ruler between two of its ticks, its length written between their numbers, and a
// cross at the world's origin. Both stand in the world's coordinates, which one video never moves,
// so they stay in place for the whole video.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "frame/mark_sizes.hpp"
#include "render/draw/frame_drawing.hpp"

namespace collide::render {
namespace {

// How long the stick may be, in ruler steps: the first that leaves room for its length's text.
constexpr std::array<int, 4> kStepsPerStick = {1, 2, 5, 10};

// Where the stick lies: from tick `from` over `steps` ruler steps; steps == 0: no room for one.
struct StickPlace {
  std::size_t from = 0;
  int steps = 0;
};

// The stick starts at the origin's tick where it can (Tracker's origin and the stick then share a
// mark), else at the first tick; it is as short as leaves room for its text between the numbers
// of its two ticks, and ends before the last tick where it can (whose number, with the unit,
// would read beside the stick's own).
StickPlace placeStick(const frame::RulerAxis& axis, const std::vector<double>& number_widths_px,
                      const frame::WorldToPixel& to_px, double label_w_px, double gap_px) {
  const std::size_t ticks = axis.ticks_m.size();
  std::size_t origin = 0;
  for (std::size_t k = 0; k < ticks; ++k) {
    if (std::abs(axis.ticks_m[k]) < 1e-9 * axis.step_m) origin = k;
  }
  for (const bool to_last : {false, true}) {
    for (const int steps : kStepsPerStick) {
      for (const std::size_t from : {origin, std::size_t{0}}) {
        const std::size_t to = from + static_cast<std::size_t>(steps);
        if (to >= ticks || (to + 1 == ticks && !to_last)) continue;
        // drawRuler centres a number under its tick, the last one (with its unit) ends there.
        const double to_number_px =
            to + 1 == ticks ? number_widths_px[to] : 0.5 * number_widths_px[to];
        const double span_px = to_px.px_per_m * (axis.ticks_m[to] - axis.ticks_m[from]);
        const double free_px = span_px - 0.5 * number_widths_px[from] - to_number_px;
        if (free_px >= label_w_px + 2.0 * gap_px) return {from, steps};
      }
    }
  }
  return {};
}

}  // namespace

void drawOriginCross(const frame::PanelModel& panel, const frame::FrameStyle& style,
                     const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                     const frame::PixelRect& area, ShapeSink& mesh) {
  // 1D bodies move along the track: their origin is on it (docs/data-format.md).
  const core::Vec2 origin = to_px.toPixel({0.0, panel.two_d ? 0.0 : panel.track_y_m});
  if (origin.x() < area.x0 || origin.x() > area.x1 || origin.y() < area.y0 ||
      origin.y() > area.y1) {
    return;
  }
  const DrawnItemScope item(mesh, "origin", "scale");
  const double arm = 0.8 * layout.small_px, thin = std::max(1.0, 0.5 * layout.line_px);
  mesh.addLine(origin - core::Vec2{arm, 0.0}, origin + core::Vec2{arm, 0.0}, thin, style.text);
  mesh.addLine(origin - core::Vec2{0.0, arm}, origin + core::Vec2{0.0, arm}, thin, style.text);
}

void drawCalibrationStick(const frame::PanelModel& panel, const frame::FrameStyle& style,
                          const frame::PanelLayout& where, const frame::FrameLayout& layout,
                          const frame::WorldToPixel& to_px, const frame::PixelRect& area,
                          Canvas& canvas) {
  const frame::RulerPlacement ruler = frame::rulerPlacement(panel, where, layout, to_px, area);
  const frame::RulerAxis& axis = ruler.along_x;
  if (axis.ticks_m.size() < 2) return;
  // The ruler's numbers as drawRuler writes them (the last with its unit).
  std::vector<double> number_widths_px;
  for (std::size_t k = 0; k < axis.ticks_m.size(); ++k) {
    const bool last = k + 1 == axis.ticks_m.size();
    const std::string number = tickLabel(axis.ticks_m[k], style.numbers) + (last ? " m" : "");
    number_widths_px.push_back(canvas.painter().width(number, layout.small_px));
  }
  // The widest length the stick could state: its text is measured before its length is known.
  const std::string widest = tickLabel(10.0 * axis.step_m, style.numbers) + " m";
  const double label_w = canvas.painter().width(widest, layout.small_px);
  const StickPlace place = placeStick(axis, number_widths_px, to_px, label_w, layout.gap_px);
  if (place.steps == 0) return;
  const double from_m = axis.ticks_m[place.from];
  const double to_m = axis.ticks_m[place.from + static_cast<std::size_t>(place.steps)];
  const double y = ruler.x_axis_y_px, tick = frame::kRulerTickLength * layout.scale_px;
  const core::Vec2 a{to_px.toPixel({from_m, 0.0}).x(), y}, b{to_px.toPixel({to_m, 0.0}).x(), y};

  ShapeSink& mesh = canvas.shapes();
  const DrawnItemScope item(mesh, "calibration", "scale");
  mesh.describeStick({a, b, to_m - from_m, to_px.px_per_m});
  // A bar along the ruler's line between the ticks, and an end cap over each tick reaching above
  // the line, where nothing else is drawn: the two marks Tracker's stick is dragged onto.
  const double bar = std::max(2.0, 0.4 * tick), cap = std::max(1.5, 0.6 * layout.line_px);
  const core::Vec2 down{0.0, 0.5 * tick};
  mesh.addLine(a + down, b + down, bar, style.text);
  for (const core::Vec2& end : {a, b}) {
    mesh.addLine(end - core::Vec2{0.0, 0.4 * tick}, end + core::Vec2{0.0, tick}, cap, style.text);
  }
  const std::string label = tickLabel(to_m - from_m, style.numbers) + " m";
  canvas.text(label, {0.5 * (a.x() + b.x()), y + tick + 0.2 * layout.small_px}, layout.small_px,
              style.text, HAlign::kCenter, VAlign::kTop);
}

}  // namespace collide::render
