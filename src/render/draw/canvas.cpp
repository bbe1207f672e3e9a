#include "render/draw/canvas.hpp"

namespace collide::render {

void MeshCanvas::clear() {
  shapes_.clear();
  text_.clear();
  batches_.clear();
  open_ = false;
}

void MeshCanvas::closeBatch() {
  if (!open_) return;
  DrawBatch& batch = batches_.back();
  batch.shape_count = shapes_.vertexCount() - batch.shape_first;
  batch.text_count = text_.size() - batch.text_first;
  open_ = false;
}

void MeshCanvas::beginBatch(std::optional<frame::PixelRect> clip) {
  closeBatch();
  batches_.push_back({shapes_.vertexCount(), 0, text_.size(), 0, clip});
  open_ = true;
}

void MeshCanvas::finish() {
  closeBatch();
}

void MeshCanvas::MeshSink::addTriangle(const core::Vec2& a, const core::Vec2& b,
                                       const core::Vec2& c, const frame::Rgba& color) {
  mesh_.addTriangle(a, b, c, color);
}
void MeshCanvas::MeshSink::addRect(const frame::PixelRect& rect, const frame::Rgba& color) {
  mesh_.addRect(rect, color);
}
void MeshCanvas::MeshSink::addRectFrame(const frame::PixelRect& outer, double thickness_px,
                                        const frame::Rgba& color) {
  mesh_.addRectFrame(outer, thickness_px, color);
}
void MeshCanvas::MeshSink::addDisk(const core::Vec2& center_px, double radius_px,
                                   const frame::Rgba& color) {
  mesh_.addDisk(center_px, radius_px, color);
}
void MeshCanvas::MeshSink::addRing(const core::Vec2& center_px, double outer_px, double inner_px,
                                   const frame::Rgba& color) {
  mesh_.addRing(center_px, outer_px, inner_px, color);
}
void MeshCanvas::MeshSink::addArrow(const core::Vec2& tail_px, const core::Vec2& direction,
                                    double length_px, double shaft_px, double head_length_px,
                                    double head_width_px, const frame::Rgba& color) {
  mesh_.addArrow(tail_px, direction, length_px, shaft_px, head_length_px, head_width_px, color);
}
void MeshCanvas::MeshSink::addLine(const core::Vec2& a, const core::Vec2& b, double thickness_px,
                                   const frame::Rgba& color) {
  mesh_.addLine(a, b, thickness_px, color);
}
void MeshCanvas::MeshSink::addPolyline(const std::vector<core::Vec2>& points, double thickness_px,
                                       const frame::Rgba& color, double dash_px) {
  mesh_.addPolyline(points, thickness_px, color, dash_px);
}
void MeshCanvas::MeshSink::addPolyline(const std::vector<core::Vec2>& points, double thickness_px,
                                       const std::vector<frame::Rgba>& segment_colors) {
  mesh_.addPolyline(points, thickness_px, segment_colors);
}
void MeshCanvas::MeshSink::addSector(const core::Vec2& center_px, double radius_px, double from_rad,
                                     double to_rad, const frame::Rgba& color) {
  mesh_.addSector(center_px, radius_px, from_rad, to_rad, color);
}

}  // namespace collide::render
