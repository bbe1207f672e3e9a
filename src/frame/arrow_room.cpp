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

namespace {

// An arrow beside its body stands at most this many of its heads' widths farther off than
// touching distance: farther, it reads as another body's.
constexpr int kBesideFarthestHeads = 2;

// How far a line from `from` along `dir` (pixels, unit) runs before a wall's face or the box of
// another body than `body`, grown by pad_px, less a gap (infinity where nothing is in its way);
// `from` behind a wall's face or in such a box: no room. `own_box_free`: a body whose box holds
// `from` is no obstacle (the line starts at the body's centre).
double roomAlongPx(const core::Vec2& from, const core::Vec2& dir, const BodyModel& body,
                   const PanelModel& panel, const FrameLayout& layout, const WorldToPixel& to_px,
                   double pad_px, bool own_box_free) {
  double reach = std::numeric_limits<double>::infinity();
  for (const WallModel& wall : panel.walls) {
    const core::Vec2 normal{wall.normal.x(), -wall.normal.y()};
    const double ahead = (from - to_px.toPixel(wall.point_m)).dot(normal);
    if (!own_box_free && ahead < 0.5 * layout.track_px + pad_px) return 0.0;
    const double towards = dir.dot(normal);
    if (towards >= 0.0) continue;  // moving away from its face, or along it
    const double along = (to_px.toPixel(wall.point_m) - from).dot(normal) / towards;
    if (along >= 0.0) reach = std::min(reach, along - 0.5 * layout.track_px - pad_px);
  }
  const auto index = static_cast<int>(&body - panel.bodies.data());
  for (const BodyModel& other : panel.bodies) {
    // A body riding on this one (a bullet in its block) is drawn over it: the arrow speaks for
    // both.
    if (other.moves_with == index || (!own_box_free && &other == &body)) continue;
    const core::Vec2 centre = to_px.toPixel(other.center_m);
    const core::Vec2 half = drawnHalfBoxPx(other, layout, to_px) + core::Vec2::Constant(pad_px);
    const core::Vec2 lo = centre - half, hi = centre + half;
    if (from.x() >= lo.x() && from.x() <= hi.x() && from.y() >= lo.y() && from.y() <= hi.y()) {
      if (own_box_free) continue;
      return 0.0;
    }
    reach = std::min(reach, rayIntoBoxPx(from, dir, lo, hi));
  }
  return reach - layout.gap_px;
}

// The body's velocity direction in pixels (y down), unit.
core::Vec2 pixelDirection(const BodyModel& body) {
  return core::Vec2{body.velocity_mps.x(), -body.velocity_mps.y()}.normalized();
}

}  // namespace

double arrowRoomPx(const BodyModel& body, const PanelModel& panel, const FrameLayout& layout,
                   const WorldToPixel& to_px) {
  return roomAlongPx(to_px.toPixel(body.center_m), pixelDirection(body), body, panel, layout, to_px,
                     0.0, true);
}

core::Vec2 arrowBesideDirection(const core::Vec2& direction) {
  core::Vec2 across{direction.y(), -direction.x()};
  if (across.y() > 0.0 || (across.y() == 0.0 && across.x() > 0.0)) across = -across;
  return across;
}

ArrowShape arrowBesideOrInRoom(const ArrowShape& shape, double room_px, double hidden_px,
                               const BodyModel& body, const PanelModel& panel,
                               const FrameLayout& layout, const WorldToPixel& to_px) {
  // Straight on where it fits there, whole or with a break.
  const ArrowShape in_room = arrowInRoom(shape, room_px, hidden_px, layout);
  if (in_room.length_px > 0.0) return in_room;
  const core::Vec2 dir = pixelDirection(body);
  const core::Vec2 across = arrowBesideDirection(dir);
  // Whole and to its scale from its tail: nothing of it is under the body there.
  ArrowShape whole = arrowShape(body.velocity_mps.norm(), panel, layout, to_px);
  // Beside the body: its line clear of the body's drawn box by a gap and half the head.
  const core::Vec2 half = drawnHalfBoxPx(body, layout, to_px);
  const double pad = 0.5 * whole.head_width_px;
  const double beside =
      std::abs(across.x()) * half.x() + std::abs(across.y()) * half.y() + layout.gap_px + pad;
  if (!whole.off_scale && !whole.under_scale && whole.length_px > 0.0) {
    // Above first, as near the body as is clear (a ball swinging down into the row: its line
    // falls towards the next ball's top), then below.
    for (const double side : {1.0, -1.0}) {
      for (int farther = 0; farther <= kBesideFarthestHeads; ++farther) {
        const double off = beside + farther * whole.head_width_px;
        const core::Vec2 from = to_px.toPixel(body.center_m) + side * off * across;
        if (roomAlongPx(from, dir, body, panel, layout, to_px, pad, false) >= whole.length_px) {
          whole.beside_px = side * off;
          return whole;
        }
      }
    }
  }
  return in_room;
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
