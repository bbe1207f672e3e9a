#pragma once
// Private: one TrueType/OpenType face through FreeType, rasterized with fixed settings (grayscale
// anti-aliasing, light hinting: vertical only) so the same text gives the same pixels every run,
// and the same face for HarfBuzz to shape with (render/text/shaper.hpp).
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

struct hb_font_t;

namespace collide::render {

// A glyph as a coverage bitmap (one byte per pixel, 0 = none, 255 = full), placed relative to the
// pen position on the baseline: its top-left pixel is at (pen_x + left, baseline_y - top).
struct GlyphBitmap {
  int width = 0, rows = 0;
  int left = 0, top = 0;
  double advance_px = 0.0;             // pen movement to the next glyph
  std::vector<std::uint8_t> coverage;  // rows × width, top row first
};

struct FontMetrics {
  double ascender_px = 0.0;   // baseline to the top of the tallest glyphs, > 0
  double descender_px = 0.0;  // baseline to the bottom of descenders, > 0 (downwards)
};

class Font {
 public:
  // Loads face `face_index` of the file at `path`. Throws FontError (a RenderError) naming the
  // path.
  explicit Font(const std::string& path, int face_index = 0);
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  bool hasGlyph(char32_t codepoint) const;
  // The font's glyph for a character (0: its "missing" box).
  std::uint32_t glyphIndex(char32_t codepoint) const;
  // Rasterizes glyph `glyph_id` at `pixel_size` (em in pixels, >= 1).
  GlyphBitmap rasterizeGlyph(std::uint32_t glyph_id, int pixel_size);
  // The pen movement of a glyph as rasterized: whole pixels (light hinting rounds advances).
  double advance(std::uint32_t glyph_id, int pixel_size);
  FontMetrics metrics(int pixel_size);
  // The face for HarfBuzz at `pixel_size` (scale: 1/64 pixel), its advances this font's own
  // (advance()), so shaped text lands on the same pixels as the glyphs drawn. Owned by the font.
  hb_font_t* shapingFont(int pixel_size);
  const std::string& path() const { return path_; }
  std::string familyName() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string path_;
};

}  // namespace collide::render
