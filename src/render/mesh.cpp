#include "render/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace collide::render {
namespace {

constexpr double kMaxCircleErrorPx = 0.2;  // largest gap between polygon and circle

core::Vec2 onCircle(const core::Vec2& center, double radius, int i, int segments) {
  const double angle = 2.0 * std::numbers::pi * i / segments;
  return {center.x() + radius * std::cos(angle), center.y() + radius * std::sin(angle)};
}

}  // namespace

int circleSegments(double radius_px) {
  if (radius_px <= kMaxCircleErrorPx) return 16;
  // A chord of angle θ lies r·(1 − cos(θ/2)) inside the circle at its middle.
  const double theta = 2.0 * std::acos(1.0 - kMaxCircleErrorPx / radius_px);
  const int segments = static_cast<int>(std::ceil(2.0 * std::numbers::pi / theta));
  return std::clamp(segments, 16, 1024);
}

void MeshBuilder::push(const core::Vec2& p, const Rgba& color) {
  vertices_.push_back(Vertex{static_cast<float>(p.x()), static_cast<float>(p.y()), color.r, color.g,
                             color.b, color.a});
}

void MeshBuilder::addTriangle(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                              const Rgba& color) {
  push(a, color);
  push(b, color);
  push(c, color);
}

void MeshBuilder::addQuad(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                          const core::Vec2& d, const Rgba& color) {
  addTriangle(a, b, c, color);
  addTriangle(a, c, d, color);
}

void MeshBuilder::addRect(const PixelRect& r, const Rgba& color) {
  if (r.width() <= 0.0 || r.height() <= 0.0) return;
  addQuad({r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}, color);
}

void MeshBuilder::addRectFrame(const PixelRect& outer, double thickness_px, const Rgba& color) {
  const double t = std::min({thickness_px, 0.5 * outer.width(), 0.5 * outer.height()});
  if (t <= 0.0) return;
  // Top and bottom bands span the full width; left and right bands fit between them.
  addRect({outer.x0, outer.y0, outer.x1, outer.y0 + t}, color);
  addRect({outer.x0, outer.y1 - t, outer.x1, outer.y1}, color);
  addRect({outer.x0, outer.y0 + t, outer.x0 + t, outer.y1 - t}, color);
  addRect({outer.x1 - t, outer.y0 + t, outer.x1, outer.y1 - t}, color);
}

void MeshBuilder::addDisk(const core::Vec2& center_px, double radius_px, const Rgba& color) {
  if (radius_px <= 0.0) return;
  const int n = circleSegments(radius_px);
  for (int i = 0; i < n; ++i) {
    addTriangle(center_px, onCircle(center_px, radius_px, i, n),
                onCircle(center_px, radius_px, i + 1, n), color);
  }
}

void MeshBuilder::addRing(const core::Vec2& center_px, double outer_px, double inner_px,
                          const Rgba& color) {
  inner_px = std::max(0.0, inner_px);
  if (outer_px <= inner_px) return;
  // Same segment count as the disk inside, so the ring's inner edge meets it without gaps.
  const int n = circleSegments(outer_px);
  for (int i = 0; i < n; ++i) {
    addQuad(onCircle(center_px, inner_px, i, n), onCircle(center_px, outer_px, i, n),
            onCircle(center_px, outer_px, i + 1, n), onCircle(center_px, inner_px, i + 1, n),
            color);
  }
}

void MeshBuilder::addArrow(const core::Vec2& tail_px, const core::Vec2& direction, double length_px,
                           double shaft_px, double head_length_px, double head_width_px,
                           const Rgba& color) {
  if (length_px <= 0.0) return;
  const core::Vec2 along = direction.normalized();
  const core::Vec2 across{-along.y(), along.x()};
  const double head_length = std::min(head_length_px, length_px);
  const core::Vec2 tip = tail_px + length_px * along;
  const core::Vec2 head_base = tip - head_length * along;
  const double shaft_half = 0.5 * shaft_px;
  if (length_px > head_length) {
    addQuad(tail_px - shaft_half * across, head_base - shaft_half * across,
            head_base + shaft_half * across, tail_px + shaft_half * across, color);
  }
  const double head_half = 0.5 * head_width_px;
  addTriangle(head_base - head_half * across, tip, head_base + head_half * across, color);
}

void MeshBuilder::addLine(const core::Vec2& a, const core::Vec2& b, double thickness_px,
                          const Rgba& color) {
  const core::Vec2 d = b - a;
  const double length = d.norm();
  if (length <= 0.0 || thickness_px <= 0.0) return;
  const core::Vec2 across = (0.5 * thickness_px / length) * core::Vec2{-d.y(), d.x()};
  addQuad(a - across, b - across, b + across, a + across, color);
}

void MeshBuilder::addPolyline(const std::vector<core::Vec2>& points, double thickness_px,
                              const Rgba& color, double dash_px) {
  if (dash_px <= 0.0) {
    for (std::size_t i = 1; i < points.size(); ++i) {
      addLine(points[i - 1], points[i], thickness_px, color);
    }
    return;
  }
  // Dashes continue across vertices: dash k covers arc length [2k·dash, (2k+1)·dash] of the
  // whole line; each segment draws the parts of the dashes that fall on it.
  const double period = 2.0 * dash_px;
  double s0 = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const core::Vec2 a = points[i - 1], d = points[i] - a;
    const double length = d.norm();
    if (length <= 0.0) continue;
    const double s1 = s0 + length;
    for (double k = std::floor(s0 / period); k * period < s1; k += 1.0) {
      const double from = std::max(s0, k * period), to = std::min(s1, k * period + dash_px);
      if (to > from) {
        addLine(a + ((from - s0) / length) * d, a + ((to - s0) / length) * d, thickness_px, color);
      }
    }
    s0 = s1;
  }
}

void MeshBuilder::addSector(const core::Vec2& center_px, double radius_px, double from_rad,
                            double to_rad, const Rgba& color) {
  if (radius_px <= 0.0 || to_rad <= from_rad) return;
  const int n =
      std::max(2, static_cast<int>(std::ceil(circleSegments(radius_px) * (to_rad - from_rad) /
                                             (2.0 * std::numbers::pi))));
  for (int i = 0; i < n; ++i) {
    const double a0 = from_rad + (to_rad - from_rad) * i / n;
    const double a1 = from_rad + (to_rad - from_rad) * (i + 1) / n;
    addTriangle(center_px, center_px + radius_px * core::Vec2{std::cos(a0), std::sin(a0)},
                center_px + radius_px * core::Vec2{std::cos(a1), std::sin(a1)}, color);
  }
}

}  // namespace collide::render
