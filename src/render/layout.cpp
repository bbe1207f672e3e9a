#include "render/layout.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace collide::render {
namespace {

// Fractions of the frame height. Tuned at 360 px high: margin 14 px, bar 25 px, labels band 22 px.
constexpr double kMargin = 0.04;       // frame edge to content, and scene to bar
constexpr double kBarHeight = 0.07;    // outer height of the energy bar
constexpr double kLabelBand = 0.06;    // room below the bar kept for segment labels (text later)
constexpr double kBarFrame = 0.006;    // bar frame thickness
constexpr double kOutline = 0.005;     // body outline thickness
constexpr double kTrack = 0.006;       // track line thickness
constexpr double kArrowGap = 0.045;    // body top → arrow centre line
constexpr double kArrowShaft = 0.008;  // shaft thickness
constexpr double kArrowHeadLength = 0.035;
constexpr double kArrowHeadWidth = 0.04;

}  // namespace

FrameLayout computeFrameLayout(int width_px, int height_px) {
  COLLIDE_ASSERT(width_px > 0 && height_px > 0, "frame size must be positive");
  const double h = height_px;
  FrameLayout layout;
  layout.width_px = width_px;
  layout.height_px = height_px;

  // The bar is snapped to whole pixels so its inner length, and thus every segment boundary, is
  // exactly computable from barSegmentEdgesPx.
  const double margin = std::round(kMargin * h);
  const double bar_height = std::max(3.0, std::round(kBarHeight * h));
  const double label_band = std::round(kLabelBand * h);
  layout.bar_frame_px = std::max(1.0, std::round(kBarFrame * h));
  layout.bar_outer.x0 = margin;
  layout.bar_outer.x1 = std::max(margin + 3.0, width_px - margin);
  layout.bar_outer.y1 = h - margin - label_band;
  layout.bar_outer.y0 = layout.bar_outer.y1 - bar_height;
  const double f = layout.bar_frame_px;
  layout.bar_inner = {layout.bar_outer.x0 + f, layout.bar_outer.y0 + f, layout.bar_outer.x1 - f,
                      layout.bar_outer.y1 - f};

  layout.scene = {margin, margin, width_px - margin,
                  std::max(margin, layout.bar_outer.y0 - margin)};
  // World things may stray into the margins (an arrow above a tall body) but never onto the bar.
  layout.world_clip_y1_px =
      static_cast<int>(std::round(0.5 * (layout.scene.y1 + layout.bar_outer.y0)));

  layout.outline_px = kOutline * h;
  layout.track_px = kTrack * h;
  layout.arrow_gap_px = kArrowGap * h;
  layout.arrow_shaft_px = kArrowShaft * h;
  layout.arrow_head_length_px = kArrowHeadLength * h;
  layout.arrow_head_width_px = kArrowHeadWidth * h;
  return layout;
}

WorldToPixel fitView(const ViewWindow& view, const PixelRect& area) {
  const double view_w = view.max_m.x() - view.min_m.x();
  const double view_h = view.max_m.y() - view.min_m.y();
  COLLIDE_ASSERT(view_w > 0.0 || view_h > 0.0, "view window is empty");
  double scale = HUGE_VAL;
  if (view_w > 0.0) scale = std::min(scale, area.width() / view_w);
  if (view_h > 0.0) scale = std::min(scale, area.height() / view_h);

  WorldToPixel mapping;
  mapping.px_per_m = scale;
  const core::Vec2 view_center_m = 0.5 * (view.min_m + view.max_m);
  const core::Vec2 area_center_px{0.5 * (area.x0 + area.x1), 0.5 * (area.y0 + area.y1)};
  mapping.origin_px = {area_center_px.x() - scale * view_center_m.x(),
                       area_center_px.y() + scale * view_center_m.y()};
  return mapping;
}

std::vector<double> barSegmentEdgesPx(const EnergyBar& bar, const PixelRect& inner) {
  COLLIDE_ASSERT(bar.full_scale_J > 0.0, "energy bar full scale must be positive");
  std::vector<double> edges;
  edges.reserve(bar.segments.size() + 1);
  edges.push_back(inner.x0);
  // Cumulative sums, not per-segment lengths, so neighbours share one edge: no gaps, no overlap.
  double cumulative_J = 0.0;
  for (const EnergySegment& segment : bar.segments) {
    cumulative_J += std::max(0.0, segment.energy_J);
    const double x = inner.x0 + inner.width() * (cumulative_J / bar.full_scale_J);
    edges.push_back(std::clamp(x, inner.x0, inner.x1));
  }
  return edges;
}

}  // namespace collide::render
