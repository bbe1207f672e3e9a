#include "render/text/text_metrics.hpp"

#include <mutex>

#include "render/errors.hpp"
#include "render/text/font_set.hpp"
#include "render/text/glyph_atlas.hpp"
#include "render/text/text.hpp"

#ifndef COLLIDE_DEFAULT_FONT
#define COLLIDE_DEFAULT_FONT "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
#endif

namespace collide::render {
namespace {
std::mutex font_mutex;
std::string chosen_font;  // guarded by font_mutex; empty: the built-in default
}  // namespace

std::string defaultFontPath() {
  const std::lock_guard<std::mutex> lock(font_mutex);
  return chosen_font.empty() ? std::string(COLLIDE_DEFAULT_FONT) : chosen_font;
}

void setDefaultFontPath(const std::string& path) {
  const std::lock_guard<std::mutex> lock(font_mutex);
  chosen_font = path;
}

void checkFont(const std::string& path) {
  Font font(path);
  static_cast<void>(font.rasterizeGlyph(font.glyphIndex(U'0'), 12));
}

// The painter's own text code on a CPU-only atlas: the widths cannot drift from what is drawn.
struct TextMetrics::Impl {
  explicit Impl(const TextFonts& text_fonts) : fonts(text_fonts) {}
  FontSet fonts;
  GlyphAtlas atlas{fonts};
  TextPainter painter{atlas};
};

TextMetrics::TextMetrics(const std::string& font_path, std::string_view language_tag)
    : impl_(std::make_unique<Impl>(textFontsFor(font_path, language_tag))) {}
TextMetrics::~TextMetrics() = default;

double TextMetrics::width(std::string_view text, double size_px) {
  return impl_->painter.width(text, size_px);
}
double TextMetrics::ascender(double size_px) {
  return impl_->painter.ascender(size_px);
}
double TextMetrics::descender(double size_px) {
  return impl_->painter.descender(size_px);
}

}  // namespace collide::render
