// SPDX-License-Identifier: MIT
#include "render/draw/item_canvas.hpp"

#include <algorithm>
#include <string>

namespace collide::render {

void ItemCanvas::clear() {
  items_.clear();
  open_.reset();
  clip_.reset();
  panel_ = -1;
}

frame::PixelRect ItemCanvas::text(std::string_view text, const core::Vec2& anchor_px,
                                  double size_px, const frame::Rgba& /*color*/, HAlign h,
                                  VAlign v) {
  const frame::PixelRect box = painter().place(text, anchor_px, size_px, h, v).box;
  if (open_ && !text.empty()) {
    open_->lines.emplace_back(text);
    cover(box);
  }
  return box;
}

void ItemCanvas::cover(frame::PixelRect box, double pad) {
  if (!open_) return;
  box = {box.x0 - pad, box.y0 - pad, box.x1 + pad, box.y1 + pad};
  if (clip_) {
    box = {std::max(box.x0, clip_->x0), std::max(box.y0, clip_->y0), std::min(box.x1, clip_->x1),
           std::min(box.y1, clip_->y1)};
    if (box.x1 <= box.x0 || box.y1 <= box.y0) return;
  }
  frame::PixelRect& at = open_->box;
  if (!open_covers_) {
    at = box;
    open_covers_ = true;
    return;
  }
  at = {std::min(at.x0, box.x0), std::min(at.y0, box.y0), std::max(at.x1, box.x1),
        std::max(at.y1, box.y1)};
}

void ItemCanvas::coverPoints(const std::vector<core::Vec2>& points, double pad) {
  if (points.empty()) return;
  frame::PixelRect box{points[0].x(), points[0].y(), points[0].x(), points[0].y()};
  for (const core::Vec2& p : points) {
    box = {std::min(box.x0, p.x()), std::min(box.y0, p.y()), std::max(box.x1, p.x()),
           std::max(box.y1, p.y())};
  }
  cover(box, pad);
}

void ItemCanvas::ItemSink::addTriangle(const core::Vec2& a, const core::Vec2& b,
                                       const core::Vec2& c, const frame::Rgba& /*color*/) {
  canvas_.coverPoints({a, b, c}, 0.0);
}
void ItemCanvas::ItemSink::addRect(const frame::PixelRect& rect, const frame::Rgba& /*color*/) {
  canvas_.cover(rect);
}
void ItemCanvas::ItemSink::addRectFrame(const frame::PixelRect& outer, double /*thickness_px*/,
                                        const frame::Rgba& /*color*/) {
  canvas_.cover(outer);
}
void ItemCanvas::ItemSink::addDisk(const core::Vec2& center_px, double radius_px,
                                   const frame::Rgba& /*color*/) {
  canvas_.coverPoints({center_px}, radius_px);
}
void ItemCanvas::ItemSink::addRing(const core::Vec2& center_px, double outer_px,
                                   double /*inner_px*/, const frame::Rgba& /*color*/) {
  canvas_.coverPoints({center_px}, outer_px);
}
void ItemCanvas::ItemSink::addArrow(const core::Vec2& tail_px, const core::Vec2& direction,
                                    double length_px, double shaft_px, double /*head_length_px*/,
                                    double head_width_px, const frame::Rgba& /*color*/) {
  const core::Vec2 tip = tail_px + length_px * direction.normalized();
  canvas_.coverPoints({tail_px, tip}, 0.5 * std::max(shaft_px, head_width_px));
}
void ItemCanvas::ItemSink::addLine(const core::Vec2& a, const core::Vec2& b, double thickness_px,
                                   const frame::Rgba& /*color*/) {
  canvas_.coverPoints({a, b}, 0.5 * thickness_px);
}
void ItemCanvas::ItemSink::addPolyline(const std::vector<core::Vec2>& points, double thickness_px,
                                       const frame::Rgba& /*color*/, double /*dash_px*/) {
  canvas_.coverPoints(points, 0.5 * thickness_px);
}
void ItemCanvas::ItemSink::addPolyline(const std::vector<core::Vec2>& points, double thickness_px,
                                       const std::vector<frame::Rgba>& /*segment_colors*/) {
  canvas_.coverPoints(points, 0.5 * thickness_px);
}
void ItemCanvas::ItemSink::addSector(const core::Vec2& center_px, double radius_px,
                                     double /*from_rad*/, double /*to_rad*/,
                                     const frame::Rgba& /*color*/) {
  canvas_.coverPoints({center_px}, radius_px);
}

void ItemCanvas::ItemSink::beginItem(std::string_view id, std::string_view kind, int body,
                                     const std::optional<frame::DrawnArrow>& arrow) {
  endItem();
  frame::DrawnItem item;
  // A panel after the first names its items apart: the same body in two panels is two things.
  item.id = canvas_.panel_ > 0 ? "panel" + std::to_string(canvas_.panel_ + 1) + "." : "";
  item.id += id;
  item.kind = kind;
  item.body = body;
  item.panel = canvas_.panel_;
  item.arrow = arrow;
  canvas_.open_ = std::move(item);
  canvas_.open_covers_ = false;
}

void ItemCanvas::ItemSink::endItem() {
  if (canvas_.open_ && canvas_.open_covers_) canvas_.items_.push_back(std::move(*canvas_.open_));
  canvas_.open_.reset();
}

}  // namespace collide::render
