#pragma once
// Private: one line of text shaped for every script. The line is split into bidirectional runs
// (FriBidi: the Unicode Bidirectional Algorithm), each run into pieces one font and one size
// draw, and each piece is shaped by HarfBuzz into glyph ids and positions: Arabic letters join,
// Devanagari conjuncts form, ligatures and kerning apply. Pieces are laid out in visual order,
// left to right, so a right-to-left line starts at its right end.
//
// Unicode subscripts (U+2080..U+209C) and superscripts (¹ ² ³, U+2070..U+207F) are shaped as the
// ordinary character at kScriptScale of the size, lowered or raised, so "v₁′" and "m₂" look the
// same with any font. A prime (U+2032) no font has becomes an apostrophe.
//
// Shaping is the costly part of text: TextPainter shapes a string once and keeps the result.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "render/text/font_set.hpp"
#include "render/text/utf8.hpp"

namespace collide::render {

inline constexpr double kScriptScale = 0.68;

struct ShapedGlyph {
  int font = 0;                // index into the FontSet
  std::uint32_t glyph_id = 0;  // the font's glyph (what FreeType rasterizes)
  int pixel_size = 0;          // em of this glyph, pixels
  double x_px = 0.0;           // the glyph's origin from the line's left end, pixels
  double shift_px = 0.0;       // its baseline moved down (sub- and superscripts, marks), pixels
  double advance_px = 0.0;     // pen movement to the next glyph, pixels
  // The characters of the line it draws: [cluster_begin, cluster_end) of ShapedLine::text. A
  // ligature or conjunct is one cluster of several characters; a cluster may have several glyphs.
  std::uint32_t cluster_begin = 0, cluster_end = 0;
  char32_t drawn = 0;          // the character shaped at cluster_begin ('1' for a '₁')
  bool right_to_left = false;  // its run reads from the right
};

struct ShapedLine {
  std::u32string text;              // the line's characters, logical order
  std::vector<ShapedGlyph> glyphs;  // visual order, left to right
  double width_px = 0.0;            // sum of the advances
};

// Shapes `text` at `size_px` with `fonts` in the paragraph direction of their language.
ShapedLine shapeLine(FontSet& fonts, std::string_view text, double size_px);

}  // namespace collide::render
