#include "compose/placement_obstacles.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace collide::compose {
namespace {

// Whether the segment ab crosses the box (Liang–Barsky clipping).
bool crosses(const Box& box, const core::Vec2& a, const core::Vec2& b) {
  double t0 = 0.0, t1 = 1.0;
  const core::Vec2 d = b - a;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a.x() - box.x0, box.x1 - a.x(), a.y() - box.y0, box.y1 - a.y()};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
    } else {
      const double t = q[i] / p[i];
      if (p[i] < 0.0)
        t0 = std::max(t0, t);
      else
        t1 = std::min(t1, t);
    }
  }
  return t0 <= t1;
}

double cross(const core::Vec2& u, const core::Vec2& v) {
  return u.x() * v.y() - u.y() * v.x();
}

// std::hypot(dx, dy) of two gaps (>= 0), with the usual case of a text beside or above a thing
// (one gap zero) answered exactly without the call: placement asks it for every candidate
// against every body and mark, frame after frame, and hypot was 2 % of a batch's CPU.
double gapLength(double dx, double dy) {
  if (dx == 0.0) return dy;
  if (dy == 0.0) return dx;
  return std::hypot(dx, dy);
}

// The gaps across and up or down from the box to point p (0 where p is within its span).
core::Vec2 gapsTo(const Box& box, const core::Vec2& p) {
  return {std::max({box.x0 - p.x(), 0.0, p.x() - box.x1}),
          std::max({box.y0 - p.y(), 0.0, p.y() - box.y1})};
}

// The squared distance from point p to the segment from a along ab (length2: ab's squared
// length, asked once by a caller that measures several points against one segment).
double squaredToSegment(const core::Vec2& p, const core::Vec2& a, const core::Vec2& ab,
                        double length2) {
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).squaredNorm();
}

}  // namespace

double distance(const Box& box, const core::Vec2& p) {
  const core::Vec2 gaps = gapsTo(box, p);
  return gapLength(gaps.x(), gaps.y());
}

double distance(const core::Vec2& p, const core::Vec2& a, const core::Vec2& b) {
  const core::Vec2 ab = b - a;
  return std::sqrt(squaredToSegment(p, a, ab, ab.squaredNorm()));
}

double distance(const Box& box, const core::Vec2& a, const core::Vec2& b) {
  if (crosses(box, a, b)) return 0.0;
  // The least of the four corners' distances to the segment and the two ends' distances to the
  // box, the same number as taking each in full: placement asks it for every pair of labels'
  // boxes and leaders, time and again. A square root is correctly rounded and never decreasing,
  // so the corners' least distance is the root of their least square; and an end's distance to
  // the box is at least its larger gap, so one no nearer than that cannot be the least.
  const core::Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  double least2 = std::numeric_limits<double>::infinity();
  for (const core::Vec2& corner : {core::Vec2{box.x0, box.y0}, core::Vec2{box.x1, box.y0},
                                   core::Vec2{box.x0, box.y1}, core::Vec2{box.x1, box.y1}}) {
    least2 = std::min(least2, squaredToSegment(corner, a, ab, length2));
  }
  double best = std::sqrt(least2);
  for (const core::Vec2& end : {a, b}) {
    const core::Vec2 gaps = gapsTo(box, end);
    if (std::max(gaps.x(), gaps.y()) < best) best = std::min(best, gapLength(gaps.x(), gaps.y()));
  }
  return best;
}

double segmentDistance(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                       const core::Vec2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) &&
      ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))) {
    return 0.0;
  }
  return std::min({distance(a, c, d), distance(b, c, d), distance(c, a, b), distance(d, a, b)});
}

namespace {

// Whether the boxes spanned by a..b and c..d stand `limit_px` or more apart along an axis (their
// gap along it, 0 where they overlap along it): then no point of one is nearer a point of the
// other than that. Across first: most far pairs are told from it alone.
bool apartAlongAnAxis(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                      const core::Vec2& d, double limit_px) {
  const double gap_x = std::max({std::min(c.x(), d.x()) - std::max(a.x(), b.x()), 0.0,
                                 std::min(a.x(), b.x()) - std::max(c.x(), d.x())});
  if (gap_x >= limit_px) return true;
  const double gap_y = std::max({std::min(c.y(), d.y()) - std::max(a.y(), b.y()), 0.0,
                                 std::min(a.y(), b.y()) - std::max(c.y(), d.y())});
  return gap_y >= limit_px;
}

}  // namespace

bool nearerThan(const Box& box, const core::Vec2& a, const core::Vec2& b, double limit_px) {
  const core::Vec2 low{box.x0, box.y0}, high{box.x1, box.y1};
  if (apartAlongAnAxis(low, high, a, b, limit_px)) return false;
  return distance(box, a, b) < limit_px;
}

bool segmentsNearerThan(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                        const core::Vec2& d, double limit_px) {
  if (apartAlongAnAxis(a, b, c, d, limit_px)) return false;
  return segmentDistance(a, b, c, d) < limit_px;
}

