#pragma once
// Private: the vector painter's canvas. Shapes become exact Cairo paths as they arrive; each
// batch's text is drawn when the batch ends, after its shapes, as in the GL painter. A body is one
// path filled and stroked at once, so an SVG keeps it as one element.
#include <cairo.h>

#include <optional>
#include <utility>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/vector/vector_text.hpp"

namespace collide::render {

class VectorCanvas final : public Canvas {
 public:
  // Draws onto `cr`, whose user space is the frame's pixels; `frame_w`, `frame_h` bound clips.
  VectorCanvas(TextPainter& painter, cairo_t* cr, VectorText& text, int frame_w, int frame_h)
      : Canvas(painter),
        sink_(cr),
        vector_text_(text),
        cr_(cr),
        frame_w_(frame_w),
        frame_h_(frame_h) {}
  ~VectorCanvas() override;

  void clear() override;
  void beginBatch(std::optional<frame::PixelRect> clip = std::nullopt) override;
  void finish() override;
  ShapeSink& shapes() override { return sink_; }
  frame::PixelRect text(std::string_view text, const core::Vec2& anchor_px, double size_px,
                        const frame::Rgba& color, HAlign h = HAlign::kLeft,
                        VAlign v = VAlign::kBaseline) override;
  void glyphs(const PlacedLine& line, const frame::Rgba& color) override {
    pending_text_.emplace_back(line, color);
  }

 private:
  class CairoSink final : public ShapeSink {
   public:
    explicit CairoSink(cairo_t* cr) : cr_(cr) {}
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
    void addOutlinedDisk(const core::Vec2& center_px, double radius_px, double outline_px,
                         const frame::Rgba& fill, const frame::Rgba& edge) override;
    void addOutlinedRect(const frame::PixelRect& outer, double outline_px, const frame::Rgba& fill,
                         const frame::Rgba& edge) override;
    double seamCoverPx() const override { return 0.0; }

   private:
    void fill(const frame::Rgba& color, cairo_fill_rule_t rule = CAIRO_FILL_RULE_WINDING);
    void stroke(double width_px, const frame::Rgba& color, cairo_line_join_t join);
    // Fills the current path and strokes it outline_px wide (mitred; not at all where 0): one
    // element in an SVG.
    void fillAndOutline(double outline_px, const frame::Rgba& fill_color, const frame::Rgba& edge);
    cairo_t* cr_;
  };

  void closeBatch();

  CairoSink sink_;
  VectorText& vector_text_;
  cairo_t* cr_;
  int frame_w_, frame_h_;
  std::vector<std::pair<PlacedLine, frame::Rgba>> pending_text_;  // the open batch's
  bool open_ = false;
};

}  // namespace collide::render
