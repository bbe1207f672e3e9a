#pragma once
// Private: draws a Canvas (analytic shapes, then text from the glyph atlas, batch by batch) into
// whatever framebuffer is bound. Needs a current context throughout its life.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "frame/frame_model.hpp"
#include "render/draw/canvas.hpp"

namespace collide::render {

class ShaderProgram;

class CanvasPainter {
 public:
  // Compiles the text program (each shape program the first time a frame needs it); throws
  // RenderError if GL refuses one.
  explicit CanvasPainter(const GlyphAtlas& atlas);
  ~CanvasPainter();
  CanvasPainter(const CanvasPainter&) = delete;
  CanvasPainter& operator=(const CanvasPainter&) = delete;

  // Clears the bound framebuffer (width_px × height_px, already the viewport) to `background`
  // and draws the canvas over it, blending premultiplied colours. With `regions`, fills (a box of
  // the background colour drawn unblended, canvas_painter.cpp says why not a clear) and draws
  // only inside them, leaving the rest of the framebuffer as it was (repaint_regions.hpp).
  void paint(const MeshCanvas& canvas, int width_px, int height_px, const frame::Rgba& background,
             const std::vector<frame::PixelRect>* regions = nullptr);

 private:
  // Fills with the background and draws the whole canvas inside `region` (none: the whole frame).
  void drawPass(const MeshCanvas& canvas, int width_px, int height_px,
                const std::optional<frame::PixelRect>& region);

  struct Gl;
  std::unique_ptr<Gl> gl_;
  const GlyphAtlas& atlas_;
  std::uint64_t atlas_revision_ = 0;  // revision uploaded to the atlas texture
  int atlas_height_ = 0;              // texels allocated in the atlas texture
};

}  // namespace collide::render
