#pragma once
// Private: flat-coloured 2D shapes as analytic primitives, in pixel coordinates (see layout.hpp).
// Each shape becomes one quad (two GL_TRIANGLES) a little larger than the shape; its fragment
// shader (shaders/shape.frag) computes how much of each pixel the exact outline covers, so one
// sample per pixel gives anti-aliased edges without a multisampled framebuffer.
//
// Coverage adds up only inside one primitive: two primitives that merely touch (a fill beside its
// outline, two bar segments) blend "over" each other at the shared edge and let a little of what is
// behind show through. Callers that want a seamless join draw the lower shape under the upper one
// (see drawBody) or use one primitive (an arrow is one, a polyline chain shares its joins).
#include <cstddef>
#include <vector>

#include "core/vec.hpp"
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"

namespace collide::render {

// What the parameters of a primitive mean; the numbers are shared with shaders/shape.frag.
enum class ShapeKind : int {
  // p0 = (centre x, y, unit axis u x, y); p1 = (half extent along u, half extent along the
  // perpendicular v = (−u.y, u.x), inset, 0): inset > 0 leaves out the box shrunk by inset on
  // every side (a frame).
  kBox = 1,
  // p0 = (centre x, y, outer radius, inner radius): inner radius > 0 is a ring.
  kDisk = 2,
  // p0 = (centre x, y, radius, 0); p1 = (cos, sin of the start angle, cos, sin of the end angle);
  // the angles run from +x towards +y (clockwise on screen) and span at most a quarter turn.
  kSector = 3,
  // p0 = (a x, y, b x, y); p1 = (c x, y, 0, 0): the three corners.
  kTriangle = 4,
  // p0 = (tail x, y, unit direction x, y); p1 = (length including the head, half shaft width,
  // head length, half head width): shaft and head in one primitive, so they meet without a seam.
  kArrow = 5,
  // One segment a–b of a polyline chain with its neighbours: p0 = (a x, y, b x, y),
  // p1 = (previous point x, y, next point x, y), p2 = (half thickness, has previous, has next, 0).
  // Each pixel is drawn by the segment nearest to it, so joins are round and blend once; the
  // chain's two ends are cut square at its first and last points.
  kStroke = 6,
};

// One vertex as uploaded to the GPU: a corner of the primitive's quad and the primitive itself
// (the same on all six vertices).
struct Vertex {
  float x_px, y_px;  // quad corner
  float r, g, b, a;  // straight alpha
  float kind;        // ShapeKind
  // p2[3] is always 0: shape.frag relies on it (see its main).
  float p0[4], p1[4], p2[4];
};

inline constexpr int kVerticesPerShape = 6;

class MeshBuilder {
 public:
  void addTriangle(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                   const frame::Rgba& color);
  void addRect(const frame::PixelRect& rect, const frame::Rgba& color);
  // The band of `thickness_px` just inside `outer`, as one primitive.
  void addRectFrame(const frame::PixelRect& outer, double thickness_px, const frame::Rgba& color);
  void addDisk(const core::Vec2& center_px, double radius_px, const frame::Rgba& color);
  // The band between radius inner_px and outer_px.
  void addRing(const core::Vec2& center_px, double outer_px, double inner_px,
               const frame::Rgba& color);
  // Arrow from `tail_px` along unit vector `direction`, total length_px including the head. A head
  // longer than the arrow shrinks to the arrow's length.
  void addArrow(const core::Vec2& tail_px, const core::Vec2& direction, double length_px,
                double shaft_px, double head_length_px, double head_width_px,
                const frame::Rgba& color);

  // A straight band of `thickness_px` centred on the segment a–b, square ends (nothing if a == b).
  void addLine(const core::Vec2& a, const core::Vec2& b, double thickness_px,
               const frame::Rgba& color);
  // A line through `points` with round joins; dash_px > 0 draws dashes of that length with equal
  // gaps, continuing across the points.
  void addPolyline(const std::vector<core::Vec2>& points, double thickness_px,
                   const frame::Rgba& color, double dash_px = 0.0);
  // The same without dashes, segment i (points i to i+1) in segment_colors[i].
  void addPolyline(const std::vector<core::Vec2>& points, double thickness_px,
                   const std::vector<frame::Rgba>& segment_colors);
  // The pie slice of a disk between two angles (radians, measured from +x towards +y pixel, i.e.
  // clockwise on screen).
  void addSector(const core::Vec2& center_px, double radius_px, double from_rad, double to_rad,
                 const frame::Rgba& color);

  std::size_t vertexCount() const { return vertices_.size(); }
  std::size_t shapeCount() const { return vertices_.size() / kVerticesPerShape; }
  const std::vector<Vertex>& vertices() const { return vertices_; }
  // The first vertex of shape i: its kind, colour and parameters.
  const Vertex& shape(std::size_t i) const { return vertices_[i * kVerticesPerShape]; }
  void clear() { vertices_.clear(); }

 private:
  struct Params {
    float p0[4] = {0, 0, 0, 0}, p1[4] = {0, 0, 0, 0}, p2[4] = {0, 0, 0, 0};
  };
  // A primitive drawn over the parallelogram centre ± half_u·u ± half_v·v (u, v unit vectors).
  void push(ShapeKind kind, const frame::Rgba& color, const Params& params,
            const core::Vec2& center, const core::Vec2& u, double half_u, double half_v);
  void addChain(const std::vector<core::Vec2>& points, double thickness_px,
                const std::vector<frame::Rgba>& segment_colors);
  std::vector<Vertex> vertices_;
};

}  // namespace collide::render
