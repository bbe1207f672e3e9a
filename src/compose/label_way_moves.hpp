// SPDX-License-Identifier: MIT
// How a label's place moves from one planner step to the next: the measures the way planner
// (label_ways.cpp) and its glides (label_glides.cpp) share.
#pragma once

#include <algorithm>
#include <cmath>

#include "compose/label_ways.hpp"

namespace collide::compose {

inline core::Vec2 cornerOf(const Box& box) {
  return {box.x0, box.y0};
}

inline Box movedTo(const Box& box, const core::Vec2& corner) {
  return {corner.x(), corner.y(), corner.x() + box.x1 - box.x0, corner.y() + box.y1 - box.y0};
}

// How far a place moved from one step to the next beyond its body's motion, and standing still:
// the nearer of the two, and whether that is riding with the body.
struct Move {
  double px;
  bool rides;
};
// How far a box moved along one axis beyond `carried`: the nearest of its near edge, far edge and
// centre (a text whose value grows or shrinks keeps one side where it stood).
inline double shiftAlong(double was0, double was1, double now0, double now1, double carried) {
  return std::min({std::abs(now0 - was0 - carried), std::abs(now1 - was1 - carried),
                   std::abs(0.5 * (now0 + now1 - was0 - was1) - carried)});
}

inline Move moveBetween(const Box& was, const core::Vec2& body_was, const Box& now,
                        const core::Vec2& body_now) {
  const core::Vec2 carried = body_now - body_was;
  const double beyond = std::hypot(shiftAlong(was.x0, was.x1, now.x0, now.x1, carried.x()),
                                   shiftAlong(was.y0, was.y1, now.y0, now.y1, carried.y()));
  const double still = std::hypot(shiftAlong(was.x0, was.x1, now.x0, now.x1, 0.0),
                                  shiftAlong(was.y0, was.y1, now.y0, now.y1, 0.0));
  return beyond <= still ? Move{beyond, true} : Move{still, false};
}

// Whether moveBetween(was, body_was, now, body_now).px <= reach_px: the nearer of its two moves
// within reach. Each is told without its root where one of its parts is 0 (the root is the
// other) or beyond the reach (the root is no less than either part): the way planner asks it of
// every candidate at every step.
inline bool movesWithin(const Box& was, const core::Vec2& body_was, const Box& now,
                        const core::Vec2& body_now, double reach_px) {
  const auto within = [reach_px](double across, double up_or_down) {
    if (across == 0.0) return up_or_down <= reach_px;
    if (up_or_down == 0.0) return across <= reach_px;
    if (across > reach_px || up_or_down > reach_px) return false;
    return std::hypot(across, up_or_down) <= reach_px;
  };
  const core::Vec2 carried = body_now - body_was;
  return within(shiftAlong(was.x0, was.x1, now.x0, now.x1, carried.x()),
                shiftAlong(was.y0, was.y1, now.y0, now.y1, carried.y())) ||
         within(shiftAlong(was.x0, was.x1, now.x0, now.x1, 0.0),
                shiftAlong(was.y0, was.y1, now.y0, now.y1, 0.0));
}

// Whether candidate `c` stands still on the page from step `first` to step `last` (a standing
// place, label_ways.hpp's addStandingPlaces, or one whose body stands).
inline bool standsOnPage(const WaySteps& steps, std::size_t c, std::size_t first,
                         std::size_t last) {
  constexpr double kStillPx = 0.5;
  return (cornerOf(steps.boxes[last][c]) - cornerOf(steps.boxes[first][c])).norm() < kStillPx;
}

}  // namespace collide::compose
