#include "render/draw/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace collide::render {
namespace {

// A pixel reaches √2/2 px from its centre, so a pixel whose centre is farther than that from the
// outline has no coverage; each quad reaches 1 px beyond its shape.
constexpr double kMarginPx = 1.0;
// Points of a polyline closer than this are one point (a zero-length segment has no direction).
constexpr double kSamePointPx = 1e-3;

void set(float (&p)[4], double a, double b, double c, double d) {
  p[0] = static_cast<float>(a);
  p[1] = static_cast<float>(b);
  p[2] = static_cast<float>(c);
  p[3] = static_cast<float>(d);
}

}  // namespace

void MeshBuilder::push(ShapeKind kind, const frame::Rgba& color, const Params& params,
                       const core::Vec2& center, const core::Vec2& u, double half_u,
                       double half_v) {
  const core::Vec2 v{-u.y(), u.x()};
  const core::Vec2 du = half_u * u, dv = half_v * v;
  const core::Vec2 corners[4] = {center - du - dv, center + du - dv, center + du + dv,
                                 center - du + dv};
  for (int index : {0, 1, 2, 0, 2, 3}) {
    Vertex vertex{};
    vertex.x_px = static_cast<float>(corners[index].x());
    vertex.y_px = static_cast<float>(corners[index].y());
    vertex.r = color.r;
    vertex.g = color.g;
    vertex.b = color.b;
    vertex.a = color.a;
    vertex.kind = static_cast<float>(kind);
    std::copy(std::begin(params.p0), std::end(params.p0), vertex.p0);
    std::copy(std::begin(params.p1), std::end(params.p1), vertex.p1);
    std::copy(std::begin(params.p2), std::end(params.p2), vertex.p2);
    vertices_.push_back(vertex);
  }
}

void MeshBuilder::addTriangle(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                              const frame::Rgba& color) {
  const double area2 = (b - a).x() * (c - a).y() - (c - a).x() * (b - a).y();
  if (std::abs(area2) < 1e-12) return;
  Params params;
  set(params.p0, a.x(), a.y(), b.x(), b.y());
  set(params.p1, c.x(), c.y(), 0.0, 0.0);
  const double x0 = std::min({a.x(), b.x(), c.x()}), x1 = std::max({a.x(), b.x(), c.x()});
  const double y0 = std::min({a.y(), b.y(), c.y()}), y1 = std::max({a.y(), b.y(), c.y()});
  push(ShapeKind::kTriangle, color, params, {0.5 * (x0 + x1), 0.5 * (y0 + y1)}, {1.0, 0.0},
       0.5 * (x1 - x0) + kMarginPx, 0.5 * (y1 - y0) + kMarginPx);
}

void MeshBuilder::addRect(const frame::PixelRect& r, const frame::Rgba& color) {
  if (r.width() <= 0.0 || r.height() <= 0.0) return;
  Params params;
  set(params.p0, 0.5 * (r.x0 + r.x1), 0.5 * (r.y0 + r.y1), 1.0, 0.0);
  set(params.p1, 0.5 * r.width(), 0.5 * r.height(), 0.0, 0.0);
  push(ShapeKind::kBox, color, params, {0.5 * (r.x0 + r.x1), 0.5 * (r.y0 + r.y1)}, {1.0, 0.0},
       0.5 * r.width() + kMarginPx, 0.5 * r.height() + kMarginPx);
}

void MeshBuilder::addRectFrame(const frame::PixelRect& outer, double thickness_px,
                               const frame::Rgba& color) {
  if (outer.width() <= 0.0 || outer.height() <= 0.0) return;
  const double t = std::min({thickness_px, 0.5 * outer.width(), 0.5 * outer.height()});
  if (t <= 0.0) return;
  Params params;
  const core::Vec2 center{0.5 * (outer.x0 + outer.x1), 0.5 * (outer.y0 + outer.y1)};
  set(params.p0, center.x(), center.y(), 1.0, 0.0);
  set(params.p1, 0.5 * outer.width(), 0.5 * outer.height(), t, 0.0);
  push(ShapeKind::kBox, color, params, center, {1.0, 0.0}, 0.5 * outer.width() + kMarginPx,
       0.5 * outer.height() + kMarginPx);
}

void MeshBuilder::addDisk(const core::Vec2& center_px, double radius_px, const frame::Rgba& color) {
  addRing(center_px, radius_px, 0.0, color);
}

void MeshBuilder::addRing(const core::Vec2& center_px, double outer_px, double inner_px,
                          const frame::Rgba& color) {
  inner_px = std::max(0.0, inner_px);
  if (outer_px <= inner_px) return;
  Params params;
  set(params.p0, center_px.x(), center_px.y(), outer_px, inner_px);
  push(ShapeKind::kDisk, color, params, center_px, {1.0, 0.0}, outer_px + kMarginPx,
       outer_px + kMarginPx);
}

void MeshBuilder::addArrow(const core::Vec2& tail_px, const core::Vec2& direction, double length_px,
                           double shaft_px, double head_length_px, double head_width_px,
                           const frame::Rgba& color) {
  if (length_px <= 0.0 || direction.norm() <= 0.0) return;
  const core::Vec2 along = direction.normalized();
  const double head_length = std::min(head_length_px, length_px);
  const double half_width = 0.5 * std::max(shaft_px, head_width_px);
  Params params;
  set(params.p0, tail_px.x(), tail_px.y(), along.x(), along.y());
  set(params.p1, length_px, 0.5 * shaft_px, head_length, 0.5 * head_width_px);
  push(ShapeKind::kArrow, color, params, tail_px + 0.5 * length_px * along, along,
       0.5 * length_px + kMarginPx, half_width + kMarginPx);
}

