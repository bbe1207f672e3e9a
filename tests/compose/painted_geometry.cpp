#include "painted_geometry.hpp"

#include <algorithm>
#include <cmath>

#include "frame/mark_sizes.hpp"

namespace collide::compose_test {

std::vector<PixelBody> paintedBodies(const frame::PanelModel& panel,
                                     const frame::WorldToPixel& to_px) {
  std::vector<PixelBody> bodies;
  for (const frame::BodyModel& body : panel.bodies) {
    const core::Vec2 c = to_px.toPixel(body.center_m);
    const double hx = to_px.px_per_m * body.half_extent_m.x();
    const bool disk = body.shape == frame::BodyShape::kDisk;
    const double hy = disk ? hx : to_px.px_per_m * body.half_extent_m.y();
    bodies.push_back({disk, c, {hx, hy}});
  }
  return bodies;
}

namespace {

// How far from `from` along `d` (unit, pixels) body `self`'s arrow reaches before a wall's face
// (its line half a track wide) or the box of another body (its outline half a line wide) less
// a gap; bodies whose box holds `from` do not count.
double reachBeforeObstacle(const frame::PanelModel& panel, const frame::FrameLayout& layout,
                           const frame::WorldToPixel& to_px, std::size_t self,
                           const core::Vec2& from, const core::Vec2& d) {
  double reach = INFINITY;
  for (const frame::WallModel& wall : panel.walls) {
    const core::Vec2 n{wall.normal.x(), -wall.normal.y()};
    if (d.dot(n) >= 0.0) continue;
    const double along = (to_px.toPixel(wall.point_m) - from).dot(n) / d.dot(n);
    if (along >= 0.0) reach = std::min(reach, along - 0.5 * layout.track_px);
  }
  for (std::size_t k = 0; k < panel.bodies.size(); ++k) {
    const frame::BodyModel& other = panel.bodies[k];
    const core::Vec2 c = to_px.toPixel(other.center_m);
    const double hx = to_px.px_per_m * other.half_extent_m.x();
    const bool disk = other.shape == frame::BodyShape::kDisk;
    const double hy = disk ? hx : to_px.px_per_m * other.half_extent_m.y();
    const double cos_a = disk ? 1.0 : std::abs(std::cos(other.angle_rad));
    const double sin_a = disk ? 0.0 : std::abs(std::sin(other.angle_rad));
    const core::Vec2 half = core::Vec2{hx * cos_a + hy * sin_a, hx * sin_a + hy * cos_a} +
                            core::Vec2::Constant(0.5 * layout.outline_px);
    const core::Vec2 lo = c - half, hi = c + half;
    if (k == self ||
        (from.x() >= lo.x() && from.x() <= hi.x() && from.y() >= lo.y() && from.y() <= hi.y())) {
      continue;
    }
    // The ray's entry into the box (slabs).
    double enter = 0.0, leave = INFINITY;
    bool misses = false;
    for (int a = 0; a < 2; ++a) {
      if (std::abs(d[a]) < 1e-12) {
        misses = misses || from[a] <= lo[a] || from[a] >= hi[a];
        continue;
      }
      const double t0 = (lo[a] - from[a]) / d[a], t1 = (hi[a] - from[a]) / d[a];
      enter = std::max(enter, std::min(t0, t1));
      leave = std::min(leave, std::max(t0, t1));
    }
    if (!misses && enter < leave) reach = std::min(reach, enter);
  }
  return reach - layout.gap_px;
}

}  // namespace

std::vector<PaintedArrow> paintedArrows(const frame::PanelModel& panel,
                                        const frame::FrameLayout& layout,
                                        const frame::WorldToPixel& to_px) {
  const std::vector<PixelBody> outlines = paintedBodies(panel, to_px);
  std::vector<PaintedArrow> arrows;
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    const frame::BodyModel& body = panel.bodies[i];
    const core::Vec2 c = outlines[i].center;
    const double hx = outlines[i].half.x(), hy = outlines[i].half.y();
    const double speed = body.velocity_mps.norm();
    if (speed > 1e-6 && panel.arrow_m_per_mps > 0.0 && body.moves_with < 0) {
      const core::Vec2 d{body.velocity_mps.x() / speed, -body.velocity_mps.y() / speed};
      // 1D: above the body; a lifted arrow (arrow_row r) r rows of a head's width and a gap
      // above the tallest body's arrow line.
      double line_y = c.y() - hy - layout.arrow_gap_px;
      if (body.arrow_row > 0) {
        for (const frame::BodyModel& other : panel.bodies) {
          line_y =
              std::min(line_y, to_px.toPixel(other.center_m).y() -
                                   to_px.px_per_m * other.half_extent_m.y() - layout.arrow_gap_px);
        }
        line_y -= body.arrow_row * (layout.arrow_head_width_px + layout.gap_px);
      }
      core::Vec2 tail = panel.two_d ? c : core::Vec2{c.x(), line_y};
      // To scale, but never longer than the panel's off-scale limit nor shorter than the
      // painter's visible minimum: one head length, in 2D beyond the disk's edge.
      const double least =
          1.0 * layout.arrow_head_length_px + (panel.two_d ? std::max(hx, hy) : 0.0);
      double length = speed * panel.arrow_m_per_mps * to_px.px_per_m;
      if (panel.arrow_max_length_m > 0.0) {
        length = std::min(length, panel.arrow_max_length_m * to_px.px_per_m);
      }
      // 2D: one that reads at its true length (a head or more) but would not clear the body
      // from its centre is drawn that long from the body's edge, or beside it, or not at all
      // (where it stands is the painter's; ArrowReadingTest and VideoFramesTest check that it
      // stands by its body, crosses nothing and keeps its scale).
      // So is one the layout over time asks to be drawn beside its body first, or not at all
      // (frame::BodyModel's arrow_beside_first and arrow_hidden: compose/arrow_forms.hpp).
      if (panel.two_d && body.arrow_hidden) continue;
      const bool short_of_its_body = length >= layout.arrow_head_length_px && length < least;
      if (panel.two_d && (short_of_its_body || body.arrow_beside_first)) {
        const frame::ArrowShape drawn = frame::bodyArrowShape(body, panel, layout, to_px);
        if (drawn.length_px <= 0.0) continue;
        if (drawn.beside_px != 0.0 || drawn.tail_ahead_px > 0.0) {
          tail = frame::bodyArrowTailPx(body, panel, layout, to_px, drawn);
          arrows.push_back({tail, tail + drawn.length_px * d, 0.5 * layout.arrow_head_width_px, i});
          continue;
        }
      }
      length = std::max(length, least);
      // 1D: one that would reach the face of a wall it moves towards is drawn back, its tip a
      // gap short of it.
      double room = INFINITY;
      for (const frame::WallModel& wall : panel.walls) {
        const double ahead = (to_px.toPixel(wall.point_m).x() - c.x()) * d.x();
        if (!panel.two_d && wall.normal.x() * d.x() < 0.0 && ahead >= 0.0) {
          room = std::min(room, ahead - layout.gap_px);
        }
      }
      // 2D: one that would reach a wall's face or another body's box stops a gap short of it,
      // where that leaves a head and its break past the body; else it is not drawn.
      if (panel.two_d) {
        double reach = reachBeforeObstacle(panel, layout, to_px, i, c, d);
        if (length > reach) {
          if (reach <
              std::max(hx, hy) + layout.arrow_head_length_px + 0.6 * layout.arrow_head_width_px) {
            // No room straight on: drawn beside the body where that is clear, whole (where it
            // stands is the painter's; PictureReadingTest and VideoFramesTest check that it
            // crosses nothing and keeps its scale).
            const frame::ArrowShape beside = frame::bodyArrowShape(body, panel, layout, to_px);
            if (beside.beside_px == 0.0 || beside.length_px <= 0.0) continue;
            tail = frame::bodyArrowTailPx(body, panel, layout, to_px, beside);
            reach = beside.length_px;
          }
          length = reach;
        }
      }
      const core::Vec2 start = tail - std::max(0.0, length - room) * d;
      arrows.push_back({start, start + length * d, 0.5 * layout.arrow_head_width_px, i});
    }
  }
  return arrows;
}

