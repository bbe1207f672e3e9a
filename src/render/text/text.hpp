#pragma once
// Private: lays out one line of UTF-8 text as textured quads from the glyph atlas. Glyph quads
// land on whole pixels, so the atlas is copied texel for texel (crisp, deterministic). The line
// is shaped first (render/text/shaper.hpp: every script, either direction, sub- and superscripts),
// once per distinct string and size: frames only position the shaped line.
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/vec.hpp"
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"
#include "render/text/glyph_atlas.hpp"
#include "render/text/shaper.hpp"
#include "render/text/utf8.hpp"

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

// One glyph of a laid-out line: a glyph of a font at a position. Sub- and superscripts are
// their ordinary character (`drawn`) at a smaller size, moved off the baseline; `source` is the
// character of the text (e.g. U+2081 for a drawn '1'), and [cluster_begin, cluster_end) all the
// characters it draws (a ligature or conjunct draws several), for vector output that keeps the
// text.
struct PlacedGlyph {
  int font = 0;                // index into the painter's FontSet (0: the default font)
  std::uint32_t glyph_id = 0;  // the font's glyph
  char32_t drawn = 0;
  char32_t source = 0;
  std::uint32_t cluster_begin = 0, cluster_end = 0;  // characters of PlacedLine::text
  int pixel_size = 0;                                // em of this glyph, pixels
  double pen_x_px = 0.0;       // the glyph's origin on the baseline, before rounding to pixels
  double baseline_px = 0;      // this glyph's baseline (whole pixels; shifted for scripts)
  double advance_px = 0.0;     // pen movement to the next glyph
  bool right_to_left = false;  // its run reads from the right
};

struct PlacedLine {
  std::u32string text;              // the line's characters, logical order
  std::vector<PlacedGlyph> glyphs;  // visual order, left to right
  frame::PixelRect box;             // advance × line height
};

class TextPainter {
 public:
  explicit TextPainter(GlyphAtlas& atlas) : atlas_(atlas) {}

  // The fonts text is drawn with.
  FontSet& fonts() { return atlas_.fonts(); }
  // `text` shaped at `size_px`: from the cache after the first time.
  const ShapedLine& shaped(std::string_view text, double size_px);

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
  // The text in at most max_lines lines of max_width_px (text::wrapText's breaks, or those of
  // `pattern`, its words at their widest in the video, spread over at least least_lines:
  // text::wrapLike); what does not fit in them is left out of the last line by fitWhole's rule.
  std::vector<std::string> wrap(std::string_view text, double size_px, double max_width_px,
                                int max_lines, std::string_view pattern = {},
                                std::size_t least_lines = 0);
  double ascender(double size_px);
  double descender(double size_px);

  // Where each glyph of the line goes.
  PlacedLine place(std::string_view text, const core::Vec2& anchor_px, double size_px, HAlign h,
                   VAlign v);
  // Appends the quads of glyphs already placed to `out`.
  void drawPlaced(const PlacedLine& line, const frame::Rgba& color, std::vector<TextVertex>& out);
  // Appends the line's quads to `out`; returns the box it occupies (advance × line height).
  frame::PixelRect draw(std::string_view text, const core::Vec2& anchor_px, double size_px,
                        const frame::Rgba& color, HAlign h, VAlign v, std::vector<TextVertex>& out);

 private:
  // Frames draw the same strings again and again; a new string (a clock reading, and the trial
  // cuts fitWhole shapes of a caption that holds it) is shaped once. Two generations: lines are
  // added to recent_; when it holds this many, it becomes older_ and the previous older_ is
  // dropped. A line found in older_ moves back to recent_, so what every frame draws (titles,
  // labels) stays, while a clock reading is gone two generations later. Small generations keep
  // the cache small; one large generation (emptied when full) grew a 1080p60 render's memory
  // over its first minute (bench/results.md).
  static constexpr std::size_t kLinesPerGeneration = 256;
  // The same for wrap's lines, by all its arguments: a frame wraps its title, headings and
  // captions as the frame before did, and wrapping measures every trial line.
  static constexpr std::size_t kWrapsPerGeneration = 64;

  // wrap's lines found, not kept.
  std::vector<std::string> wrapAnew(std::string_view text, double size_px, double max_width_px,
                                    int max_lines, std::string_view pattern,
                                    std::size_t least_lines);

  GlyphAtlas& atlas_;
  std::unordered_map<std::string, ShapedLine> recent_;
  std::unordered_map<std::string, ShapedLine> older_;
  std::string key_;  // scratch: the size and the text
  std::unordered_map<std::string, std::vector<std::string>> recent_wraps_;
  std::unordered_map<std::string, std::vector<std::string>> older_wraps_;
};

}  // namespace collide::render
