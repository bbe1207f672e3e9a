// Bodies on strings: the bar the strings hang from, the strings, dotted arc trails, and
// dimension lines (a ballistic pendulum's rise) with their labels.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "frame/mark_sizes.hpp"
#include "render/draw/frame_drawing.hpp"

namespace collide::render {
namespace {

// Fractions of the layout scale.
constexpr double kSupportHatchSpacing = 0.022;
constexpr double kArcDotSpacing = 0.018;  // between the dots of an arc trail
constexpr double kArcDotRadius = 0.0035;

}  // namespace

void drawSuspensionUnder(const frame::SuspensionModel& suspension, const frame::FrameStyle& style,
                         const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                         ShapeSink& mesh) {
  const double s = layout.scale_px;
  for (const frame::ArcModel& arc : suspension.arcs) {
    // Dots along the swept arc, evenly spaced in pixels.
    const double radius_px = arc.radius_m * to_px.px_per_m;
    const double span = arc.to_rad - arc.from_rad;
    const int dots = std::clamp(static_cast<int>(radius_px * span / (kArcDotSpacing * s)), 1, 2000);
    for (int k = 0; k <= dots; ++k) {
      const double a = arc.from_rad + span * k / dots;
      const core::Vec2 p = arc.center_m + arc.radius_m * core::Vec2(std::sin(a), -std::cos(a));
      mesh.addDisk(to_px.toPixel(p), std::max(1.0, kArcDotRadius * s), withAlpha(arc.color, 0.8));
    }
  }
  for (const frame::StringModel& string : suspension.strings) {
    mesh.addLine(to_px.toPixel(string.pivot_m), to_px.toPixel(string.body_m),
                 frame::stringThicknessPx(layout), style.track);
  }
  for (const frame::SupportModel& bar : suspension.supports) {
    // A beam with its top hatched: the fixed support.
    const core::Vec2 a = to_px.toPixel(bar.from_m), b = to_px.toPixel(bar.to_m);
    const double thick = frame::kSupportThickness * s;
    mesh.addRect({std::min(a.x(), b.x()), a.y() - thick, std::max(a.x(), b.x()), a.y()},
                 style.track);
    const double spacing = kSupportHatchSpacing * s, length = frame::kSupportHatchLength * s;
    for (double x = std::min(a.x(), b.x()) + 0.5 * spacing; x < std::max(a.x(), b.x());
         x += spacing) {
      const core::Vec2 base{x, a.y() - thick};
      mesh.addLine(base, base + length * core::Vec2(0.7071, -0.7071), 0.5 * layout.track_px,
                   style.track);
    }
  }
  for (const frame::StringModel& string : suspension.strings) {
    mesh.addDisk(to_px.toPixel(string.pivot_m), frame::pivotRadiusPx(layout), style.track);
  }
}

void drawSuspensionOver(const frame::SuspensionModel& suspension, const frame::FrameStyle& style,
                        const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                        bool placed, Canvas& canvas) {
  ShapeSink& mesh = canvas.shapes();
  for (std::size_t d = 0; d < suspension.dimensions.size(); ++d) {
    const frame::DimensionModel& dim = suspension.dimensions[d];
    const std::string id = "dimension." + std::to_string(d + 1);
    std::optional<DrawnItemScope> item(std::in_place, mesh, id, "dimension");
    const frame::DimensionGeometry g = frame::dimensionGeometry(dim, layout, to_px);
    const core::Vec2 &low = g.low_px, &high = g.high_px;
    const double x = g.line_x_px, head = g.head_px;
    // Extension lines from the two heights out to the dimension line.
    for (int k : {0, 1}) mesh.addLine(g.lines[k].a, g.lines[k].b, g.thin_px, style.muted_text);
    // The dimension line with an arrowhead at each end, pointing at the extension lines.
    mesh.addLine({x, low.y() - head}, {x, high.y() + head}, g.thin_px, style.text);
    mesh.addTriangle({x, high.y()}, {x - 0.35 * head, high.y() + head},
                     {x + 0.35 * head, high.y() + head}, style.text);
    mesh.addTriangle({x, low.y()}, {x - 0.35 * head, low.y() - head},
                     {x + 0.35 * head, low.y() - head}, style.text);
    if (placed) {
      if (dim.label_at && !dim.label.empty()) {
        canvas.text(dim.label, dim.label_at->top_left_px, layout.text_px, style.text, HAlign::kLeft,
                    VAlign::kTop);
      }
    } else {
      // The label right of the line, or left of it where the frame ends first.
      const double wide = canvas.painter().width(dim.label, layout.text_px);
      const bool right = x + 0.6 * head + wide <= layout.width_px - 0.5 * head;
      const core::Vec2 at{right ? x + 0.6 * head : x - 0.6 * head, 0.5 * (low.y() + high.y())};
      canvas.text(dim.label, at, layout.text_px, style.text, right ? HAlign::kLeft : HAlign::kRight,
                  VAlign::kMiddle);
    }
    item.reset();
    if (placed && !dim.notes_at_px) continue;  // no free place for them at this size
    const DrawnItemScope notes(mesh, id + ".notes", "caption");
    core::Vec2 note_at = placed ? *dim.notes_at_px : to_px.toPixel(dim.notes_m);
    const std::vector<std::string>& lines =
        placed && !dim.notes_lines.empty() ? dim.notes_lines : dim.notes;
    const double notes_px = placed && dim.notes_px > 0.0 ? dim.notes_px : layout.text_px;
    for (const std::string& line : lines) {
      canvas.text(line, note_at, notes_px, style.text, HAlign::kLeft, VAlign::kTop);
      note_at.y() += 1.3 * notes_px;
    }
  }
}

}  // namespace collide::render