std::vector<PaintedMark> paintedMarks(const frame::PanelModel& panel,
                                      const frame::FrameLayout& layout,
                                      const frame::WorldToPixel& to_px,
                                      const frame::PixelRect& area, int width_px, int height_px) {
  // Walls (their line and hatching: a track-width line twice as thick and strokes of the hatch
  // length on the solid side) and contact flashes, as the painter draws them.
  std::vector<PaintedMark> marks;
  const double wall_half = 2.0 * layout.track_px + frame::kWallHatchLength * layout.scale_px;
  for (const frame::WallModel& wall : panel.walls) {
    const core::Vec2 w = to_px.toPixel(wall.point_m);
    if (!panel.two_d) {
      marks.push_back({{w.x(), to_px.toPixel({0.0, panel.track_y_m}).y()},
                       {w.x(), area.y0},
                       wall_half,
                       "a wall"});
    } else {
      const core::Vec2 along{wall.normal.y(), wall.normal.x()};
      const double reach = 2.0 * (width_px + height_px);
      marks.push_back({w - reach * along, w + reach * along, wall_half, "a wall"});
    }
  }
  for (const frame::FlashModel& flash : panel.flashes) {
    const core::Vec2 f = to_px.toPixel(flash.center_m);
    marks.push_back({f, f, frame::flashRadiusPx(flash, layout, to_px), "a flash"});
  }
  // Strings (lines 0.6 of the line width thick, at least a pixel), their pivots, and the
  // beams they hang from (a beam under its line's height, hatched above with strokes at 45°).
  for (const frame::StringModel& string : panel.suspension.strings) {
    const core::Vec2 pivot = to_px.toPixel(string.pivot_m);
    marks.push_back({pivot, to_px.toPixel(string.body_m), 0.5 * std::max(1.0, 0.6 * layout.line_px),
                     "a string"});
    marks.push_back(
        {pivot, pivot, std::max(1.5, frame::kPivotRadius * layout.scale_px), "a string's pivot"});
  }
  for (const frame::SupportModel& support : panel.suspension.supports) {
    const core::Vec2 a = to_px.toPixel(support.from_m), b = to_px.toPixel(support.to_m);
    const double beam = frame::kSupportThickness * layout.scale_px;
    const double hatch = frame::kSupportHatchLength * layout.scale_px / std::sqrt(2.0);
    // As a thick segment through the middle of the beam and its hatching.
    const double half = 0.5 * (beam + hatch), y = a.y() - half;
    marks.push_back({{std::min(a.x(), b.x()) + half, y},
                     {std::max(a.x(), b.x()) + hatch - half, y},
                     half,
                     "the beam strings hang from"});
  }
  return marks;
}

}  // namespace collide::compose_test
