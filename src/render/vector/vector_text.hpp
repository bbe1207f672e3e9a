#pragma once
// Private: text in vector figures, in one place. Glyphs go exactly where the shared text layout
// (TextPainter::place, shaped by HarfBuzz) put them, the same glyph ids drawn from the same fonts
// through Cairo's FreeType backend, and each cluster carries its characters, so a PDF's text can
// be selected, searched and read aloud. In an SVG each line becomes a <text> element instead
// (svg_text.hpp).
#include <cairo.h>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "frame/frame_model.hpp"
#include "render/text/script_fonts.hpp"
#include "render/text/text.hpp"

namespace collide::render {

class VectorText {
 public:
  // Loads the faces of `fonts` (the painter's FontSet's files, in its order). Throws RenderError
  // if it cannot (check them with Font first for the user's message).
  // `svg_units_per_px`: for an SVG, its user units per layout pixel; none for a PDF.
  VectorText(const TextFonts& fonts, std::optional<double> svg_units_per_px);
  ~VectorText();
  VectorText(const VectorText&) = delete;
  VectorText& operator=(const VectorText&) = delete;

  // Draws `line` onto `cr` (user space: frame pixels): each cluster of glyphs with the
  // characters of the line it draws (a subscript drawn as a small '1' reads as the '₁' it stands
  // for, a Devanagari conjunct as its letters).
  void draw(cairo_t* cr, const PlacedLine& line, const frame::Rgba& color);

  // For an SVG: Cairo's finished document with every line drawn as <text> (svg_text.hpp).
  std::string finishSvg(const std::string& cairo_svg) const;

 private:
  // SVG: the glyphs drawn in a colour that marks where the line's <text> goes.
  void drawSvgMarks(cairo_t* cr, const PlacedLine& line, const frame::Rgba& color);
  // PDF: the clusters of glyphs [first, end) of `line` into impl_'s scratch buffers, then shown.
  void collectClusters(const PlacedLine& line, std::size_t first, std::size_t end);
  void showClusters(cairo_t* cr, double pixel_size);

  struct Impl;
  std::unique_ptr<Impl> impl_;
  bool flip_ = false;  // which of two font scales the last glyph used (see draw)
};

}  // namespace collide::render
