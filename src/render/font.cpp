#include "render/font.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cstring>

#include "core/bounded_read.hpp"
#include "render/renderer.hpp"

namespace collide::render {

// Fonts are a few MB; the largest CJK collections stay under this.
constexpr std::size_t kMaxFontBytes = std::size_t{64} << 20;

struct Font::Impl {
  std::string bytes;  // the font file: FreeType reads from it for the face's whole life
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  int current_size = 0;

  ~Impl() {
    if (face != nullptr) FT_Done_Face(face);
    if (library != nullptr) FT_Done_FreeType(library);
  }

  void setSize(int pixel_size) {
    if (pixel_size == current_size) return;
    if (FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(pixel_size)) != 0) {
      throw FontError("font: cannot scale to " + std::to_string(pixel_size) + " px");
    }
    current_size = pixel_size;
  }
};

Font::Font(const std::string& path) : impl_(std::make_unique<Impl>()), path_(path) {
  if (FT_Init_FreeType(&impl_->library) != 0) throw FontError("font: FreeType did not start");
  // Read through the one bounded reader (never /dev/zero for ever), then handed to FreeType.
  core::BoundedRead read = core::readBounded(path, kMaxFontBytes);
  const bool unopened = read.outcome != core::ReadOutcome::kRead;
  impl_->bytes = std::move(read.bytes);
  const FT_Error error =
      unopened ? FT_Err_Cannot_Open_Resource
               : FT_New_Memory_Face(impl_->library,
                                    reinterpret_cast<const FT_Byte*>(impl_->bytes.data()),
                                    static_cast<FT_Long>(impl_->bytes.size()), 0, &impl_->face);
  if (error != 0) {
    if (path == COLLIDE_DEFAULT_FONT) {
      // Not the user's input but a missing package: a runtime failure, with the way out.
      throw RenderError("default font '" + path +
                        "': " + (unopened ? "cannot be opened" : "cannot be read as a font") +
                        "; install fonts-dejavu-core or pass --font FILE (a TrueType or "
                        "OpenType file)");
    }
    throw FontError("--font: '" + path + "': " +
                    (unopened
                         ? "cannot be opened (" + core::describeRefusal(read, kMaxFontBytes) + ")"
                         : std::string("cannot be read as a font")) +
                    "; allowed: a TrueType or OpenType file (e.g. " COLLIDE_DEFAULT_FONT ")");
  }
  if (!FT_IS_SCALABLE(impl_->face)) {
    throw FontError("--font: '" + path + "': a bitmap-only font: allowed: a scalable font");
  }
}

Font::~Font() = default;

bool Font::hasGlyph(char32_t codepoint) const {
  return FT_Get_Char_Index(impl_->face, codepoint) != 0;
}

GlyphBitmap Font::rasterize(char32_t codepoint, int pixel_size) {
  impl_->setSize(std::max(1, pixel_size));
  FT_Face face = impl_->face;
  const FT_UInt index = FT_Get_Char_Index(face, codepoint);
  if (FT_Load_Glyph(face, index, FT_LOAD_RENDER | FT_LOAD_TARGET_LIGHT) != 0) return {};
  const FT_GlyphSlot slot = face->glyph;
  const FT_Bitmap& bitmap = slot->bitmap;
  GlyphBitmap glyph;
  glyph.width = static_cast<int>(bitmap.width);
  glyph.rows = static_cast<int>(bitmap.rows);
  glyph.left = slot->bitmap_left;
  glyph.top = slot->bitmap_top;
  glyph.advance_px = slot->advance.x / 64.0;
  glyph.coverage.resize(static_cast<std::size_t>(glyph.width) * glyph.rows);
  for (int row = 0; row < glyph.rows; ++row) {
    const unsigned char* src = bitmap.buffer + static_cast<std::ptrdiff_t>(row) * bitmap.pitch;
    std::memcpy(glyph.coverage.data() + static_cast<std::size_t>(row) * glyph.width, src,
                static_cast<std::size_t>(glyph.width));
  }
  return glyph;
}

FontMetrics Font::metrics(int pixel_size) {
  impl_->setSize(std::max(1, pixel_size));
  const FT_Size_Metrics& m = impl_->face->size->metrics;
  return {m.ascender / 64.0, -m.descender / 64.0};
}

}  // namespace collide::render
