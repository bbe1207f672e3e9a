#include "render/canvas.hpp"

namespace collide::render {

void Canvas::clear() {
  shapes_.clear();
  text_.clear();
  batches_.clear();
  open_ = false;
}

void Canvas::closeBatch() {
  if (!open_) return;
  DrawBatch& batch = batches_.back();
  batch.shape_count = shapes_.vertexCount() - batch.shape_first;
  batch.text_count = text_.size() - batch.text_first;
  open_ = false;
}

void Canvas::beginBatch(std::optional<PixelRect> clip) {
  closeBatch();
  batches_.push_back({shapes_.vertexCount(), 0, text_.size(), 0, clip});
  open_ = true;
}

void Canvas::finish() {
  closeBatch();
}

}  // namespace collide::render
