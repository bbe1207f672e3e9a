#pragma once
// Private: CPU tessellation of flat-coloured 2D shapes into one triangle list (GL_TRIANGLES), in
// pixel coordinates (see layout.hpp). Shapes never overlap their own parts, so translucent colours
// blend once per pixel.
#include <vector>

#include "core/vec.hpp"
#include "render/frame_model.hpp"
#include "render/layout.hpp"

namespace collide::render {

// One vertex as uploaded to the GPU: position in pixels, straight-alpha colour.
struct Vertex {
  float x_px, y_px;
  float r, g, b, a;
};

// Triangles for a circle of this radius so the polygon strays < 0.2 px from the true circle
// (at least 16, at most 1024).
int circleSegments(double radius_px);

class MeshBuilder {
 public:
  void addTriangle(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                   const Rgba& color);
  // A convex quadrilateral given in order around its edge.
  void addQuad(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c, const core::Vec2& d,
               const Rgba& color);
  void addRect(const PixelRect& rect, const Rgba& color);
  // The band of `thickness_px` just inside `outer`, as four non-overlapping quads.
  void addRectFrame(const PixelRect& outer, double thickness_px, const Rgba& color);
  void addDisk(const core::Vec2& center_px, double radius_px, const Rgba& color);
  // The band between radius inner_px and outer_px.
  void addRing(const core::Vec2& center_px, double outer_px, double inner_px, const Rgba& color);
  // Arrow from `tail_px` along unit vector `direction`, total length_px including the head. A head
  // longer than the arrow shrinks to the arrow's length.
  void addArrow(const core::Vec2& tail_px, const core::Vec2& direction, double length_px,
                double shaft_px, double head_length_px, double head_width_px, const Rgba& color);

  // A straight band of `thickness_px` centred on the segment a–b (nothing if a == b).
  void addLine(const core::Vec2& a, const core::Vec2& b, double thickness_px, const Rgba& color);
  // Consecutive lines through `points`; dash_px > 0 draws dashes of that length with equal gaps.
  void addPolyline(const std::vector<core::Vec2>& points, double thickness_px, const Rgba& color,
                   double dash_px = 0.0);
  // The pie slice of a disk between two angles (radians, measured from +x towards +y pixel, i.e.
  // clockwise on screen).
  void addSector(const core::Vec2& center_px, double radius_px, double from_rad, double to_rad,
                 const Rgba& color);

  std::size_t vertexCount() const { return vertices_.size(); }
  const std::vector<Vertex>& vertices() const { return vertices_; }
  void clear() { vertices_.clear(); }

 private:
  void push(const core::Vec2& p, const Rgba& color);
  std::vector<Vertex> vertices_;
};

}  // namespace collide::render
