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

  std::size_t vertexCount() const { return vertices_.size(); }
  const std::vector<Vertex>& vertices() const { return vertices_; }
  void clear() { vertices_.clear(); }

 private:
  void push(const core::Vec2& p, const Rgba& color);
  std::vector<Vertex> vertices_;
};

}  // namespace collide::render
