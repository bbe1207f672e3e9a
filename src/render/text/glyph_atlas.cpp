#include "render/text/glyph_atlas.hpp"

#include <algorithm>
#include <cstring>

#include "render/errors.hpp"

namespace collide::render {

namespace {
constexpr int kPadding = 1;  // empty texels around each glyph: nothing bleeds into a neighbour
}

GlyphAtlas::GlyphAtlas(FontSet& fonts)
    : fonts_(fonts), texels_(static_cast<std::size_t>(kWidth) * kInitialHeight, 0) {}

void GlyphAtlas::grow(int needed_height) {
  int height = height_;
  while (height < needed_height) height *= 2;
  if (height > kMaxHeight) {
    throw RenderError("text: the glyph atlas is full (" + std::to_string(glyphs_.size()) +
                      " glyphs); use a smaller frame height");
  }
  // Rows are top first, so growing appends zero rows and keeps every placed glyph in place.
  texels_.resize(static_cast<std::size_t>(kWidth) * height, 0);
  height_ = height;
}

const AtlasGlyph& GlyphAtlas::glyph(int font, std::uint32_t glyph_id, int pixel_size) {
  const auto key = std::make_tuple(font, glyph_id, pixel_size);
  if (const auto found = glyphs_.find(key); found != glyphs_.end()) return found->second;

  const GlyphBitmap bitmap = fonts_.font(font).rasterizeGlyph(glyph_id, pixel_size);
  AtlasGlyph placed;
  placed.width = std::min(bitmap.width, kWidth - 2 * kPadding);
  placed.rows = bitmap.rows;
  placed.left = bitmap.left;
  placed.top = bitmap.top;
  placed.advance_px = bitmap.advance_px;
  if (placed.width > 0 && placed.rows > 0) {
    if (shelf_x_ + placed.width + 2 * kPadding > kWidth) {  // next shelf
      shelf_y_ += shelf_h_;
      shelf_x_ = 0;
      shelf_h_ = 0;
    }
    shelf_h_ = std::max(shelf_h_, placed.rows + 2 * kPadding);
    if (shelf_y_ + shelf_h_ > height_) grow(shelf_y_ + shelf_h_);
    placed.x = shelf_x_ + kPadding;
    placed.y = shelf_y_ + kPadding;
    for (int row = 0; row < placed.rows; ++row) {
      std::memcpy(&texels_[static_cast<std::size_t>(placed.y + row) * kWidth + placed.x],
                  &bitmap.coverage[static_cast<std::size_t>(row) * bitmap.width],
                  static_cast<std::size_t>(placed.width));
    }
    shelf_x_ += placed.width + 2 * kPadding;
    ++revision_;
  }
  return glyphs_.emplace(key, placed).first->second;
}

}  // namespace collide::render
