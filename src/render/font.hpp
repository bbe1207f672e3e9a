#pragma once
// Private: one TrueType/OpenType face through FreeType, rasterized with fixed settings (grayscale
// anti-aliasing, light hinting: vertical only) so the same text gives the same pixels every run.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

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
  // Loads the face at `path` (index 0). Throws FontError (a RenderError) naming the path.
  explicit Font(const std::string& path);
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  bool hasGlyph(char32_t codepoint) const;
  // Rasterizes `codepoint` at `pixel_size` (em in pixels, >= 1). A missing glyph gives the font's
  // "missing" box.
  GlyphBitmap rasterize(char32_t codepoint, int pixel_size);
  FontMetrics metrics(int pixel_size);
  const std::string& path() const { return path_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string path_;
};

}  // namespace collide::render
