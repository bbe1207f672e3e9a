// SPDX-License-Identifier: MIT
#include "render/frame_layout.hpp"

#include <memory>

#include "core/error.hpp"
#include "frame/layout.hpp"
#include "render/draw/frame_drawing.hpp"
#include "render/draw/item_canvas.hpp"
#include "render/text/font_set.hpp"
#include "render/text/glyph_atlas.hpp"
#include "render/text/text_metrics.hpp"

namespace collide::render {
namespace {

// A painter that measures text in `fonts`, with the fonts it loaded and their (unused) atlas.
struct Measurer {
  explicit Measurer(const TextFonts& text_fonts)
      : loaded(text_fonts), fonts(text_fonts), atlas(fonts), painter(atlas) {}
  TextFonts loaded;
  FontSet fonts;
  GlyphAtlas atlas;
  TextPainter painter;
};

bool sameFonts(const TextFonts& a, const TextFonts& b) {
  return a.files == b.files && a.math_font == b.math_font && a.language_tag == b.language_tag &&
         a.right_to_left == b.right_to_left;
}

// The painter this thread measured with last where its fonts are `fonts`, else a new one: a
// layout lays out frame after frame in the same fonts, and loading them and shaping every text
// again for each frame cost more than the layout itself. A text's shape depends on its fonts,
// its characters and its whole-pixel size only (TextPainter::shaped), so a painter's cache
// measures as a new painter would; it holds a bounded number of lines.
TextPainter& painterFor(const TextFonts& fonts) {
  thread_local std::unique_ptr<Measurer> last;
  if (last == nullptr || !sameFonts(last->loaded, fonts)) {
    last.reset();
    last = std::make_unique<Measurer>(fonts);
  }
  return last->painter;
}

}  // namespace

std::vector<frame::DrawnItem> drawnItems(const frame::FrameModel& frame, int width_px,
                                         int height_px, const RendererOptions& options) {
  COLLIDE_ASSERT(width_px > 0 && height_px > 0, "drawnItems: size must be > 0 (validate input)");
  // The fonts a Renderer with these options draws with (gl_rasterizer.cpp), so text measures alike.
  const std::string font_path = options.font_path.empty() ? defaultFontPath() : options.font_path;
  TextPainter& painter =
      painterFor(options.text_fonts.files.empty() ? textFontsFor(font_path) : options.text_fonts);
  const frame::FrameLayout layout = frame::layoutFrame(
      frame, width_px, height_px, options.text_floor_px,
      [&painter](std::string_view text, double size) { return painter.width(text, size); });
  ItemCanvas canvas(painter);
  drawFrame(frame, layout, canvas);
  return canvas.items();
}

}  // namespace collide::render
