#pragma once
// Private: real, selectable text in SVG figures. Cairo 1.16's SVG surface writes every glyph as an
// outline (a <symbol> in <defs>, a <use> where it is drawn), which no viewer can select, search or
// read aloud. So each line of text becomes one <text> element of our own, in the frame's font
// family, size and colour, and each piece of a line (glyphs of one font, size, baseline and
// direction) one <tspan> whose characters are one string, so an editor edits a word and a search
// finds it. The default font's glyphs keep the places the shared layout gave them: a list of x
// values, one per character. Text in another script's font (Arabic, Devanagari, CJK), read from
// the right, or in clusters of several characters, is anchored at its start or, read from the
// right, its right end: the viewer shapes it (joins Arabic letters, forms conjuncts), which it
// cannot do across characters placed one by one. librsvg 2.54 reads only the first x of a list
// and lays the rest out itself, within a pixel of the layout.
//
// Why Cairo still draws the glyphs: the paint order and the clip of each line (a label under the
// next panel's shapes, a chart's labels inside the chart's clip) are Cairo's to write. Each line
// is drawn with a colour that numbers it; Cairo's SVG then holds one glyph group per line, in the
// right place, and replaceGlyphGroups() swaps each group for its line's <text> and drops the
// outlines. Writing the whole SVG ourselves would mean a second SVG writer for every shape, clip
// and dash Cairo already writes; this keeps Cairo the one writer of shapes.
#include <string>
#include <vector>

#include "frame/frame_model.hpp"
#include "render/text/text.hpp"

struct FT_FaceRec_;

namespace collide::render {

// Spaces that draw nothing: the ASCII and no-break spaces and the typographic ones (thin, narrow
// no-break and the like). Cairo drops a glyph run of them alone.
inline bool drawsNothing(char32_t c) {
  return c == U' ' || c == U'\u00A0' || (c >= U'\u2000' && c <= U'\u200B') || c == U'\u202F' ||
         c == U'\u205F' || c == U'\u3000';
}

class SvgTextLines {
 public:
  // `faces`: the frame's fonts, the default one first (family names, and the default font's own
  // sub- and superscript glyphs).
  // `units_per_px`: SVG user units per layout pixel (the page's points per pixel).
  SvgTextLines(const std::vector<FT_FaceRec_*>& faces, double units_per_px);

  // Keeps the <text> element of `line` drawn in `color`; returns the colour that Cairo must draw
  // the line's glyphs with, so that replaceGlyphGroups() finds them. Opaque, unique per line.
  frame::Rgba add(const PlacedLine& line, const frame::Rgba& color);

  // `svg` (Cairo's document) with each glyph group replaced by its line's <text>, and the glyph
  // outlines gone. Throws RenderError if Cairo wrote glyphs in a form this does not know.
  std::string replaceGlyphGroups(const std::string& svg) const;

  std::size_t size() const { return elements_.size(); }

 private:
  FT_FaceRec_* face_;  // the default font
  double units_per_px_;
  std::vector<std::string> families_;  // per font, XML-escaped, for an attribute
  std::vector<std::string> elements_;  // per line: its <text> element
};

}  // namespace collide::render
