// SPDX-License-Identifier: MIT
// The floor under a dragged disk pair's distance over a stretch of time. See drag_sweep.hpp.
#include "physics/drag_sweep.hpp"

#include <algorithm>

namespace collide::physics::detail {
namespace {

using core::Vec2;

// Twice the signed area of the triangle o, a, b: positive when it turns counter-clockwise.
double turn(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// The distance from the origin to the segment p q.
double segmentDistanceFromOrigin_m(const Vec2& p, const Vec2& q) {
  const Vec2 along = q - p;
  const double length2 = along.squaredNorm();
  const double s = length2 > 0.0 ? std::clamp(-p.dot(along) / length2, 0.0, 1.0) : 0.0;
  return (p + s * along).norm();
}

bool lexicographicallyLess(const Vec2& p, const Vec2& q) {
  return p.x() != q.x() ? p.x() < q.x() : p.y() < q.y();
}

}  // namespace

double hullDistanceFromOrigin_m(std::array<Vec2, 5> points) {
  // Andrew's monotone chain: the hull counter-clockwise, collinear points dropped, closed (its
  // last vertex is its first).
  std::sort(points.begin(), points.end(), lexicographicallyLess);
  std::array<Vec2, 2 * points.size()> hull;
  int m = 0;
  for (const Vec2& p : points) {
    while (m >= 2 && turn(hull[m - 2], hull[m - 1], p) <= 0.0) --m;
    hull[m++] = p;
  }
  const int lower = m + 1;
  for (int i = static_cast<int>(points.size()) - 2; i >= 0; --i) {
    while (m >= lower && turn(hull[m - 2], hull[m - 1], points[i]) <= 0.0) --m;
    hull[m++] = points[i];
  }
  const int edges = m - 1;
  bool inside = edges >= 3;
  double distance = segmentDistanceFromOrigin_m(hull[0], hull[1]);
  for (int i = 0; i < edges; ++i) {
    inside = inside && turn(hull[i], hull[i + 1], Vec2::Zero()) >= 0.0;
    distance = std::min(distance, segmentDistanceFromOrigin_m(hull[i], hull[i + 1]));
  }
  return inside ? 0.0 : distance;
}

double sweptDistanceFloor_m(const Vec2& separation_m, const SweptVelocities& v, double span_s) {
  const Vec2& d = separation_m;
  return hullDistanceFromOrigin_m(
      {d, d + span_s * (v.b_start_mps - v.a_start_mps), d + span_s * (v.b_start_mps - v.a_end_mps),
       d + span_s * (v.b_end_mps - v.a_start_mps), d + span_s * (v.b_end_mps - v.a_end_mps)});
}

}  // namespace collide::physics::detail
