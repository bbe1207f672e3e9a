#include "render/vector/vector_text.hpp"

#include <cairo-ft.h>
#include <ft2build.h>

#include <cmath>
#include FT_FREETYPE_H

#include "render/gl_context.hpp"
#include "render/vector/svg_text.hpp"

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
  std::vector<cairo_font_face_t*> font_faces;  // per font of the set
  std::vector<FT_Face> faces;                  // owned through font_faces
  std::string utf8;                            // scratch, reused per run
  std::vector<cairo_glyph_t> glyphs;
  std::vector<cairo_text_cluster_t> clusters;
  std::vector<bool> blank;          // per cluster: draws nothing (spaces)
  std::optional<SvgTextLines> svg;  // an SVG's lines as <text>

  ~Impl() {
    for (cairo_font_face_t* face : font_faces) cairo_font_face_destroy(face);
  }
};

VectorText::VectorText(const TextFonts& fonts, std::optional<double> svg_units_per_px)
    : impl_(std::make_unique<Impl>()) {
  for (const FontFile& file : fonts.files) {
    auto owner = std::make_unique<FaceOwner>();
    if (FT_Init_FreeType(&owner->library) != 0 ||
        FT_New_Face(owner->library, file.path.c_str(), file.face_index, &owner->face) != 0) {
      throw RenderError("vector figure: cannot load the font '" + file.path + "'");
    }
    FT_Face face = owner->face;
    cairo_font_face_t* font_face = cairo_ft_font_face_create_for_ft_face(face, 0);
    impl_->font_faces.push_back(font_face);
    impl_->faces.push_back(face);
    if (cairo_font_face_set_user_data(font_face, &kFaceOwnerKey, owner.get(), destroyOwner) !=
        CAIRO_STATUS_SUCCESS) {
      throw RenderError("vector figure: Cairo cannot hold the font '" + file.path + "'");
    }
    static_cast<void>(owner.release());  // Cairo frees it with the font face
  }
  if (svg_units_per_px) impl_->svg.emplace(impl_->faces, *svg_units_per_px);
}

VectorText::~VectorText() = default;

std::string VectorText::finishSvg(const std::string& cairo_svg) const {
  return impl_->svg ? impl_->svg->replaceGlyphGroups(cairo_svg) : cairo_svg;
}

namespace {

// Glyphs of one piece: the same font, size and baseline.
bool samePiece(const PlacedGlyph& a, const PlacedGlyph& b) {
  return a.font == b.font && a.pixel_size == b.pixel_size && a.baseline_px == b.baseline_px;
}

// The end of the piece that starts at `first`.
std::size_t pieceEnd(const PlacedLine& line, std::size_t first) {
  std::size_t end = first;
  while (end < line.glyphs.size() && samePiece(line.glyphs[end], line.glyphs[first])) ++end;
  return end;
}

// The end of the cluster that starts at `begin` within the piece ending at `end`: neighbouring
// glyphs that draw the same characters (a ligature's, a conjunct's).
std::size_t clusterEnd(const PlacedLine& line, std::size_t begin, std::size_t end) {
  const PlacedGlyph& g = line.glyphs[begin];
  std::size_t next = begin + 1;
  while (next < end && line.glyphs[next].cluster_begin == g.cluster_begin &&
         line.glyphs[next].cluster_end == g.cluster_end) {
    ++next;
  }
  return next;
}

}  // namespace

void VectorText::draw(cairo_t* cr, const PlacedLine& line, const frame::Rgba& color) {
  if (line.glyphs.empty()) return;
  if (impl_->svg) return drawSvgMarks(cr, line, color);
  cairo_set_source_rgba(cr, color.r, color.g, color.b, color.a);
  for (std::size_t first = 0; first < line.glyphs.size();) {
    const std::size_t end = pieceEnd(line, first);
    collectClusters(line, first, end);
    const PlacedGlyph& lead = line.glyphs[first];
    cairo_set_font_face(cr, impl_->font_faces[static_cast<std::size_t>(lead.font)]);
    showClusters(cr, lead.pixel_size);
    first = end;
  }
}

