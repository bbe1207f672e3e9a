#include "render/frame_mesh.hpp"

#include <algorithm>

namespace collide::render {
namespace {

constexpr Rgba kTrackColor{0.30f, 0.30f, 0.30f, 1.0f};
constexpr Rgba kArrowColor{0.12f, 0.12f, 0.12f, 1.0f};
constexpr Rgba kBarFrameColor{0.78f, 0.78f, 0.78f, 1.0f};
constexpr float kOutlineShade = 0.7f;  // outline = fill colour × this (same alpha)

Rgba darker(const Rgba& c) {
  return {c.r * kOutlineShade, c.g * kOutlineShade, c.b * kOutlineShade, c.a};
}

// Draws one body; returns the pixel y of its top edge (for the arrow).
double addBody(const BodyModel& body, const FrameLayout& layout, const WorldToPixel& to_px,
               MeshBuilder& mesh) {
  const core::Vec2 center = to_px.toPixel(body.center_m);
  const double outline = layout.outline_px;
  if (body.shape == BodyShape::kDisk) {
    const double radius = to_px.px_per_m * body.half_extent_m.x();
    const double inner = std::max(0.0, radius - outline);
    mesh.addDisk(center, inner, body.fill);
    mesh.addRing(center, radius, inner, darker(body.fill));
    return center.y() - radius;
  }
  const double half_w = to_px.px_per_m * body.half_extent_m.x();
  const double half_h = to_px.px_per_m * body.half_extent_m.y();
  const PixelRect outer{center.x() - half_w, center.y() - half_h, center.x() + half_w,
                        center.y() + half_h};
  const double t = std::min({outline, half_w, half_h});
  mesh.addRect({outer.x0 + t, outer.y0 + t, outer.x1 - t, outer.y1 - t}, body.fill);
  mesh.addRectFrame(outer, t, darker(body.fill));
  return outer.y0;
}

void addVelocityArrow(const BodyModel& body, double body_top_px, double arrow_m_per_mps,
                      const FrameLayout& layout, const WorldToPixel& to_px, MeshBuilder& mesh) {
  const double speed_mps = body.velocity_mps.norm();
  if (speed_mps <= kRestSpeed_mps || arrow_m_per_mps <= 0.0) return;
  const double length_px = speed_mps * arrow_m_per_mps * to_px.px_per_m;
  // World y is up, pixel y is down.
  const core::Vec2 direction{body.velocity_mps.x(), -body.velocity_mps.y()};
  const core::Vec2 tail{to_px.toPixel(body.center_m).x(), body_top_px - layout.arrow_gap_px};
  mesh.addArrow(tail, direction / speed_mps, length_px, layout.arrow_shaft_px,
                layout.arrow_head_length_px, layout.arrow_head_width_px, kArrowColor);
}

void addEnergyBar(const EnergyBar& bar, const FrameLayout& layout, MeshBuilder& mesh) {
  mesh.addRectFrame(layout.bar_outer, layout.bar_frame_px, kBarFrameColor);
  if (bar.full_scale_J <= 0.0) return;
  const std::vector<double> edges = barSegmentEdgesPx(bar, layout.bar_inner);
  for (std::size_t i = 0; i < bar.segments.size(); ++i) {
    mesh.addRect({edges[i], layout.bar_inner.y0, edges[i + 1], layout.bar_inner.y1},
                 bar.segments[i].color);
  }
}

}  // namespace

FrameMeshRanges buildFrameMesh(const FrameModel& frame, const FrameLayout& layout,
                               MeshBuilder& mesh) {
  mesh.clear();
  const WorldToPixel to_px = fitView(frame.view, layout.scene);

  if (frame.draw_track) {
    // The line's top edge is the track, so blocks resting on it do not cover it.
    const double y = to_px.toPixel({0.0, frame.track_y_m}).y();
    mesh.addRect({layout.scene.x0, y, layout.scene.x1, y + layout.track_px}, kTrackColor);
  }
  std::vector<double> body_tops_px;
  body_tops_px.reserve(frame.bodies.size());
  for (const BodyModel& body : frame.bodies) {
    body_tops_px.push_back(addBody(body, layout, to_px, mesh));
  }
  // Arrows after all bodies, so a neighbour never hides one.
  for (std::size_t i = 0; i < frame.bodies.size(); ++i) {
    addVelocityArrow(frame.bodies[i], body_tops_px[i], frame.arrow_m_per_mps, layout, to_px, mesh);
  }

  FrameMeshRanges ranges;
  ranges.world_vertices = mesh.vertexCount();
  addEnergyBar(frame.energy_bar, layout, mesh);
  ranges.total_vertices = mesh.vertexCount();
  return ranges;
}

}  // namespace collide::render
