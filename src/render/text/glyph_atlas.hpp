#pragma once
// Private: glyph bitmaps packed into one single-channel image (the texture text is drawn from),
// keyed by font, glyph id (what HarfBuzz shaped, not a character) and size. Glyphs are rasterized
// on first use and stay; the image grows taller when a shelf runs out.
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include "render/text/font_set.hpp"

namespace collide::render {

struct AtlasGlyph {
  int x = 0, y = 0;         // top-left texel in the atlas
  int width = 0, rows = 0;  // texels
  int left = 0, top = 0;    // placement relative to the pen on the baseline (see GlyphBitmap)
  double advance_px = 0.0;
};

class GlyphAtlas {
 public:
  static constexpr int kWidth = 1024;       // texels; glyphs wider than this are clipped
  static constexpr int kMaxHeight = 16384;  // GL_MAX_TEXTURE_SIZE on llvmpipe
  static constexpr int kInitialHeight = 256;

  explicit GlyphAtlas(FontSet& fonts);

  // Glyph `glyph_id` of font `font` (an index into the FontSet), rasterized and packed on first
  // use. Throws RenderError when the atlas is full.
  const AtlasGlyph& glyph(int font, std::uint32_t glyph_id, int pixel_size);

  FontSet& fonts() { return fonts_; }
  int width() const { return kWidth; }
  int height() const { return height_; }
  const std::vector<std::uint8_t>& texels() const { return texels_; }  // top row first
  // Incremented whenever texels change: the renderer re-uploads when it differs from its copy.
  std::uint64_t revision() const { return revision_; }

 private:
  void grow(int needed_height);

  FontSet& fonts_;
  std::map<std::tuple<int, std::uint32_t, int>, AtlasGlyph> glyphs_;
  std::vector<std::uint8_t> texels_;
  int height_ = kInitialHeight;
  int shelf_x_ = 0, shelf_y_ = 0, shelf_h_ = 0;  // the shelf being filled
  std::uint64_t revision_ = 1;
};

}  // namespace collide::render
