#pragma once
// Private: lays out one line of UTF-8 text as textured quads from the glyph atlas. Glyph quads
// land on whole pixels, so the atlas is copied texel for texel (crisp, deterministic).
//
// Unicode subscripts (U+2080..U+209C) and superscripts (¹ ² ³, U+2070..U+207F) are drawn as the
// ordinary character at kScriptScale of the size, lowered or raised, so "v₁′" and "m₂" look the
// same with any font. A prime (U+2032) the font lacks falls back to an apostrophe.
#include <string>
#include <string_view>
#include <vector>

#include "core/vec.hpp"
#include "render/frame_model.hpp"
#include "render/glyph_atlas.hpp"
#include "render/layout.hpp"

namespace collide::render {

struct TextVertex {
  float x_px, y_px;        // frame pixels, origin top-left
  float u_texel, v_texel;  // atlas texels, origin top-left
  float r, g, b, a;        // straight alpha
};

enum class HAlign { kLeft, kCenter, kRight };
enum class VAlign {
  kTop,       // anchor y is the top of the line (ascender)
  kMiddle,    // anchor y is half the capital height above the baseline
  kBaseline,  // anchor y is the baseline
  kBottom,    // anchor y is the bottom of the line (descender)
};

inline constexpr double kScriptScale = 0.68;

// Decodes UTF-8; malformed bytes become U+FFFD.
std::u32string decodeUtf8(std::string_view text);
std::string encodeUtf8(const std::u32string& text);

// One glyph of a laid-out line: the character drawn at a pen position. Sub- and superscripts are
// their ordinary character (`drawn`) at a smaller size, moved off the baseline; `source` is the
// character of the text (e.g. U+2081 for a drawn '1'), for vector output that keeps the text.
struct PlacedGlyph {
  char32_t drawn = 0;
  char32_t source = 0;
  int pixel_size = 0;      // em of this glyph, pixels
  double pen_x_px = 0.0;   // pen position on the baseline, before rounding to whole pixels
  double baseline_px = 0;  // this glyph's baseline (whole pixels; shifted for scripts)
};

struct PlacedLine {
  std::vector<PlacedGlyph> glyphs;
  PixelRect box;  // advance × line height
};

class TextPainter {
 public:
  explicit TextPainter(GlyphAtlas& atlas) : atlas_(atlas) {}

  // Advance width of the line in pixels at this em size.
  double width(std::string_view text, double size_px);
  // The text, cut at the end and finished with "…" if wider than max_width_px.
  std::string elide(std::string_view text, double size_px, double max_width_px);
  // The text if it fits, else its longest beginning that fits and ends at a whole part: readouts
  // and captions list their parts most important first, so the rule drops the least important
  // ones and never cuts a number. Boundaries, coarsest first: clauses ("; ", "   "), then items
  // (", ", " ("), then words (" "); the coarsest kind that leaves something that fits is used.
  // Only a first word wider than the room is elided. What drops parts ends in "…", so the
  // reader sees that something was left out.
  std::string fitWhole(std::string_view text, double size_px, double max_width_px);
  // The text in at most max_lines lines of max_width_px (render::wrapText's breaks); what does not
  // fit in them is left out of the last line by fitWhole's rule.
  std::vector<std::string> wrap(std::string_view text, double size_px, double max_width_px,
                                int max_lines);
  double ascender(double size_px);
  double descender(double size_px);

  // Where each glyph of the line goes.
  PlacedLine place(std::string_view text, const core::Vec2& anchor_px, double size_px, HAlign h,
                   VAlign v);
  // Appends the line's quads to `out`; returns the box it occupies (advance × line height).
  PixelRect draw(std::string_view text, const core::Vec2& anchor_px, double size_px,
                 const Rgba& color, HAlign h, VAlign v, std::vector<TextVertex>& out);

 private:
  struct Piece {
    char32_t codepoint;
    char32_t source;  // the character of the text it stands for
    int pixel_size;
    double shift_px;  // baseline shift, + downwards
  };
  std::vector<Piece> shape(std::string_view text, double size_px);
  double advance(const Piece& piece);

  GlyphAtlas& atlas_;
};

}  // namespace collide::render
