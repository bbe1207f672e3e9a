#include "render/vector_text.hpp"

#include <cairo-ft.h>
#include <cmath>
#include <ft2build.h>
#include FT_FREETYPE_H

#include "render/gl_context.hpp"

namespace collide::render {
namespace {

// FreeType's library and face live as long as Cairo's font face (Cairo may cache it past our
// last reference), so Cairo frees them.
struct FaceOwner {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  ~FaceOwner() {
    if (face != nullptr) FT_Done_Face(face);
    if (library != nullptr) FT_Done_FreeType(library);
  }
};

const cairo_user_data_key_t kFaceOwnerKey{};

void destroyOwner(void* owner) {
  delete static_cast<FaceOwner*>(owner);
}

}  // namespace

struct VectorText::Impl {
  cairo_font_face_t* font_face = nullptr;
  FT_Face face = nullptr;  // owned through font_face
  std::string utf8;        // scratch, reused per run
  std::vector<cairo_glyph_t> glyphs;
  std::vector<cairo_text_cluster_t> clusters;

  ~Impl() {
    if (font_face != nullptr) cairo_font_face_destroy(font_face);
  }
};

VectorText::VectorText(const std::string& font_path) : impl_(std::make_unique<Impl>()) {
  auto owner = std::make_unique<FaceOwner>();
  if (FT_Init_FreeType(&owner->library) != 0 ||
      FT_New_Face(owner->library, font_path.c_str(), 0, &owner->face) != 0) {
    throw RenderError("vector figure: cannot load the font '" + font_path + "'");
  }
  impl_->face = owner->face;
  impl_->font_face = cairo_ft_font_face_create_for_ft_face(owner->face, 0);
  if (cairo_font_face_set_user_data(impl_->font_face, &kFaceOwnerKey, owner.get(), destroyOwner) !=
      CAIRO_STATUS_SUCCESS) {
    throw RenderError("vector figure: Cairo cannot hold the font '" + font_path + "'");
  }
  static_cast<void>(owner.release());  // Cairo frees it with the font face
}

VectorText::~VectorText() = default;

void VectorText::draw(cairo_t* cr, const PlacedLine& line, const Rgba& color) {
  if (line.glyphs.empty()) return;
  cairo_set_font_face(cr, impl_->font_face);
  cairo_set_source_rgba(cr, color.r, color.g, color.b, color.a);
  std::size_t first = 0;
  while (first < line.glyphs.size()) {
    const PlacedGlyph& lead = line.glyphs[first];
    std::size_t end = first;
    impl_->utf8.clear();
    impl_->glyphs.clear();
    impl_->clusters.clear();
    for (; end < line.glyphs.size(); ++end) {
      const PlacedGlyph& g = line.glyphs[end];
      if (g.pixel_size != lead.pixel_size || g.baseline_px != lead.baseline_px) break;
      const std::string chars = encodeUtf8(std::u32string(1, g.source));
      impl_->utf8 += chars;
      // At the whole pixel the GL painter puts the glyph on, so both show the same line.
      impl_->glyphs.push_back(
          {FT_Get_Char_Index(impl_->face, g.drawn), std::round(g.pen_x_px), g.baseline_px});
      impl_->clusters.push_back({static_cast<int>(chars.size()), 1});
    }
    cairo_set_font_size(cr, lead.pixel_size);
    cairo_show_text_glyphs(cr, impl_->utf8.data(), static_cast<int>(impl_->utf8.size()),
                           impl_->glyphs.data(), static_cast<int>(impl_->glyphs.size()),
                           impl_->clusters.data(), static_cast<int>(impl_->clusters.size()),
                           static_cast<cairo_text_cluster_flags_t>(0));
    first = end;
  }
}

}  // namespace collide::render
