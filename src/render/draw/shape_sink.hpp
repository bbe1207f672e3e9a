#pragma once
// Private: the flat shapes a frame is drawn from, in pixel coordinates (see layout.hpp). The frame
// drawing code (frame_drawing.hpp) lays a FrameModel out once and hands the shapes to a sink: the
// GL painter tessellates them into triangles (mesh.hpp), the vector painter turns them into exact
// Cairo paths (circles as arcs). Nothing here knows GL or Cairo.
#include <optional>
#include <string_view>
#include <vector>

#include "core/vec.hpp"
#include "frame/drawn_items.hpp"
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"

namespace collide::render {

class ShapeSink {
 public:
  virtual ~ShapeSink() = default;

  virtual void addTriangle(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                           const frame::Rgba& color) = 0;
  virtual void addRect(const frame::PixelRect& rect, const frame::Rgba& color) = 0;
  // The band of `thickness_px` just inside `outer`.
  virtual void addRectFrame(const frame::PixelRect& outer, double thickness_px,
                            const frame::Rgba& color) = 0;
  virtual void addDisk(const core::Vec2& center_px, double radius_px, const frame::Rgba& color) = 0;
  // The band between radius inner_px and outer_px.
  virtual void addRing(const core::Vec2& center_px, double outer_px, double inner_px,
                       const frame::Rgba& color) = 0;
  // Arrow from `tail_px` along unit vector `direction`, total length_px including the head. A head
  // longer than the arrow shrinks to the arrow's length.
  virtual void addArrow(const core::Vec2& tail_px, const core::Vec2& direction, double length_px,
                        double shaft_px, double head_length_px, double head_width_px,
                        const frame::Rgba& color) = 0;
  // A straight band of `thickness_px` centred on the segment a–b, square ends (nothing if a == b).
  virtual void addLine(const core::Vec2& a, const core::Vec2& b, double thickness_px,
                       const frame::Rgba& color) = 0;
  // A line through `points` with round joins; dash_px > 0 draws dashes of that length with equal
  // gaps, continuing across the points.
  virtual void addPolyline(const std::vector<core::Vec2>& points, double thickness_px,
                           const frame::Rgba& color, double dash_px = 0.0) = 0;
  // The same without dashes, segment i (points i to i+1) in segment_colors[i].
  virtual void addPolyline(const std::vector<core::Vec2>& points, double thickness_px,
                           const std::vector<frame::Rgba>& segment_colors) = 0;
  // The pie slice of a disk between two angles (radians, measured from +x towards +y pixel, i.e.
  // clockwise on screen).
  virtual void addSector(const core::Vec2& center_px, double radius_px, double from_rad,
                         double to_rad, const frame::Rgba& color) = 0;

  // A body: `fill` inside, an outline band of outline_px just inside its edge in `edge`. One
  // object, so a vector figure keeps it as one element. By default a fill and a band; an opaque
  // fill reaches under the band's inner half, so an anti-aliased shared edge shows no seam.
  virtual void addOutlinedDisk(const core::Vec2& center_px, double radius_px, double outline_px,
                               const frame::Rgba& fill, const frame::Rgba& edge) {
    const double inner = radius_px - outline_px > 0.0 ? radius_px - outline_px : 0.0;
    addDisk(center_px, fill.a >= 1.0f ? radius_px - 0.5 * outline_px : inner, fill);
    addRing(center_px, radius_px, inner, edge);
  }
  // `outline_px` is at most half the rectangle's smaller side (the caller clamps it).
  virtual void addOutlinedRect(const frame::PixelRect& outer, double outline_px,
                               const frame::Rgba& fill, const frame::Rgba& edge) {
    const double t = outline_px;
    const double inset = fill.a >= 1.0f ? 0.5 * t : t;
    addRect({outer.x0 + inset, outer.y0 + inset, outer.x1 - inset, outer.y1 - inset}, fill);
    addRectFrame(outer, t, edge);
  }

  // How far a shape may reach under an opaque neighbour that abuts it (pixels), so that edges
  // anti-aliased one shape at a time show no background seam between them: 1 for the GL painter,
  // 0 for exact vector shapes, which join without one (and keep their exact sizes).
  virtual double seamCoverPx() const { return 1.0; }

  // What is drawn between beginItem and endItem (shapes, and the canvas's text) is one item of
  // the frame's layout (frame/drawn_items.hpp): a sink that records the layout (ItemCanvas) keeps
  // its box and text; the painters ignore these. Items do not nest. enterPanel: the items that
  // follow belong to panel `index` (-1: to the frame).
  virtual void beginItem(std::string_view /*id*/, std::string_view /*kind*/, int /*body*/ = -1,
                         const std::optional<frame::DrawnArrow>& /*arrow*/ = std::nullopt) {}
  virtual void endItem() {}
  // The item open now is a calibration stick (frame::DrawnStick); the painters ignore it.
  virtual void describeStick(const frame::DrawnStick& /*stick*/) {}
  // The item open now is a line through `points` (an energy bar's leader); the painters ignore it.
  virtual void describePath(const std::vector<core::Vec2>& /*points*/) {}
  // The item open now is drawn at this opacity (frame::PlacedText::opacity, < 1: a text fading in
  // or out); the painters ignore it (its colours carry it).
  virtual void describeOpacity(double /*opacity*/) {}
  virtual void enterPanel(int /*index*/) {}
};

// Marks what is drawn during its life as one item (ShapeSink::beginItem).
class DrawnItemScope {
 public:
  DrawnItemScope(ShapeSink& sink, std::string_view id, std::string_view kind, int body = -1,
                 const std::optional<frame::DrawnArrow>& arrow = std::nullopt)
      : sink_(sink) {
    sink_.beginItem(id, kind, body, arrow);
  }
  ~DrawnItemScope() { sink_.endItem(); }
  DrawnItemScope(const DrawnItemScope&) = delete;
  DrawnItemScope& operator=(const DrawnItemScope&) = delete;

 private:
  ShapeSink& sink_;
};

}  // namespace collide::render
