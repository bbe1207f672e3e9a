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

// The places tried beside a body stand this share of a head's width apart, nearest first.
constexpr double kBesideStepHeads = 0.25;

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

// Whether the segment from `from` to `to` (pixels) lies in the panel's view window, which the
// scene's area holds whole: an arrow beyond it would be cut at the scene's edge.
bool inViewPx(const core::Vec2& from, const core::Vec2& to, const PanelModel& panel,
              const WorldToPixel& to_px) {
  const core::Vec2 a = to_px.toPixel(panel.view.min_m), b = to_px.toPixel(panel.view.max_m);
  const core::Vec2 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  const auto inside = [&](const core::Vec2& p) {
    return p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y();
  };
  return inside(from) && inside(to);
}

// Half the body's drawn extent across `across` (pixels, unit): a disk's radius, else the support
// of its drawn box; half its outline included.
double halfAcrossPx(const BodyModel& body, const core::Vec2& across, const FrameLayout& layout,
                    const WorldToPixel& to_px) {
  const core::Vec2 half = drawnHalfBoxPx(body, layout, to_px);
  if (body.shape == BodyShape::kDisk) return half.x();
  return std::abs(across.x()) * half.x() + std::abs(across.y()) * half.y();
}

// `whole` (to its scale, from its tail) placed beside `body` (ArrowShape::beside_px): its line
// clear of the body's outline by a gap and half its head, or up to kArrowBesideReachHeads head
// widths and a gap off it (a ball swinging down into the row: its line falls towards the next
// ball's top), above first, then below, where nothing is in its way and it stays in the view.
// Where no such place holds it from beside the centre on, the same places drawn back
// (ArrowShape::tail_ahead_px < 0), its tip a gap short of what stops it ahead, as a 1D arrow is
// drawn back from a wall: a ball running into a cushion keeps its arrow, whole and to its scale,
// beside it up to the cushion (billiards-break's pink ball at 0.217-0.233 s had none).
// False where there is no such place.
bool placeBeside(ArrowShape& whole, const BodyModel& body, const PanelModel& panel,
                 const FrameLayout& layout, const WorldToPixel& to_px) {
  const core::Vec2 dir = pixelDirection(body);
  const core::Vec2 across = arrowBesideDirection(dir);
  const core::Vec2 centre = to_px.toPixel(body.center_m);
  const double pad = 0.5 * whole.head_width_px;
  const double outline = halfAcrossPx(body, across, layout, to_px) + layout.gap_px;
  const double step = kBesideStepHeads * layout.arrow_head_width_px;
  const double farthest = kArrowBesideReachHeads * layout.arrow_head_width_px;
  for (const bool drawn_back : {false, true}) {
    for (const double side : {1.0, -1.0}) {
      for (double off = pad; off <= farthest + 1e-9; off += step) {
        const core::Vec2 beside = centre + side * (outline + off) * across;
        double back_px = 0.0;
        if (drawn_back) {
          const double ahead_px = roomAlongPx(beside, dir, body, panel, layout, to_px, pad, false);
          // A millionth of a pixel more, so that the room from the tail, the same wall or body
          // ahead, holds the whole arrow after the round-off of the sum.
          back_px = whole.length_px - std::max(0.0, ahead_px) + 1e-6;
          if (!(back_px > 1e-6)) continue;  // tried from beside the centre on
        }
        const core::Vec2 from = beside - back_px * dir;
        if (roomAlongPx(from, dir, body, panel, layout, to_px, pad, false) >= whole.length_px &&
            inViewPx(from, from + whole.length_px * dir, panel, to_px)) {
          whole.beside_px = side * (outline + off);
          whole.tail_ahead_px = -back_px;
          return true;
        }
      }
    }
  }
  return false;
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
  // Whole and to its scale from its tail: nothing of it is under the body there.
  ArrowShape whole = arrowShape(body.velocity_mps.norm(), panel, layout, to_px);
  const bool on_scale = !whole.off_scale && !whole.under_scale && whole.length_px > 0.0;
  // Beside the body before any other form where compose planned it so
  // (BodyModel::arrow_beside_first).
  if (on_scale && body.arrow_beside_first && placeBeside(whole, body, panel, layout, to_px)) {
    return whole;
  }
  // Straight on where it fits there whole.
  if (shape.length_px <= room_px) return shape;
  // Else straight on with a break, beside it only where the break has no room either.
  const ArrowShape in_room = arrowInRoom(shape, room_px, hidden_px, layout);
  if (in_room.length_px > 0.0 || body.arrow_beside_first) return in_room;
  if (on_scale && placeBeside(whole, body, panel, layout, to_px)) return whole;
  return in_room;
}

double edgeAlongPx(const BodyModel& body, const core::Vec2& direction, const WorldToPixel& to_px) {
  const core::Vec2 half = to_px.px_per_m * body.half_extent_m;
  if (body.shape == BodyShape::kDisk) return half.x();
  // The direction in the box's own axes (its angle turns it counter-clockwise in the world, where
  // y is up).
  const double c = std::cos(body.angle_rad), s = std::sin(body.angle_rad);
  const core::Vec2 own{c * direction.x() - s * direction.y(),
                       s * direction.x() + c * direction.y()};
  double edge = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 2; ++k) {
    if (std::abs(own[k]) > 1e-12) edge = std::min(edge, half[k] / std::abs(own[k]));
  }
  return edge;
}

ArrowShape arrowReadingOrMark(const ArrowShape& mark, double room_px, double hidden_px,
                              const BodyModel& body, const PanelModel& panel,
                              const FrameLayout& layout, const WorldToPixel& to_px) {
  ArrowShape whole = arrowShape(body.velocity_mps.norm(), panel, layout, to_px);
  if (whole.under_scale || whole.off_scale || whole.length_px <= 0.0) {
    return arrowInRoom(mark, room_px, hidden_px, layout);
  }
  if (body.arrow_beside_first && placeBeside(whole, body, panel, layout, to_px)) return whole;
  const core::Vec2 dir = pixelDirection(body);
  const double edge = edgeAlongPx(body, dir, to_px);
  const core::Vec2 tail = to_px.toPixel(body.center_m) + edge * dir;
  if (room_px >= edge + whole.length_px &&
      inViewPx(tail, tail + whole.length_px * dir, panel, to_px)) {
    whole.tail_ahead_px = edge;
    return whole;
  }
  if (placeBeside(whole, body, panel, layout, to_px)) return whole;
  return ArrowShape{};
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
