// Where things go inside a panel once the frame's layout is chosen (frame/layout.cpp): the
// world's area and mapping, the momentum box, arrows, rulers and the bar's segment edges.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "frame/arrow_room.hpp"
#include "frame/layout.hpp"
#include "frame/mark_sizes.hpp"

namespace collide::frame {
namespace {

bool overlapsArea(const PixelRect& a, const PixelRect& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}
}  // namespace

namespace {

// The world's area with room for the ruler or without; `least`: never under a fifth of the scene.
PixelRect worldAreaWith(const PanelModel& panel, const PanelLayout& panel_layout,
                        const FrameLayout& layout, bool with_ruler, bool least = true) {
  const double line = kLineSpacing * layout.text_px;
  const double ruler = with_ruler ? kRulerTickLength * layout.scale_px + layout.gap_px +
                                        kLineSpacing * layout.small_px
                                  : 0.0;
  double top = layout.gap_px, bottom = layout.gap_px, left = 0.0;
  if (panel.two_d) {
    // Labels are placed around the bodies, inside the scene (compose's placement pass), so the
    // world takes the whole height but for the ruler: a plane scene fills its frame.
    bottom = layout.gap_px + ruler;
    if (with_ruler) left = 2.5 * layout.small_px + kRulerTickLength * layout.scale_px;
  } else {
    // Arrow and velocity label above the bodies; the track, mass labels and ruler below.
    top = layout.arrow_gap_px + 0.5 * layout.arrow_head_width_px + layout.gap_px +
          panel_layout.label_lines_above * line;
    // A printed figure's lines of labels: a gap from the scene's top edge too (its legend keeps
    // one from every edge), and over its arrows however high they are lifted (two blocks in
    // contact: one arrow a row up), so the lines keep their room.
    if (panel_layout.label_lines_below == 0) {
      int rows = 0;
      for (const BodyModel& body : panel.bodies) rows = std::max(rows, body.arrow_row);
      top += layout.gap_px + arrowLiftPx(rows, layout);
    }
    bottom = layout.track_px + layout.gap_px + panel_layout.label_lines_below * line + ruler;
  }
  const PixelRect& s = panel_layout.scene;
  PixelRect area{s.x0 + left, s.y0 + top, s.x1, s.y1 - bottom};
  // A momentum diagram in the scene's corner stands beside the world, never over a body.
  if (const std::optional<PixelRect> box = momentumBox(panel, panel_layout, layout)) {
    if (overlapsArea(*box, area)) area.x1 = std::max(area.x0 + 1.0, box->x0 - layout.gap_px);
  }
  // A printed figure's 1D scene (its labels' lines all above the arrows): the world, as high as
  // its width lets it be, stands at the foot of its area, so all the room to spare is above it,
  // where the labels go.
  if (!panel.two_d && panel_layout.label_lines_below == 0) {
    const double view_w = panel.view.max_m.x() - panel.view.min_m.x();
    const double view_h = panel.view.max_m.y() - panel.view.min_m.y();
    if (view_w > 0.0) area.y0 = std::max(area.y0, area.y1 - view_h * area.width() / view_w);
  }
  // Tiny panels: keep a fifth of the scene for the world rather than nothing.
  const double min_h = 0.2 * s.height();
  if (least && area.height() < min_h) {
    const double mid = 0.5 * (area.y0 + area.y1);
    area.y0 = std::max(s.y0, mid - 0.5 * min_h);
    area.y1 = area.y0 + min_h;
    // A printed figure's 1D world keeps its foot (its track stays over the bar's margin).
    if (!panel.two_d && panel_layout.label_lines_below == 0) {
      area.y1 = std::min(area.y1, s.y1);
      area.y0 = area.y1 - min_h;
    }
  }
  if (area.width() < 1.0) area.x1 = area.x0 + 1.0;
  return area;
}

// The room a 1D world's area has beyond the world's own height where its width sets its scale
// (a 1D scene is wide and flat), pixels; negative: too short for it.
double spareHeightPx(const PanelModel& panel, const PanelLayout& panel_layout,
                     const FrameLayout& layout, bool with_ruler) {
  const PixelRect area = worldAreaWith(panel, panel_layout, layout, with_ruler, false);
  const double view_w = panel.view.max_m.x() - panel.view.min_m.x();
  const double view_h = panel.view.max_m.y() - panel.view.min_m.y();
  return area.height() - (view_w > 0.0 ? view_h * area.width() / view_w : 0.0);
}

}  // namespace

bool drawsRuler(const PanelModel& panel, const PanelLayout& panel_layout,
                const FrameLayout& layout) {
  if (!panel.ruler) return false;
  if (panel.two_d) {
    // A printed figure's flat plane scene (a head-on shot along the table): a world that its
    // width scales (it fits the height with room to spare) but that leaves less than a line of
    // labels above and below it. The room is the labels' (a ball's mass and velocity have no
    // other place); the scale arrow still gives the scale. A world its height scales (a throw)
    // keeps its ruler, and so does every scene on a screen, whose text is small enough.
    const bool printed = layout.scale_px > layout.height_px;
    const double line = kLineSpacing * layout.text_px + 2.0 * layout.gap_px;
    const double spare_px = spareHeightPx(panel, panel_layout, layout, true);
    return !printed || spare_px < 0.0 || spare_px >= 2.0 * line;
  }
  if (panel_layout.label_lines_below > 0) return true;
  return spareHeightPx(panel, panel_layout, layout, true) >= 0.0;
}

PixelRect worldArea(const PanelModel& panel, const PanelLayout& panel_layout,
                    const FrameLayout& layout) {
  return worldAreaWith(panel, panel_layout, layout, drawsRuler(panel, panel_layout, layout));
}

std::optional<PixelRect> momentumBox(const PanelModel& panel, const PanelLayout& panel_layout,
                                     const FrameLayout& layout) {
  // Smaller than this many label ems, a box has no room for its title and its arrows' labels.
  constexpr double kLeastSideEm = 8.0;
  if (!panel.momentum || !(panel.momentum->full_scale_Ns > 0.0)) return std::nullopt;
  PixelRect box = panel_layout.momentum;
  if (!(box.height() > 0.0)) {
    const PixelRect& s = panel_layout.scene;
    const double side = std::round(
        std::min({kInsetSize * layout.scale_px, kInsetMaxShare * s.width(), s.height()}));
    box = {s.x1 - side, s.y0, s.x1, s.y0 + side};
  }
  if (std::min(box.width(), box.height()) < kLeastSideEm * layout.small_px) return std::nullopt;
  return box;
}

MomentumChainPlot momentumChainPlot(const MomentumDiagram& diagram, const PixelRect& box,
                                    const FrameLayout& layout) {
  MomentumChainPlot plot;
  const double size = layout.small_px, pad = 0.5 * size, line = std::round(kLineSpacing * size);
  const bool has_bar = diagram.scale_bar_Ns > 0.0 && !diagram.scale_bar_label.empty();
  // Room for an arrow's label (its line, 1.2 em, set off 0.2 em beyond half the drawn head's
  // width, and a tenth of an em to spare) above and below the chain, and for its half width at
  // either side.
  const double label_room = 1.5 * size + 0.3 * layout.arrow_head_width_px;
  plot.area = {box.x0 + pad + 1.5 * size, box.y0 + pad + line + label_room,
               box.x1 - pad - 1.5 * size, box.y1 - pad - (has_bar ? line : 0.0) - label_room};
  const double full = std::max(diagram.full_scale_Ns, 1e-12);
  core::Vec2 low = diagram.reach_low_Ns, high = diagram.reach_high_Ns;
  if (!(low.x() <= high.x() && low.y() <= high.y())) {
    low = core::Vec2::Constant(-full);
    high = core::Vec2::Constant(full);
  }
  plot.one_d = high.y() - low.y() <= 1e-12 * full;
  for (const MomentumArrow& arrow : diagram.arrows) {
    plot.one_d = plot.one_d && std::abs(arrow.momentum_Ns.y()) <= 1e-12 * full;
  }
  const double span_x = std::max(high.x() - low.x(), 1e-9 * full);
  const double span_y = plot.one_d ? 0.0 : std::max(high.y() - low.y(), 1e-9 * full);
  const double w = std::max(plot.area.width(), 1.0), h = std::max(plot.area.height(), 1.0);
  plot.px_per_Ns = span_y > 0.0 ? std::min(w / span_x, h / span_y) : w / span_x;
  // The reach centred in the plot (pixel y down).
  const core::Vec2 middle{0.5 * (plot.area.x0 + plot.area.x1), 0.5 * (plot.area.y0 + plot.area.y1)};
  plot.start_px = {middle.x() - plot.px_per_Ns * 0.5 * (low.x() + high.x()),
                   middle.y() + plot.px_per_Ns * 0.5 * (low.y() + high.y())};
  if (has_bar) {
    plot.scale_bar_px = diagram.scale_bar_Ns * plot.px_per_Ns;
    plot.scale_bar_y_px = box.y1 - pad - 0.5 * line;
  }
  return plot;
}

WorldToPixel panelMapping(const PanelModel& panel, const PanelLayout& panel_layout,
                          const FrameLayout& layout) {
  return fitView(panel.view, worldArea(panel, panel_layout, layout));
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

ArrowShape arrowShape(double speed_mps, const PanelModel& panel, const FrameLayout& layout,
                      const WorldToPixel& to_px, double hidden_px) {
  ArrowShape shape;
  if (!(speed_mps > 0.0) || panel.arrow_m_per_mps <= 0.0) return shape;
  double length = speed_mps * panel.arrow_m_per_mps * to_px.px_per_m;
  if (panel.arrow_max_length_m > 0.0 && length > panel.arrow_max_length_m * to_px.px_per_m) {
    length = panel.arrow_max_length_m * to_px.px_per_m;
    shape.off_scale = true;
  }
  const double head = std::max(layout.arrow_head_length_px, 1e-9);
  const double least = std::max(0.0, hidden_px) + kArrowMinHeads * head;
  if (length < least) {
    length = least;
    shape.under_scale = true;
    shape.mark_from_px = std::max(0.0, hidden_px);
  }
  shape.length_px = length;
  const double head_share = std::clamp(kArrowHeadOfLength * length / head, kArrowHeadMinShare, 1.0);
  shape.shaft_px = layout.arrow_shaft_px;
  shape.head_length_px = head_share * layout.arrow_head_length_px;
  shape.head_width_px = std::max(layout.arrow_shaft_px, head_share * layout.arrow_head_width_px);
  return shape;
}

ArrowShape scaleArrowShape(double speed_mps, const PanelModel& panel, const FrameLayout& layout,
                           const WorldToPixel& to_px) {
  ArrowShape shape;
  if (!(speed_mps > 0.0) || panel.arrow_m_per_mps <= 0.0) return shape;
  shape.length_px = speed_mps * panel.arrow_m_per_mps * to_px.px_per_m;
  const double head = std::max(layout.arrow_head_length_px, 1e-9);
  const double shrink = std::min(1.0, shape.length_px / head);
  const double head_share =
      std::clamp(kArrowHeadOfLength * shape.length_px / head, kArrowHeadMinShare, 1.0);
  shape.shaft_px = shrink * layout.arrow_shaft_px;
  shape.head_length_px = shrink * head_share * layout.arrow_head_length_px;
  shape.head_width_px =
      shrink * std::max(layout.arrow_shaft_px, head_share * layout.arrow_head_width_px);
  return shape;
}

ArrowShape bodyArrowShape(const BodyModel& body, const PanelModel& panel, const FrameLayout& layout,
                          const WorldToPixel& to_px) {
  // 2D arrows start at the body's centre: the part inside the body does not count as seen.
  double hidden_px = 0.0;
  if (panel.two_d) {
    hidden_px = to_px.px_per_m * (body.shape == BodyShape::kDisk
                                      ? body.half_extent_m.x()
                                      : std::max(body.half_extent_m.x(), body.half_extent_m.y()));
  }
  if (panel.two_d && body.arrow_hidden) return ArrowShape{};
  ArrowShape shape = arrowShape(body.velocity_mps.norm(), panel, layout, to_px, hidden_px);
  if (shape.length_px <= 0.0) return shape;
  // 2D: never through a wall, a cushion or another body (arrow_room.hpp); "below scale" only
  // where the arrow at its true length would not read.
  if (panel.two_d) {
    const double room_px = arrowRoomPx(body, panel, layout, to_px);
    if (shape.under_scale) {
      return arrowReadingOrMark(shape, room_px, hidden_px, body, panel, layout, to_px);
    }
    return arrowBesideOrInRoom(shape, room_px, hidden_px, body, panel, layout, to_px);
  }
  // 1D: the room before the nearest wall ahead that faces the body, less a gap; an arrow longer
  // than that is drawn back, its tip there (shortened, it would misstate the speed).
  const double direction = body.velocity_mps.x() >= 0.0 ? 1.0 : -1.0;
  const double center_x = to_px.toPixel(body.center_m).x();
  double room = std::numeric_limits<double>::infinity();
  for (const WallModel& wall : panel.walls) {
    if (wall.normal.x() * direction >= 0.0) continue;  // the body moves away from its face
    const double ahead = (to_px.toPixel(wall.point_m).x() - center_x) * direction;
    if (ahead >= 0.0) room = std::min(room, ahead - layout.gap_px);
  }
  shape.tail_back_px = std::max(0.0, shape.length_px - room);
  return shape;
}

core::Vec2 bodyArrowTailPx(const BodyModel& body, const PanelModel& panel,
                           const FrameLayout& layout, const WorldToPixel& to_px,
                           const ArrowShape& shape) {
  const core::Vec2 center = to_px.toPixel(body.center_m);
  if (panel.two_d) {
    if (shape.beside_px == 0.0 && shape.tail_ahead_px == 0.0) return center;
    const core::Vec2 dir = core::Vec2{body.velocity_mps.x(), -body.velocity_mps.y()}.normalized();
    return center + shape.tail_ahead_px * dir + shape.beside_px * arrowBesideDirection(dir);
  }
  const double direction = body.velocity_mps.x() >= 0.0 ? 1.0 : -1.0;
  return {center.x() - direction * shape.tail_back_px, arrowLineYPx(panel, body, layout, to_px)};
}

double arrowLiftPx(int row, const FrameLayout& layout) {
  return std::max(0, row) * (layout.arrow_head_width_px + layout.gap_px);
}

double arrowLineYPx(const PanelModel& panel, const BodyModel& body, const FrameLayout& layout,
                    const WorldToPixel& to_px) {
  const auto top = [&](const BodyModel& b) {
    return to_px.toPixel(b.center_m + core::Vec2{0.0, b.half_extent_m.y()}).y();
  };
  if (body.arrow_row <= 0) return top(body) - layout.arrow_gap_px;
  double highest = top(body);
  for (const BodyModel& other : panel.bodies) highest = std::min(highest, top(other));
  return highest - layout.arrow_gap_px - arrowLiftPx(body.arrow_row, layout);
}

double captionScaleRoomPx(const PanelModel& panel, const PanelLayout& panel_layout,
                          const FrameLayout& layout, const text::TextWidth& width) {
  if (!(panel.scale_arrow_mps > 0.0) || panel.scale_arrow_label.empty()) return 0.0;
  const ArrowShape shape = scaleArrowShape(panel.scale_arrow_mps, panel, layout,
                                           panelMapping(panel, panel_layout, layout));
  if (shape.length_px <= 0.0) return 0.0;
  return shape.length_px + layout.gap_px + width(panel.scale_arrow_label, layout.small_px) +
         layout.text_px;
}

ArrowBreak arrowBreak(const ArrowShape& shape) {
  const double gap = kArrowBreakOfHeadWidth * shape.head_width_px;
  // In the visible part of the shaft: past the body a 2D arrow starts in (mark_from_px).
  const double start =
      std::max(0.4 * (shape.length_px - shape.head_length_px) - 0.5 * gap, shape.mark_from_px);
  return {std::max(0.0, start), std::max(0.0, start) + gap};
}

RulerAxis rulerAxis(double lo_m, double hi_m, double px_per_m, double min_spacing_px) {
  RulerAxis axis;
  axis.from_m = std::min(lo_m, hi_m);
  axis.to_m = std::max(lo_m, hi_m);
  if (!(px_per_m > 0.0) || !std::isfinite(axis.to_m - axis.from_m)) return axis;
  // The smallest of 1, 2, 5 × 10^k metres at least min_spacing_px apart.
  const double min_step_m = std::max(min_spacing_px, 1.0) / px_per_m;
  const double power = std::pow(10.0, std::floor(std::log10(min_step_m)));
  axis.step_m = 10.0 * power;
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * power >= min_step_m * (1.0 - 1e-9)) {
      axis.step_m = m * power;
      break;
    }
  }
  constexpr int kMostTicks = 200;  // a degenerate range never loops long
  const double first = std::ceil(axis.from_m / axis.step_m - 1e-9);
  for (int k = 0; k < kMostTicks; ++k) {
    const double tick_m = (first + k) * axis.step_m;
    if (tick_m > axis.to_m + 1e-9 * axis.step_m) break;
    axis.ticks_m.push_back(tick_m);
  }
  if (axis.ticks_m.size() < 2) axis.ticks_m.clear();
  return axis;
}

