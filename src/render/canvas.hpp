#pragma once
// Private: what one frame draws, before GL: flat shapes and text quads, split into batches that are
// drawn in order (each batch's shapes, then its text), each optionally clipped to a rectangle.
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "render/layout.hpp"
#include "render/mesh.hpp"
#include "render/text.hpp"

namespace collide::render {

struct DrawBatch {
  std::size_t shape_first = 0, shape_count = 0;  // vertices in Canvas::shapes
  std::size_t text_first = 0, text_count = 0;    // vertices in Canvas::text
  std::optional<PixelRect> clip;                 // pixels; none: the whole frame
};

class Canvas {
 public:
  explicit Canvas(TextPainter& painter) : painter_(painter) {}

  // Empties everything (keeps capacity: no allocation per frame once warmed up).
  void clear();
  // Ends the current batch and starts one clipped to `clip` (or not clipped).
  void beginBatch(std::optional<PixelRect> clip = std::nullopt);
  // Closes the last batch; call once all drawing is done.
  void finish();

  MeshBuilder& shapes() { return shapes_; }
  TextPainter& painter() { return painter_; }
  PixelRect text(std::string_view text, const core::Vec2& anchor_px, double size_px,
                 const Rgba& color, HAlign h = HAlign::kLeft, VAlign v = VAlign::kBaseline) {
    return painter_.draw(text, anchor_px, size_px, color, h, v, text_);
  }

  const std::vector<Vertex>& shapeVertices() const { return shapes_.vertices(); }
  const std::vector<TextVertex>& textVertices() const { return text_; }
  const std::vector<DrawBatch>& batches() const { return batches_; }

 private:
  void closeBatch();

  TextPainter& painter_;
  MeshBuilder shapes_;
  std::vector<TextVertex> text_;
  std::vector<DrawBatch> batches_;
  bool open_ = false;
};

}  // namespace collide::render
