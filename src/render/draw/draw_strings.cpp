// Bodies on strings: the bar the strings hang from, the strings and dotted arc trails.
#include <algorithm>
#include <cmath>
#include <numbers>

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

}  // namespace collide::render