double verticalRulerX(const PanelModel& panel, const WorldToPixel& to_px, const PixelRect& area,
                      const FrameLayout& layout) {
  // Where the area is wider than the world, half the room beside it goes between the ruler and
  // the world: labels of bodies at the world's left edge fit there.
  const double world_x0 = to_px.toPixel(panel.view.min_m).x();
  const double room = std::max(0.0, world_x0 - area.x0);
  return world_x0 - 0.5 * room - 0.5 * layout.gap_px;
}

std::vector<double> barSegmentEdgesPx(const EnergyBar& bar, const PixelRect& inner) {
  COLLIDE_ASSERT(bar.full_scale_J > 0.0, "energy bar full scale must be positive");
  std::vector<double> edges;
  edges.reserve(bar.segments.size() + 1);
  edges.push_back(inner.x0);
  // Cumulative sums, not per-segment lengths, so neighbours share one edge: no gaps, no overlap.
  double cumulative_J = 0.0;
  for (const EnergySegment& segment : bar.segments) {
    if (!segment.strip) cumulative_J += std::max(0.0, segment.energy_J);
    const double x = inner.x0 + inner.width() * (cumulative_J / bar.full_scale_J);
    edges.push_back(std::clamp(x, inner.x0, inner.x1));
  }
  return edges;
}

