#pragma once
// Private: what the frame drawing code (frame_drawing.hpp) draws onto: flat shapes and lines of
// text, split into batches that are drawn in order (each batch's shapes, then its text), each
// optionally clipped to a rectangle. Text is measured by one TextPainter for every canvas, so a
// frame is laid out the same way whoever paints it.
//
// MeshCanvas (here) keeps triangles and glyph quads for the GL painter; VectorCanvas
// (vector_canvas.hpp) draws Cairo paths and real text.
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "frame/layout.hpp"
#include "render/draw/mesh.hpp"
#include "render/draw/shape_sink.hpp"
#include "render/text/text.hpp"

namespace collide::render {

class Canvas {
 public:
  explicit Canvas(TextPainter& painter) : painter_(painter) {}
  virtual ~Canvas() = default;
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  // Empties everything.
  virtual void clear() = 0;
  // Ends the current batch and starts one clipped to `clip` (or not clipped).
  virtual void beginBatch(std::optional<frame::PixelRect> clip = std::nullopt) = 0;
  // Closes the last batch; call once all drawing is done.
  virtual void finish() = 0;

  virtual ShapeSink& shapes() = 0;
  // Draws one line of text (after the batch's shapes); returns the box it occupies, as measured
  // by painter().
  virtual frame::PixelRect text(std::string_view text, const core::Vec2& anchor_px, double size_px,
                                const frame::Rgba& color, HAlign h = HAlign::kLeft,
                                VAlign v = VAlign::kBaseline) = 0;

  // Draws glyphs already placed (a typeset formula's, render/text/math_typesetter.hpp), with the
  // batch's text. A canvas that records the layout draws nothing.
  virtual void glyphs(const PlacedLine& line, const frame::Rgba& color) {
    static_cast<void>(line);
    static_cast<void>(color);
  }

  // Measures text (width, elide, ascender): the same for every canvas.
  TextPainter& painter() { return painter_; }

 private:
  TextPainter& painter_;
};

struct DrawBatch {
  std::size_t shape_first = 0, shape_count = 0;  // vertices in MeshCanvas::shapeVertices
  std::size_t text_first = 0, text_count = 0;    // vertices in MeshCanvas::textVertices
  std::optional<frame::PixelRect> clip;          // pixels; none: the whole frame
};

// The GL painter's canvas: shapes as analytic primitives (mesh.hpp), text as glyph quads.
class MeshCanvas final : public Canvas {
 public:
  explicit MeshCanvas(TextPainter& painter) : Canvas(painter), sink_(shapes_) {}

  // Keeps capacity: no allocation per frame once warmed up.
  void clear() override;
  void beginBatch(std::optional<frame::PixelRect> clip = std::nullopt) override;
  void finish() override;
  ShapeSink& shapes() override { return sink_; }
  frame::PixelRect text(std::string_view text, const core::Vec2& anchor_px, double size_px,
                        const frame::Rgba& color, HAlign h = HAlign::kLeft,
                        VAlign v = VAlign::kBaseline) override {
    return painter().draw(text, anchor_px, size_px, color, h, v, text_);
  }
  void glyphs(const PlacedLine& line, const frame::Rgba& color) override {
    painter().drawPlaced(line, color, text_);
  }

  const std::vector<Vertex>& shapeVertices() const { return shapes_.vertices(); }
  const std::vector<TextVertex>& textVertices() const { return text_; }
  const std::vector<DrawBatch>& batches() const { return batches_; }

 private:
  // Hands every shape to the MeshBuilder.
  class MeshSink final : public ShapeSink {
   public:
    explicit MeshSink(MeshBuilder& mesh) : mesh_(mesh) {}
    void addTriangle(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                     const frame::Rgba& color) override;
    void addRect(const frame::PixelRect& rect, const frame::Rgba& color) override;
    void addRectFrame(const frame::PixelRect& outer, double thickness_px,
                      const frame::Rgba& color) override;
    void addDisk(const core::Vec2& center_px, double radius_px, const frame::Rgba& color) override;
    void addRing(const core::Vec2& center_px, double outer_px, double inner_px,
                 const frame::Rgba& color) override;
    void addArrow(const core::Vec2& tail_px, const core::Vec2& direction, double length_px,
                  double shaft_px, double head_length_px, double head_width_px,
                  const frame::Rgba& color) override;
    void addLine(const core::Vec2& a, const core::Vec2& b, double thickness_px,
                 const frame::Rgba& color) override;
    void addPolyline(const std::vector<core::Vec2>& points, double thickness_px,
                     const frame::Rgba& color, double dash_px = 0.0) override;
    void addPolyline(const std::vector<core::Vec2>& points, double thickness_px,
                     const std::vector<frame::Rgba>& segment_colors) override;
    void addSector(const core::Vec2& center_px, double radius_px, double from_rad, double to_rad,
                   const frame::Rgba& color) override;

   private:
    MeshBuilder& mesh_;
  };

  void closeBatch();

  MeshBuilder shapes_;
  MeshSink sink_;
  std::vector<TextVertex> text_;
  std::vector<DrawBatch> batches_;
  bool open_ = false;
};

}  // namespace collide::render
