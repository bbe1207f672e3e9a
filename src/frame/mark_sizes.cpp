#include "frame/mark_sizes.hpp"

#include <algorithm>
#include <numbers>

namespace collide::frame {

bool tagFitsInside(const BodyModel& body, const FrameLayout& layout, const WorldToPixel& to_px) {
  const double inner = body.shape == BodyShape::kDisk
                           ? body.half_extent_m.x()
                           : std::min(body.half_extent_m.x(), body.half_extent_m.y());
  return to_px.px_per_m * inner >= 0.45 * layout.small_px;
}

core::Vec2 tagCenterPx(const PanelModel& panel, std::size_t index, const core::Vec2& center_px,
                       const WorldToPixel& to_px) {
  core::Vec2 away{0.0, 0.0};
  for (const BondModel& bond : panel.bonds) {
    const int self = static_cast<int>(index);
    if (bond.body_a != self && bond.body_b != self) continue;
    const int partner = bond.body_a == self ? bond.body_b : bond.body_a;
    if (partner < 0 || partner >= static_cast<int>(panel.bodies.size()) || partner == self)
      continue;
    const core::Vec2 to_partner =
        to_px.toPixel(panel.bodies[static_cast<std::size_t>(partner)].center_m) - center_px;
    if (to_partner.norm() > 0.0) away -= to_partner.normalized();
  }
  if (!(away.norm() > 1e-9)) return center_px;
  const BodyModel& body = panel.bodies[index];
  const double inner = body.shape == BodyShape::kDisk
                           ? body.half_extent_m.x()
                           : std::min(body.half_extent_m.x(), body.half_extent_m.y());
  return center_px + 0.5 * to_px.px_per_m * inner * away.normalized();
}

double flashRadiusPx(const FlashModel& flash, const FrameLayout& layout,
                     const WorldToPixel& to_px) {
  const double strength = std::clamp(flash.strength, 0.0, 1.0);
  double radius = kFlashRadius * layout.scale_px * (0.6 + 0.4 * strength);
  if (flash.max_radius_m > 0.0) radius = std::min(radius, flash.max_radius_m * to_px.px_per_m);
  return radius;
}

namespace {

// An extension line along `across` (the axis the line is measured across) from `point` to a
// little past the dimension line at `line_at` on that axis, on the side away from the point.
PixelSegment extensionLine(const core::Vec2& point, double line_at, int across, double over) {
  core::Vec2 end = point;
  end[across] = line_at + (line_at >= point[across] ? over : -over);
  return {point, end};
}

}  // namespace

DimensionGeometry dimensionGeometry(const DimensionModel& dim, const FrameLayout& layout,
                                    const WorldToPixel& to_px) {
  DimensionGeometry g;
  g.horizontal = dim.axis == DimensionAxis::kHorizontal;
  g.from_px = to_px.toPixel(dim.from_m);
  g.to_px = to_px.toPixel(dim.to_m);
  const int across = g.horizontal ? 1 : 0;  // pixel axis the line's place is read on
  const double line_at = g.horizontal ? to_px.toPixel({0.0, dim.line_at_m}).y()
                                      : to_px.toPixel({dim.line_at_m, 0.0}).x();
  g.from_tip_px = g.from_px;
  g.from_tip_px[across] = line_at;
  g.to_tip_px = g.to_px;
  g.to_tip_px[across] = line_at;
  g.head_px = kDimensionHead * layout.scale_px;
  g.thin_px = std::max(1.0, 0.5 * layout.line_px);
  const double over = kExtensionOverrun * layout.scale_px;
  // Heads inside need room for both and a little line between them.
  const double span = (g.to_tip_px - g.from_tip_px).norm();
  g.heads_outside = span < 2.5 * g.head_px;
  core::Vec2 a = g.from_tip_px, b = g.to_tip_px;
  if (g.heads_outside) {
    const core::Vec2 along = span > 0.0
                                 ? core::Vec2((b - a) / span)
                                 : core::Vec2(g.horizontal ? 1.0 : 0.0, g.horizontal ? 0.0 : -1.0);
    a -= g.head_px * along;
    b += g.head_px * along;
  }
  g.lines = {extensionLine(g.from_px, line_at, across, over),
             extensionLine(g.to_px, line_at, across, over), PixelSegment{a, b}};
  return g;
}

double stringThicknessPx(const FrameLayout& layout) {
  return std::max(1.0, 0.6 * layout.line_px);
}

PixelRect supportBoxPx(const SupportModel& support, const FrameLayout& layout,
                       const WorldToPixel& to_px) {
  const core::Vec2 a = to_px.toPixel(support.from_m), b = to_px.toPixel(support.to_m);
  // The beam hangs under its line's height; the hatching rises above it (strokes at 45°).
  const double thick = kSupportThickness * layout.scale_px;
  const double hatch = kSupportHatchLength * layout.scale_px * std::numbers::sqrt2 / 2.0;
  return {std::min(a.x(), b.x()), a.y() - thick - hatch, std::max(a.x(), b.x()) + hatch, a.y()};
}

double pivotRadiusPx(const FrameLayout& layout) {
  return std::max(1.5, kPivotRadius * layout.scale_px);
}

RulerPlacement rulerPlacement(const PanelModel& panel, const PanelLayout& where,
                              const FrameLayout& layout, const WorldToPixel& to_px,
                              const PixelRect& area) {
  RulerPlacement ruler;
  const double h = layout.scale_px, tick = kRulerTickLength * h;
  // The drawn region: the view window, cut to the area (equal aspect leaves one direction wider).
  const core::Vec2 area_lo = to_px.toWorld({area.x0, area.y1});
  const core::Vec2 area_hi = to_px.toWorld({area.x1, area.y0});
  const core::Vec2 lo = panel.view.min_m.cwiseMax(area_lo);
  const core::Vec2 hi = panel.view.max_m.cwiseMin(area_hi);
  // Horizontal scale: 1D right under the mass labels, 2D along the bottom of the scene.
  ruler.along_x = rulerAxis(lo.x(), hi.x(), to_px.px_per_m, kRulerMinStep * h);
  ruler.x_axis_y_px = where.scene.y1 - layout.small_px * 1.3 - tick;
  if (!panel.two_d) {
    ruler.x_axis_y_px =
        std::min(ruler.x_axis_y_px, to_px.toPixel({0.0, panel.track_y_m}).y() + layout.track_px +
                                        2.0 * layout.gap_px +
                                        where.label_lines_below * kLineSpacing * layout.text_px);
    return ruler;
  }
  // Right under the drawn region where the world is narrower than its area (it fills the width).
  ruler.x_axis_y_px =
      std::min(ruler.x_axis_y_px, to_px.toPixel({0.0, lo.y()}).y() + 2.0 * layout.gap_px);
  // Vertical scale along the left edge, over the drawn heights only.
  ruler.along_y = rulerAxis(lo.y(), hi.y(), to_px.px_per_m, kRulerMinStep * h);
  ruler.y_axis_x_px = verticalRulerX(panel, to_px, area, layout);
  return ruler;
}

}  // namespace collide::frame
