// SPDX-License-Identifier: MIT
#pragma once
// Private: a canvas that paints nothing and records the frame's layout instead: each item the
// frame drawing code marks (ShapeSink::beginItem) with the box of all it drew, inside the batch's
// clip, and its lines of text (frame/drawn_items.hpp). The frame is laid out by the same code as
// for the painters (drawFrame), so what it records is what they draw.
#include <algorithm>
#include <optional>
#include <string_view>
#include <vector>

#include "frame/drawn_items.hpp"
#include "render/draw/canvas.hpp"

namespace collide::render {

class ItemCanvas final : public Canvas {
 public:
  explicit ItemCanvas(TextPainter& painter) : Canvas(painter), sink_(*this) {}

  void clear() override;
  void beginBatch(std::optional<frame::PixelRect> clip = std::nullopt) override { clip_ = clip; }
  void finish() override {}
  ShapeSink& shapes() override { return sink_; }
  frame::PixelRect text(std::string_view text, const core::Vec2& anchor_px, double size_px,
                        const frame::Rgba& color, HAlign h = HAlign::kLeft,
                        VAlign v = VAlign::kBaseline) override;

  // The items drawn since clear(), in drawing order; an item nothing of which shows (all of it
  // outside its clip) is left out.
  const std::vector<frame::DrawnItem>& items() const { return items_; }

 private:
  // Every shape's bounding box goes to the item open now.
  class ItemSink final : public ShapeSink {
   public:
    explicit ItemSink(ItemCanvas& canvas) : canvas_(canvas) {}
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
    double seamCoverPx() const override { return 0.0; }
    void beginItem(std::string_view id, std::string_view kind, int body,
                   const std::optional<frame::DrawnArrow>& arrow) override;
    void endItem() override;
    void describeStick(const frame::DrawnStick& stick) override {
      if (canvas_.open_) canvas_.open_->stick = stick;
    }
    void describePath(const std::vector<core::Vec2>& points) override {
      if (canvas_.open_) canvas_.open_->path = points;
    }
    void describeOpacity(double opacity) override {
      if (canvas_.open_) canvas_.open_->opacity = std::clamp(opacity, 0.0, 1.0);
    }
    void enterPanel(int index) override { canvas_.panel_ = index; }

   private:
    ItemCanvas& canvas_;
  };

  // Adds `box` (grown by `pad` on every side) to the open item, cut to the clip.
  void cover(frame::PixelRect box, double pad = 0.0);
  // The points' bounding box grown by `pad`.
  void coverPoints(const std::vector<core::Vec2>& points, double pad);

  ItemSink sink_;
  std::optional<frame::PixelRect> clip_;
  std::vector<frame::DrawnItem> items_;
  std::optional<frame::DrawnItem> open_;
  bool open_covers_ = false;  // the open item has a box yet
  int panel_ = -1;
};

}  // namespace collide::render