core::Vec2 nearestOnBox(const Box& box, const core::Vec2& p) {
  return {std::clamp(p.x(), box.x0, box.x1), std::clamp(p.y(), box.y0, box.y1)};
}

double BodyOutline::distanceTo(const Box& box) const {
  if (disk) {
    const double radius = 0.5 * (bounds.x1 - bounds.x0);
    return std::max(0.0, distance(box, bounds.center()) - radius);
  }
  const double dx = std::max({bounds.x0 - box.x1, 0.0, box.x0 - bounds.x1});
  const double dy = std::max({bounds.y0 - box.y1, 0.0, box.y0 - bounds.y1});
  return gapLength(dx, dy);
}

bool BodyOutline::nearerThan(const Box& box, double limit_px) const {
  // A distance is no less than its larger gap along an axis: hypot never rounds below the larger
  // of its arguments, a representable number no greater than the root.
  if (disk) {
    const core::Vec2 gaps = gapsTo(box, bounds.center());
    const double radius = 0.5 * (bounds.x1 - bounds.x0);
    if (std::max(0.0, std::max(gaps.x(), gaps.y()) - radius) >= limit_px) return false;
  } else {
    const double dx = std::max({bounds.x0 - box.x1, 0.0, box.x0 - bounds.x1});
    const double dy = std::max({bounds.y0 - box.y1, 0.0, box.y0 - bounds.y1});
    if (std::max(dx, dy) >= limit_px) return false;
  }
  return distanceTo(box) < limit_px;
}

bool BodyOutline::crossedBy(const core::Vec2& a, const core::Vec2& b) const {
  if (disk) return distance(bounds.center(), a, b) < 0.5 * (bounds.x1 - bounds.x0);
  return crosses(bounds, a, b);
}

Obstacles::Obstacles(const Box& clip, double body_gap, double text_gap_x, double text_gap_y)
    : clip_(clip), body_gap_(body_gap), text_gap_x_(text_gap_x), text_gap_y_(text_gap_y) {
  changed();
}

void Obstacles::changed() {
  // One count for every Obstacles of the process (frames are placed on more than one thread).
  static std::atomic<std::uint64_t> revisions{0};
  revision_ = ++revisions;
}

bool Obstacles::textsApart(const Box& a, const Box& b) const {
  return !a.intersects(b, text_gap_x_, text_gap_y_);
}

int Obstacles::hits(const Box& box) const {
  int count = 0;
  // A text flush with the clip's edge stays there as its body moves (the layout over time
  // carries its place along in sums that may come out a rounding error past the edge).
  constexpr double kSlackPx = 1e-6;
  if (box.x0 < clip_.x0 - kSlackPx || box.x1 > clip_.x1 + kSlackPx ||
      box.y0 < clip_.y0 - kSlackPx || box.y1 > clip_.y1 + kSlackPx) {
    ++count;
  }
  for (const Box& region : regions_) count += box.intersects(region) ? 1 : 0;
  for (const Mark& mark : marks_) {
    count += nearerThan(box, mark.shape.a, mark.shape.b, mark.shape.radius) ? 1 : 0;
  }
  for (const BodyOutline& body : bodies_) count += body.nearerThan(box, body_gap_) ? 1 : 0;
  for (const Box& text : texts_) count += textsApart(box, text) ? 0 : 1;
  for (const Segment& leader : leaders_) count += nearerThan(box, leader.a, leader.b, 1.0) ? 1 : 0;
  return count;
}

int Obstacles::leaderHits(const core::Vec2& a, const core::Vec2& b, int owner,
                          bool to_arrow) const {
  int count = 0;
  for (const Box& text : texts_) count += nearerThan(text, a, b, 1.0) ? 1 : 0;
  for (const Mark& mark : marks_) {
    if (to_arrow && mark.owner == owner) continue;
    count += segmentsNearerThan(a, b, mark.shape.a, mark.shape.b, mark.shape.radius) ? 1 : 0;
  }
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    if (static_cast<int>(i) == owner) continue;
    count += bodies_[i].crossedBy(a, b) ? 1 : 0;
  }
  return count;
}

int readAsOthers(const Box& box, double own_px, std::size_t owner,
                 const std::vector<BodyOutline>& bodies, const std::vector<int>& moves_with,
                 const BodyArrows& arrows, double nearer_by_px) {
  int others = 0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const bool rider = i < moves_with.size() && moves_with[i] == static_cast<int>(owner);
    if (i == owner || rider) continue;
    // Nearer than that by its body or by its arrow.
    const double limit_px = own_px + nearer_by_px;
    const bool nearer = bodies[i].nearerThan(box, limit_px) ||
                        (i < arrows.size() && arrows[i] &&
                         compose::nearerThan(box, arrows[i]->first, arrows[i]->second, limit_px));
    if (nearer) ++others;
  }
  return others;
}

}  // namespace collide::compose