void MeshBuilder::addLine(const core::Vec2& a, const core::Vec2& b, double thickness_px,
                          const frame::Rgba& color) {
  const core::Vec2 d = b - a;
  const double length = d.norm();
  if (length <= 0.0 || thickness_px <= 0.0) return;
  const core::Vec2 u = d / length, center = 0.5 * (a + b);
  Params params;
  set(params.p0, center.x(), center.y(), u.x(), u.y());
  set(params.p1, 0.5 * length, 0.5 * thickness_px, 0.0, 0.0);
  push(ShapeKind::kBox, color, params, center, u, 0.5 * length + kMarginPx,
       0.5 * thickness_px + kMarginPx);
}

void MeshBuilder::addChain(const std::vector<core::Vec2>& points, double thickness_px,
                           const std::vector<frame::Rgba>& segment_colors) {
  if (thickness_px <= 0.0) return;
  // Drop repeated points (a body at rest leaves them in its trail), keeping each kept segment's
  // colour: the one of the segment that ends at its far point.
  std::vector<core::Vec2> kept;
  std::vector<frame::Rgba> colors;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!kept.empty() && (points[i] - kept.back()).norm() < kSamePointPx) continue;
    if (!kept.empty()) colors.push_back(segment_colors[std::min(i, segment_colors.size()) - 1]);
    kept.push_back(points[i]);
  }
  const double half = 0.5 * thickness_px;
  for (std::size_t i = 1; i < kept.size(); ++i) {
    const core::Vec2 a = kept[i - 1], b = kept[i];
    const bool has_prev = i >= 2, has_next = i + 1 < kept.size();
    const core::Vec2 prev = has_prev ? kept[i - 2] : a, next = has_next ? kept[i + 1] : b;
    Params params;
    set(params.p0, a.x(), a.y(), b.x(), b.y());
    set(params.p1, prev.x(), prev.y(), next.x(), next.y());
    set(params.p2, half, has_prev ? 1.0 : 0.0, has_next ? 1.0 : 0.0, 0.0);
    const double length = (b - a).norm();
    // Round joins reach `half` beyond the segment's ends.
    push(ShapeKind::kStroke, colors[i - 1], params, 0.5 * (a + b), (b - a) / length,
         0.5 * length + half + kMarginPx, half + kMarginPx);
  }
}

void MeshBuilder::addPolyline(const std::vector<core::Vec2>& points, double thickness_px,
                              const std::vector<frame::Rgba>& segment_colors) {
  if (points.size() < 2 || segment_colors.size() + 1 < points.size()) return;
  addChain(points, thickness_px, segment_colors);
}

void MeshBuilder::addPolyline(const std::vector<core::Vec2>& points, double thickness_px,
                              const frame::Rgba& color, double dash_px) {
  if (dash_px <= 0.0) {
    if (points.size() >= 2) {
      addChain(points, thickness_px, std::vector<frame::Rgba>(points.size() - 1, color));
    }
    return;
  }
  // Dashes continue across vertices: dash k covers arc length [2k·dash, (2k+1)·dash] of the
  // whole line; each dash is its own chain through the vertices it passes.
  const double period = 2.0 * dash_px;
  std::vector<core::Vec2> dash;
  const auto flush = [&] {
    if (dash.size() >= 2)
      addChain(dash, thickness_px, std::vector<frame::Rgba>(dash.size() - 1, color));
    dash.clear();
  };
  double s0 = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const core::Vec2& a = points[i - 1];
    const core::Vec2 d = points[i] - a;
    const double length = d.norm();
    if (length <= 0.0) continue;
    const double s1 = s0 + length;
    for (double k = std::floor(s0 / period); k * period < s1; k += 1.0) {
      const double from = std::max(s0, k * period), to = std::min(s1, k * period + dash_px);
      if (to <= from) continue;
      const core::Vec2 start = a + ((from - s0) / length) * d, end = a + ((to - s0) / length) * d;
      // A dash that reached the end of the previous segment goes on from this segment's start.
      if (!(from == s0 && !dash.empty())) {
        flush();
        dash.push_back(start);
      }
      dash.push_back(end);
      if (to < s1) flush();
    }
    s0 = s1;
  }
  flush();
}

void MeshBuilder::addSector(const core::Vec2& center_px, double radius_px, double from_rad,
                            double to_rad, const frame::Rgba& color) {
  if (radius_px <= 0.0 || to_rad <= from_rad) return;
  // The shader intersects the disk with two half-planes, which is good to 0.1 of a pixel for a
  // wedge of up to a quarter turn: wider ones are cut into quarters.
  const double quarter = 0.5 * std::numbers::pi;
  const int pieces = std::max(1, static_cast<int>(std::ceil((to_rad - from_rad) / quarter - 1e-9)));
  for (int i = 0; i < pieces; ++i) {
    const double a0 = from_rad + (to_rad - from_rad) * i / pieces;
    const double a1 = from_rad + (to_rad - from_rad) * (i + 1) / pieces;
    Params params;
    set(params.p0, center_px.x(), center_px.y(), radius_px, 0.0);
    set(params.p1, std::cos(a0), std::sin(a0), std::cos(a1), std::sin(a1));
    push(ShapeKind::kSector, color, params, center_px, {1.0, 0.0}, radius_px + kMarginPx,
         radius_px + kMarginPx);
  }
}

}  // namespace collide::render