void VectorText::drawSvgMarks(cairo_t* cr, const PlacedLine& line, const frame::Rgba& color) {
  // Cairo draws the glyphs, in the colour that numbers the line, only to mark where its <text>
  // goes in the paint order and under which clip.
  const frame::Rgba mark = impl_->svg->add(line, color);
  cairo_set_source_rgba(cr, mark.r, mark.g, mark.b, mark.a);
  for (std::size_t first = 0; first < line.glyphs.size();) {
    const PlacedGlyph& lead = line.glyphs[first];
    const std::size_t end = pieceEnd(line, first);
    impl_->glyphs.clear();
    for (std::size_t k = first; k < end; ++k) {
      const PlacedGlyph& g = line.glyphs[k];
      impl_->glyphs.push_back({g.glyph_id, std::round(g.pen_x_px), g.baseline_px});
    }
    cairo_set_font_face(cr, impl_->font_faces[static_cast<std::size_t>(lead.font)]);
    cairo_set_font_size(cr, lead.pixel_size);
    cairo_show_glyphs(cr, impl_->glyphs.data(), static_cast<int>(impl_->glyphs.size()));
    first = end;
  }
}

void VectorText::collectClusters(const PlacedLine& line, std::size_t first, std::size_t end) {
  impl_->utf8.clear();
  impl_->glyphs.clear();
  impl_->clusters.clear();
  impl_->blank.clear();
  for (std::size_t begin = first; begin < end;) {
    const PlacedGlyph& g = line.glyphs[begin];
    const std::size_t next = clusterEnd(line, begin, end);
    const std::u32string_view chars =
        std::u32string_view(line.text).substr(g.cluster_begin, g.cluster_end - g.cluster_begin);
    const std::string bytes = encodeUtf8(chars);
    impl_->utf8 += bytes;
    bool blank = true;
    for (char32_t c : chars) blank = blank && drawsNothing(c);
    impl_->blank.push_back(blank);
    // At the whole pixel the GL painter puts the glyph on, so both show the same line.
    for (std::size_t k = begin; k < next; ++k) {
      const PlacedGlyph& glyph = line.glyphs[k];
      impl_->glyphs.push_back({glyph.glyph_id, std::round(glyph.pen_x_px), glyph.baseline_px});
    }
    impl_->clusters.push_back({static_cast<int>(bytes.size()), static_cast<int>(next - begin)});
    begin = next;
  }
}

void VectorText::showClusters(cairo_t* cr, double pixel_size) {
  // One cluster at a time (with the spaces around it), each with a text matrix of its own:
  // Cairo 1.16 writes a PDF font's widths truncated to 1/1000 em but advances by the exact
  // widths when it positions the next glyph of a TJ string, so a viewer drifts left along a
  // line (half a pixel over a 720p title). A new text matrix (Tm) places a glyph absolutely;
  // Cairo starts one whenever the font's scale changes, so the scale alternates by a part in
  // 10^12, far below the six decimals the matrix is written with. A space stays with a glyph
  // beside it: alone, Cairo drops it as drawing nothing, and the PDF's text would lose it.
  const char* chars = impl_->utf8.data();
  const cairo_glyph_t* glyphs = impl_->glyphs.data();
  const std::size_t count = impl_->clusters.size();
  for (std::size_t k = 0; k < count;) {
    std::size_t next = k;
    while (next < count && impl_->blank[next]) ++next;  // a run may start with a space
    if (next < count) ++next;
    while (next < count && impl_->blank[next]) ++next;
    int bytes = 0, glyph_count = 0;
    for (std::size_t i = k; i < next; ++i) {
      bytes += impl_->clusters[i].num_bytes;
      glyph_count += impl_->clusters[i].num_glyphs;
    }
    flip_ = !flip_;
    cairo_set_font_size(cr, pixel_size * (flip_ ? 1.0 + 1e-12 : 1.0));
    cairo_show_text_glyphs(cr, chars, bytes, glyphs, glyph_count, &impl_->clusters[k],
                           static_cast<int>(next - k), static_cast<cairo_text_cluster_flags_t>(0));
    chars += bytes;
    glyphs += glyph_count;
    k = next;
  }
}

}  // namespace collide::render
