// SPDX-License-Identifier: MIT
#include "frame/arrow_room.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace collide::frame {
namespace {

// The first point, pixels along `dir` (unit) from `from`, where the ray enters the box [lo, hi];
// infinity where it misses the box.
double rayIntoBoxPx(const core::Vec2& from, const core::Vec2& dir, const core::Vec2& lo,
                    const core::Vec2& hi) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  double enter = 0.0, leave = kInfinity;
  for (int k = 0; k < 2; ++k) {
    if (std::abs(dir[k]) < 1e-12) {
      if (from[k] <= lo[k] || from[k] >= hi[k]) return kInfinity;
      continue;
    }
    double near = (lo[k] - from[k]) / dir[k], far = (hi[k] - from[k]) / dir[k];
    if (near > far) std::swap(near, far);
    enter = std::max(enter, near);
    leave = std::min(leave, far);
  }
  return enter < leave ? enter : kInfinity;
}

}  // namespace

core::Vec2 drawnHalfBoxPx(const BodyModel& body, const FrameLayout& layout,
                          const WorldToPixel& to_px) {
  const core::Vec2 half = to_px.px_per_m * body.half_extent_m;
  if (body.shape == BodyShape::kDisk) {
    return core::Vec2{half.x(), half.x()} + core::Vec2::Constant(0.5 * layout.outline_px);
  }
  const double c = std::abs(std::cos(body.angle_rad)), s = std::abs(std::sin(body.angle_rad));
  return core::Vec2{half.x() * c + half.y() * s, half.x() * s + half.y() * c} +
         core::Vec2::Constant(0.5 * layout.outline_px);
}

double arrowRoomPx(const BodyModel& body, const PanelModel& panel, const FrameLayout& layout,
                   const WorldToPixel& to_px) {
  const core::Vec2 from = to_px.toPixel(body.center_m);
  const core::Vec2 dir = core::Vec2{body.velocity_mps.x(), -body.velocity_mps.y()}.normalized();
  double reach = std::numeric_limits<double>::infinity();
  for (const WallModel& wall : panel.walls) {
    const core::Vec2 normal{wall.normal.x(), -wall.normal.y()};
    const double towards = dir.dot(normal);
    if (towards >= 0.0) continue;  // moving away from its face, or along it
    const double along = (to_px.toPixel(wall.point_m) - from).dot(normal) / towards;
    if (along >= 0.0) reach = std::min(reach, along - 0.5 * layout.track_px);
  }
  const auto index = static_cast<int>(&body - panel.bodies.data());
  for (const BodyModel& other : panel.bodies) {
    // A body riding on this one (a bullet in its block) is drawn over it: the arrow speaks for
    // both.
    if (other.moves_with == index) continue;
    const core::Vec2 centre = to_px.toPixel(other.center_m);
    const core::Vec2 half = drawnHalfBoxPx(other, layout, to_px);
    const core::Vec2 lo = centre - half, hi = centre + half;
    if (from.x() >= lo.x() && from.x() <= hi.x() && from.y() >= lo.y() && from.y() <= hi.y()) {
      continue;
    }
    reach = std::min(reach, rayIntoBoxPx(from, dir, lo, hi));
  }
  return reach - layout.gap_px;
}

ArrowShape arrowInRoom(const ArrowShape& shape, double room_px, double hidden_px,
                       const FrameLayout& layout) {
  if (shape.length_px <= room_px) return shape;
  const double least = hidden_px + kArrowMinHeads * layout.arrow_head_length_px +
                       kArrowBreakOfHeadWidth * layout.arrow_head_width_px;
  // A below-scale mark is already as short as an arrow reads.
  if (shape.under_scale || !(room_px >= least)) return ArrowShape{};
  ArrowShape cut = shape;
  cut.length_px = room_px;
  cut.off_scale = true;
  cut.mark_from_px = hidden_px;  // the break just past the body (arrowBreak)
  const double head_share =
      std::clamp(kArrowHeadOfLength * room_px / std::max(layout.arrow_head_length_px, 1e-9),
                 kArrowHeadMinShare, 1.0);
  cut.head_length_px = head_share * layout.arrow_head_length_px;
  cut.head_width_px = std::max(layout.arrow_shaft_px, head_share * layout.arrow_head_width_px);
  return cut;
}

}  // namespace collide::frame
