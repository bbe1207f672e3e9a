#include "render/text/font.hpp"

#include <fcntl.h>
#include <ft2build.h>
#include <hb-ot.h>
#include <hb.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <utility>

#include "core/bounded_read.hpp"
#include "render/errors.hpp"

namespace collide::render {

// Fonts are a few MB; the largest CJK collections stay under this.
constexpr std::size_t kMaxFontBytes = std::size_t{64} << 20;
constexpr FT_Int32 kLoadFlags = FT_LOAD_TARGET_LIGHT;

namespace {

// The font file mapped read-only, when it is a regular file of at most kMaxFontBytes: FreeType and
// HarfBuzz then read the one copy in the page cache, and only the pages they touch become
// resident (a CJK collection is 20 MB, of which a caption needs a few tables and glyphs; a
// process that opens it twice, once for measuring and once for drawing, maps it twice but pays
// for neither whole). Empty for anything else, which the bounded reader then reads or refuses.
struct MappedFile {
  void* data = MAP_FAILED;
  std::size_t size = 0;
  explicit MappedFile(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return;
    struct stat info {};
    if (::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) && info.st_size > 0 &&
        static_cast<std::size_t>(info.st_size) <= kMaxFontBytes) {
      size = static_cast<std::size_t>(info.st_size);
      data = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    }
    ::close(fd);
  }
  ~MappedFile() {
    if (data != MAP_FAILED) ::munmap(data, size);
  }
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  bool mapped() const { return data != MAP_FAILED; }
};

}  // namespace

struct Font::Impl {
  // The font file (mapped, else read whole): FreeType and HarfBuzz read from it for the face's
  // life, so it is destroyed after them (declared first).
  std::optional<MappedFile> mapping;
  std::string bytes;
  const char* file_data = nullptr;
  std::size_t file_size = 0;
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  int current_size = 0;
  hb_face_t* hb_face = nullptr;
  // Per em size: the HarfBuzz font, and the advances handed to it (26.6 fixed point).
  struct Sized {
    Impl* owner = nullptr;
    int pixel_size = 0;
    hb_font_t* font = nullptr;
    std::map<std::uint32_t, hb_position_t> advances;
  };
  std::map<int, std::unique_ptr<Sized>> sized;
  hb_font_funcs_t* funcs = nullptr;

  ~Impl() {
    for (auto& [size, s] : sized) hb_font_destroy(s->font);
    if (funcs != nullptr) hb_font_funcs_destroy(funcs);
    if (hb_face != nullptr) hb_face_destroy(hb_face);
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

  // The advance FreeType gives the glyph when it rasterizes it (26.6).
  hb_position_t hintedAdvance(Sized& s, std::uint32_t glyph) {
    if (const auto found = s.advances.find(glyph); found != s.advances.end()) return found->second;
    setSize(s.pixel_size);
    hb_position_t advance = 0;
    if (FT_Load_Glyph(face, glyph, kLoadFlags) == 0) {
      advance = static_cast<hb_position_t>(face->glyph->advance.x);
    }
    s.advances.emplace(glyph, advance);
    return advance;
  }

  static hb_position_t advanceFunc(hb_font_t*, void* data, hb_codepoint_t glyph, void*) {
    auto* s = static_cast<Sized*>(data);
    return s->owner->hintedAdvance(*s, glyph);
  }
};

Font::Font(const std::string& path, int face_index) : impl_(std::make_unique<Impl>()), path_(path) {
  if (FT_Init_FreeType(&impl_->library) != 0) throw FontError("font: FreeType did not start");
  // Mapped when it is a regular file; anything else through the one bounded reader (never
  // /dev/zero for ever), which says why it refuses.
  impl_->mapping.emplace(path);
  core::BoundedRead read;
  if (impl_->mapping->mapped()) {
    impl_->file_data = static_cast<const char*>(impl_->mapping->data);
    impl_->file_size = impl_->mapping->size;
  } else {
    impl_->mapping.reset();
    read = core::readBounded(path, kMaxFontBytes);
    impl_->bytes = std::move(read.bytes);
    impl_->file_data = impl_->bytes.data();
    impl_->file_size = impl_->bytes.size();
  }
  const bool unopened = read.outcome != core::ReadOutcome::kRead;
  const FT_Error error =
      unopened
          ? FT_Err_Cannot_Open_Resource
          : FT_New_Memory_Face(impl_->library, reinterpret_cast<const FT_Byte*>(impl_->file_data),
                               static_cast<FT_Long>(impl_->file_size), face_index, &impl_->face);
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
  hb_blob_t* blob = hb_blob_create(impl_->file_data, static_cast<unsigned>(impl_->file_size),
                                   HB_MEMORY_MODE_READONLY, nullptr, nullptr);
  impl_->hb_face = hb_face_create(blob, static_cast<unsigned>(face_index));
  hb_blob_destroy(blob);
  impl_->funcs = hb_font_funcs_create();
  hb_font_funcs_set_glyph_h_advance_func(impl_->funcs, &Impl::advanceFunc, nullptr, nullptr);
  hb_font_funcs_make_immutable(impl_->funcs);
}

Font::~Font() = default;

bool Font::hasGlyph(char32_t codepoint) const {
  return FT_Get_Char_Index(impl_->face, codepoint) != 0;
}

std::uint32_t Font::glyphIndex(char32_t codepoint) const {
  return FT_Get_Char_Index(impl_->face, codepoint);
}

GlyphBitmap Font::rasterizeGlyph(std::uint32_t glyph_id, int pixel_size) {
  impl_->setSize(std::max(1, pixel_size));
  FT_Face face = impl_->face;
  if (FT_Load_Glyph(face, glyph_id, FT_LOAD_RENDER | kLoadFlags) != 0) return {};
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

hb_font_t* Font::shapingFont(int pixel_size) {
  pixel_size = std::max(1, pixel_size);
  std::unique_ptr<Impl::Sized>& s = impl_->sized[pixel_size];
  if (s == nullptr) {
    s = std::make_unique<Impl::Sized>();
    s->owner = impl_.get();
    s->pixel_size = pixel_size;
    // OpenType shaping (substitutions, positioning) from the font's tables, advances from
    // FreeType's rasterizer.
    hb_font_t* parent = hb_font_create(impl_->hb_face);
    hb_font_set_scale(parent, pixel_size * 64, pixel_size * 64);
    s->font = hb_font_create_sub_font(parent);
    hb_font_destroy(parent);
    hb_font_set_funcs(s->font, impl_->funcs, s.get(), nullptr);
  }
  return s->font;
}

double Font::advance(std::uint32_t glyph_id, int pixel_size) {
  pixel_size = std::max(1, pixel_size);
  shapingFont(pixel_size);
  return impl_->hintedAdvance(*impl_->sized[pixel_size], glyph_id) / 64.0;
}

FontMetrics Font::metrics(int pixel_size) {
  impl_->setSize(std::max(1, pixel_size));
  const FT_Size_Metrics& m = impl_->face->size->metrics;
  return {m.ascender / 64.0, -m.descender / 64.0};
}

std::string Font::familyName() const {
  return impl_->face->family_name != nullptr ? impl_->face->family_name : "sans-serif";
}

}  // namespace collide::render
