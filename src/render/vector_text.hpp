#pragma once
// Private: text in vector figures, in one place. Glyphs go exactly where the shared text layout
// (TextPainter::place) put them, drawn from the frame's font through Cairo's FreeType backend, and
// each run carries its characters, so a PDF's text can be selected, searched and read aloud. In
// an SVG each line becomes a <text> element instead (svg_text.hpp).
#include <cairo.h>

#include <memory>
#include <optional>
#include <string>

#include "render/frame_model.hpp"
#include "render/text.hpp"

namespace collide::render {

class VectorText {
 public:
  // Loads the face at `font_path`. Throws RenderError if it cannot (check it with Font first for
  // the user's message).
  // `svg_units_per_px`: for an SVG, its user units per layout pixel; none for a PDF.
  VectorText(const std::string& font_path, std::optional<double> svg_units_per_px);
  ~VectorText();
  VectorText(const VectorText&) = delete;
  VectorText& operator=(const VectorText&) = delete;

  // Draws `line` onto `cr` (user space: frame pixels): each run of glyphs with one size and
  // baseline as one piece of text whose characters are the line's own (a subscript drawn as a
  // small '1' reads as the '₁' it stands for).
  void draw(cairo_t* cr, const PlacedLine& line, const Rgba& color);

  // For an SVG: Cairo's finished document with every line drawn as <text> (svg_text.hpp).
  std::string finishSvg(const std::string& cairo_svg) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  bool flip_ = false;  // which of two font scales the last glyph used (see draw)
};

}  // namespace collide::render
