#pragma once
// Distances in frame pixels between what a placed frame holds (text boxes, bodies, arrows), for
// the label checks: computed plainly and independently of compose's own geometry.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/vec.hpp"

namespace collide::compose_test {

struct Box {
  double x0, y0, x1, y1;
};

inline double pointToBox(const core::Vec2& p, const Box& box) {
  const double dx = std::max({box.x0 - p.x(), 0.0, p.x() - box.x1});
  const double dy = std::max({box.y0 - p.y(), 0.0, p.y() - box.y1});
  return std::hypot(dx, dy);
}

// Distance from a segment to a box, by sampling every quarter pixel (slow but obviously right).
inline double segmentToBox(const core::Vec2& a, const core::Vec2& b, const Box& box) {
  const int steps = std::max(1, static_cast<int>((b - a).norm() / 0.25));
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= steps; ++i) {
    best = std::min(best, pointToBox(a + (b - a) * (static_cast<double>(i) / steps), box));
  }
  return best;
}

inline bool intersects(const Box& a, const Box& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

inline double pointToSegment(const core::Vec2& p, const core::Vec2& a, const core::Vec2& b) {
  const core::Vec2 ab = b - a;
  const double t =
      ab.squaredNorm() > 0.0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Distance between two segments, by dense sampling of the first.
inline double segmentToSegment(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                               const core::Vec2& d) {
  const int steps = std::max(1, static_cast<int>((b - a).norm() / 0.25));
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= steps; ++i) {
    best = std::min(best, pointToSegment(a + (b - a) * (static_cast<double>(i) / steps), c, d));
  }
  return best;
}

// A body in pixels: its outline's distance to a box (0 when they touch or overlap).
struct PixelBody {
  bool disk;
  core::Vec2 center;
  core::Vec2 half;  // a disk's radius in x
  double distanceTo(const Box& box) const {
    if (disk) return std::max(0.0, pointToBox(center, box) - half.x());
    const double dx =
        std::max({center.x() - half.x() - box.x1, 0.0, box.x0 - center.x() - half.x()});
    const double dy =
        std::max({center.y() - half.y() - box.y1, 0.0, box.y0 - center.y() - half.y()});
    return std::hypot(dx, dy);
  }
};

}  // namespace collide::compose_test
