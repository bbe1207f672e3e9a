// SPDX-License-Identifier: MIT
#include "render/frame_layout.hpp"

#include "core/error.hpp"
#include "frame/layout.hpp"
#include "render/draw/frame_drawing.hpp"
#include "render/draw/item_canvas.hpp"
#include "render/text/font_set.hpp"
#include "render/text/glyph_atlas.hpp"
#include "render/text/text_metrics.hpp"

namespace collide::render {

std::vector<frame::DrawnItem> drawnItems(const frame::FrameModel& frame, int width_px,
                                         int height_px, const RendererOptions& options) {
  COLLIDE_ASSERT(width_px > 0 && height_px > 0, "drawnItems: size must be > 0 (validate input)");
  // The fonts a Renderer with these options draws with (gl_rasterizer.cpp), so text measures alike.
  const std::string font_path = options.font_path.empty() ? defaultFontPath() : options.font_path;
  FontSet fonts(options.text_fonts.files.empty() ? textFontsFor(font_path) : options.text_fonts);
  GlyphAtlas atlas(fonts);
  TextPainter painter(atlas);
  const frame::FrameLayout layout = frame::layoutFrame(
      frame, width_px, height_px, options.text_floor_px,
      [&painter](std::string_view text, double size) { return painter.width(text, size); });
  ItemCanvas canvas(painter);
  drawFrame(frame, layout, canvas);
  return canvas.items();
}

}  // namespace collide::render