PixelRect barStripPx(const EnergyBar& bar, const EnergySegment& strip, const PixelRect& inner) {
  COLLIDE_ASSERT(bar.full_scale_J > 0.0, "energy bar full scale must be positive");
  const auto at = [&](double energy_J) {
    return std::clamp(inner.x0 + inner.width() * (energy_J / bar.full_scale_J), inner.x0, inner.x1);
  };
  const double from_J = std::max(0.0, strip.from_J);
  return {at(from_J), inner.y1 - kBarStripShare * inner.height(),
          at(from_J + std::max(0.0, strip.energy_J)), inner.y1};
}

std::vector<double> spreadIntervals(const std::vector<double>& wanted_centers,
                                    const std::vector<double>& widths, double gap, double lo,
                                    double hi) {
  COLLIDE_ASSERT(wanted_centers.size() == widths.size(), "spreadIntervals: sizes differ");
  // Placed in the order of their wishes (ties keep their given order), returned in the given order.
  std::vector<std::size_t> order(widths.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return wanted_centers[a] < wanted_centers[b];
  });
  // Clusters of touching intervals; each sits where the mean of its members' wishes puts it,
  // clamped to [lo, hi]. Merging neighbours that overlap until none do gives the least-squares
  // placement for a fixed order.
  struct Cluster {
    std::size_t first, count;
    double total_w, wish_sum, x0;
  };
  std::vector<Cluster> clusters;
  const auto place = [&](Cluster& c) {
    c.x0 = c.wish_sum / c.count;
    c.x0 = std::min(c.x0, hi - c.total_w);
    c.x0 = std::max(c.x0, lo);
  };
  for (std::size_t i = 0; i < widths.size(); ++i) {
    const std::size_t k = order[i];
    Cluster c{i, 1, widths[k], wanted_centers[k] - 0.5 * widths[k], 0.0};
    place(c);
    clusters.push_back(c);
    while (clusters.size() > 1) {
      Cluster& prev = clusters[clusters.size() - 2];
      Cluster& last = clusters.back();
      if (prev.x0 + prev.total_w + gap <= last.x0) break;
      // Member k of the merged cluster starts at x0 + (widths and gaps before it), so its wish
      // for x0 is its own wish minus that offset.
      const double offset = prev.total_w + gap;
      prev.wish_sum += last.wish_sum - offset * last.count;
      prev.total_w += gap + last.total_w;
      prev.count += last.count;
      clusters.pop_back();
      place(clusters.back());
    }
  }
  std::vector<double> x0s(widths.size());
  for (const Cluster& c : clusters) {
    double x = c.x0;
    for (std::size_t i = c.first; i < c.first + c.count; ++i) {
      x0s[order[i]] = x;
      x += widths[order[i]] + gap;
    }
  }
  return x0s;
}

}  // namespace collide::frame
