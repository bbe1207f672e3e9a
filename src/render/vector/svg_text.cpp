#include "render/vector/svg_text.hpp"

#include <ft2build.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include FT_FREETYPE_H

#include "core/markup.hpp"
#include "render/gl_context.hpp"

namespace collide::render {
namespace {

// Cairo 1.16 writes a glyph group as
//   <g style="fill:rgb(R%,G%,B%);fill-opacity:1;">
//     <use xlink:href="#glyphF-G" x="…" y="…"/> …
//   </g>
// and each glyph's outline as <symbol overflow="visible" id="glyphF-G">…</symbol> in <defs>.
constexpr std::string_view kGlyphUse = "<use xlink:href=\"#glyph";
constexpr std::string_view kGroupStart = "<g style=\"";
constexpr std::string_view kGroupEnd = "</g>";
constexpr std::string_view kFillRgb = "fill:rgb(";
constexpr std::string_view kSymbolStart = "<symbol ";
constexpr std::string_view kSymbolEnd = "</symbol>";
constexpr std::string_view kGlyphSymbolId = "id=\"glyph";
constexpr int kChannelSteps = 256;  // a line number is written in three 8-bit colour channels

// A character XML 1.0 allows in content (tabs and line breaks never reach a placed line).
bool allowedInXml(char32_t c) {
  return (c >= 0x20 && c < 0xD800) || (c >= 0xE000 && c < 0xFFFE) ||
         (c >= 0x10000 && c <= 0x10FFFF);
}

void appendEscaped(std::string& out, char32_t c) {
  if (allowedInXml(c)) core::appendMarkupEscaped(out, encodeUtf8(std::u32string(1, c)));
}

// A length in user units: three decimals (a thousandth of a point), no trailing zeros.
std::string svgNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", value);
  std::string text(buffer);
  while (!text.empty() && text.back() == '0') text.pop_back();
  if (!text.empty() && text.back() == '.') text.pop_back();
  return text == "-0" ? "0" : text;
}

int channel8(float c) {
  return static_cast<int>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

// The ink box of a glyph in font units, unhinted; false if the font has no such glyph or it
// draws nothing.
struct InkBox {
  double x_min = 0, y_min = 0, height = 0;
};
bool inkBox(FT_Face face, char32_t c, InkBox& box) {
  const FT_UInt index = FT_Get_Char_Index(face, c);
  if (index == 0 || FT_Load_Glyph(face, index, FT_LOAD_NO_SCALE) != 0) return false;
  const FT_Glyph_Metrics& m = face->glyph->metrics;
  if (m.height <= 0) return false;
  box.x_min = static_cast<double>(m.horiBearingX);
  box.y_min = static_cast<double>(m.horiBearingY - m.height);
  box.height = static_cast<double>(m.height);
  return true;
}

// One glyph as SVG text: its characters, where its origin goes and how large it is, in pixels.
struct SvgGlyph {
  char32_t shown;
  double x_px, baseline_px, size_px;
};

// The layout draws a sub- or superscript ("₁") as its ordinary character made smaller and moved
// ("1"). The SVG keeps the real character, so it reads as the frame's text, drawn with the
// font's own script glyph scaled and moved until its ink box covers the drawn one's: the same
// look. Without such a glyph in the font, the drawn character stands in.
SvgGlyph svgGlyph(FT_Face face, const PlacedGlyph& g) {
  const double x_px = std::round(g.pen_x_px);  // the whole pixel the GL painter uses
  SvgGlyph out{g.drawn, x_px, g.baseline_px, static_cast<double>(g.pixel_size)};
  if (g.source == g.drawn) return out;
  InkBox drawn, own;
  if (!inkBox(face, g.drawn, drawn) || !inkBox(face, g.source, own)) return out;
  const double em_units = face->units_per_EM;
  const double drawn_scale = g.pixel_size / em_units;  // pixels per font unit
  const double own_scale = drawn_scale * drawn.height / own.height;
  out.shown = g.source;
  out.size_px = own_scale * em_units;
  out.x_px = x_px + drawn.x_min * drawn_scale - own.x_min * own_scale;
  out.baseline_px = g.baseline_px - drawn.y_min * drawn_scale + own.y_min * own_scale;
  return out;
}

// Where a glyph of another font, or of a piece read from the right, goes: as the layout put it
// (the viewer shapes such pieces, so no script glyph stands in).
SvgGlyph shownGlyph(FT_Face face, const PlacedGlyph& g) {
  if (g.font == 0 && !g.right_to_left) return svgGlyph(face, g);
  return {g.drawn, std::round(g.pen_x_px), g.baseline_px, static_cast<double>(g.pixel_size)};
}

// The end of the piece of a line that starts at glyph `begin`: the neighbours of one font,
// direction, size and baseline as the SVG shows them, which one <tspan> carries.
std::size_t pieceEnd(const std::vector<PlacedGlyph>& glyphs, const std::vector<SvgGlyph>& shown,
                     std::size_t begin) {
  const PlacedGlyph& g = glyphs[begin];
  std::size_t end = begin + 1;
  for (; end < glyphs.size(); ++end) {
    const PlacedGlyph& next = glyphs[end];
    if (next.font != g.font || next.right_to_left != g.right_to_left ||
        shown[end].size_px != shown[begin].size_px ||
        shown[end].baseline_px != shown[begin].baseline_px) {
      break;
    }
  }
  return end;
}

// Whether each glyph of the piece draws one character of its own, the characters in order, none
// outside the Basic Multilingual Plane: then a list of x values, one per character, places every
// glyph where the layout put it. (SVG 1.1 counts a list's characters in UTF-16 units, SVG 2 in
// code points: the same count within the plane.) A ligature or a letter with its marks is one
// glyph of several characters, which a per-character list would tear apart.
bool oneGlyphPerCharacter(const PlacedLine& line, const std::vector<SvgGlyph>& shown,
                          std::size_t begin, std::size_t end) {
  for (std::size_t k = begin; k < end; ++k) {
    const PlacedGlyph& g = line.glyphs[k];
    if (g.cluster_end != g.cluster_begin + 1) return false;
    if (k > begin && g.cluster_begin != line.glyphs[k - 1].cluster_end) return false;
    if (shown[k].shown > 0xFFFF || !allowedInXml(shown[k].shown)) return false;
  }
  return true;
}

struct SvgPieceStyle {
  const std::vector<std::string>& families;  // per font, escaped
  double base_size_px;                       // the <text>'s font size
  double units_per_px;
};

// The font attributes of a piece where they differ from its <text>'s.
void appendFontAttributes(std::string& e, const SvgPieceStyle& style, int font, double size_px) {
  if (font != 0) {
    e += " font-family=\"'" + style.families[static_cast<std::size_t>(font)] + "', sans-serif\"";
  }
  if (size_px != style.base_size_px) {
    e += " font-size=\"" + svgNumber(size_px * style.units_per_px) + "px\"";
  }
}

// Glyphs [begin, end) of `line`, one piece (pieceEnd), as one <tspan> whose characters are one
// string: what an editor edits and a search finds. Each glyph of the default font read from the
// left gets its own x, the whole pixel the GL painter draws it on. A piece the viewer must shape
// (another script's font, read from the right, or clusters of several characters) is anchored
// at its start, or at its right end when read from the right; the viewer joins its letters and
// forms its conjuncts, which it cannot do across characters placed one by one.
void appendPiece(std::string& e, const SvgPieceStyle& style, const PlacedLine& line,
                 const std::vector<SvgGlyph>& shown, std::size_t begin, std::size_t end) {
  const PlacedGlyph& g = line.glyphs[begin];
  const double u = style.units_per_px;
  if (g.font == 0 && !g.right_to_left && oneGlyphPerCharacter(line, shown, begin, end)) {
    e += "<tspan x=\"";
    for (std::size_t k = begin; k < end; ++k) {
      if (k > begin) e += ' ';
      e += svgNumber(shown[k].x_px * u);
    }
    e += "\" y=\"" + svgNumber(shown[begin].baseline_px * u) + "\"";
    appendFontAttributes(e, style, g.font, shown[begin].size_px);
    e += ">";
    for (std::size_t k = begin; k < end; ++k) appendEscaped(e, shown[k].shown);
    e += "</tspan>";
    return;
  }
  std::uint32_t begin_char = g.cluster_begin, end_char = g.cluster_end;
  for (std::size_t k = begin; k < end; ++k) {
    begin_char = std::min(begin_char, line.glyphs[k].cluster_begin);
    end_char = std::max(end_char, line.glyphs[k].cluster_end);
  }
  const PlacedGlyph& last = line.glyphs[end - 1];
  const double right_px = last.pen_x_px + last.advance_px;
  const double anchor_px = g.right_to_left ? std::round(right_px) : shown[begin].x_px;
  e += "<tspan x=\"" + svgNumber(anchor_px * u) + "\" y=\"" +
       svgNumber(shown[begin].baseline_px * u) + "\"";
  // Read from the right, the piece starts at its right end; its spaces and commas, which have
  // no direction of their own, read from the right with it (SVG 1.1 10.7.4: a <tspan> with an x
  // starts a text chunk, which `direction` governs given unicode-bidi).
  if (g.right_to_left) e += " direction=\"rtl\" unicode-bidi=\"embed\"";
  // The default font's letters with their marks, or ligatures: the width the layout gave them, for
  // a viewer whose font differs. Another script's letters keep their own width: spread out,
  // joined letters would part.
  if (g.font == 0 && !g.right_to_left) {
    e += " textLength=\"" + svgNumber((right_px - g.pen_x_px) * u) + "\"";
  }
  appendFontAttributes(e, style, g.font, shown[begin].size_px);
  e += ">";
  const std::u32string_view text(line.text);
  for (char32_t c : text.substr(begin_char, end_char - begin_char)) appendEscaped(e, c);
  e += "</tspan>";
}

[[noreturn]] void unknownForm(const char* what) {
  throw RenderError(std::string("vector figure: Cairo's SVG is not in the form expected (") + what +
                    ")");
}

// The line number a glyph group's fill colour stands for (see SvgTextLines::add).
std::size_t lineNumber(std::string_view group_start) {
  const std::size_t at = group_start.find(kFillRgb);
  if (at == std::string_view::npos) unknownForm("a glyph group without fill:rgb");
  const std::string rgb(group_start.substr(at + kFillRgb.size()));
  const char* p = rgb.c_str();
  std::size_t index = 0, weight = 1;
  for (int channel = 0; channel < 3; ++channel) {
    char* end = nullptr;
    const double percent = std::strtod(p, &end);
    if (end == p || *end != '%') unknownForm("a glyph colour");
    index += weight * static_cast<std::size_t>(std::lround(percent * 2.55));
    weight *= kChannelSteps;
    p = end + 2;  // past "%," or "%)"
  }
  return index;
}

}  // namespace

SvgTextLines::SvgTextLines(const std::vector<FT_FaceRec_*>& faces, double units_per_px)
    : face_(faces.front()), units_per_px_(units_per_px) {
  for (FT_FaceRec_* face : faces) {
    core::appendMarkupEscaped(families_.emplace_back(),
                              face->family_name != nullptr ? face->family_name : "sans-serif");
  }
}

frame::Rgba SvgTextLines::add(const PlacedLine& line, const frame::Rgba& color) {
  const std::size_t index = elements_.size();
  if (index >= std::size_t{kChannelSteps} * kChannelSteps * kChannelSteps) {
    throw RenderError("vector figure: more lines of text than an SVG figure can hold");
  }
  std::string& e = elements_.emplace_back();
  const double base_size_px = line.glyphs.empty() ? 0.0 : line.glyphs.front().pixel_size;
  char fill[8];
  std::snprintf(fill, sizeof fill, "#%02x%02x%02x", channel8(color.r), channel8(color.g),
                channel8(color.b));
  e += "<text xml:space=\"preserve\" font-family=\"'" + families_.front() +
       "', sans-serif\" font-size=\"" + svgNumber(base_size_px * units_per_px_) + "px\" fill=\"" +
       fill + "\"";
  if (color.a < 1.0f) e += " fill-opacity=\"" + svgNumber(std::max(0.0f, color.a)) + "\"";
  e += ">";
  std::vector<SvgGlyph> shown;
  shown.reserve(line.glyphs.size());
  for (const PlacedGlyph& g : line.glyphs) shown.push_back(shownGlyph(face_, g));
  const SvgPieceStyle style{families_, base_size_px, units_per_px_};
  for (std::size_t begin = 0; begin < line.glyphs.size();) {
    const std::size_t end = pieceEnd(line.glyphs, shown, begin);
    appendPiece(e, style, line, shown, begin, end);
    begin = end;
  }
  e += "</text>\n";
  const auto channel = [&](int k) {
    std::size_t n = index;
    for (int i = 0; i < k; ++i) n /= kChannelSteps;
    return static_cast<float>(n % kChannelSteps) / 255.0f;
  };
  return {channel(0), channel(1), channel(2), 1.0f};
}

std::string SvgTextLines::replaceGlyphGroups(const std::string& svg) const {
  std::string out;
  out.reserve(svg.size());
  std::vector<bool> written(elements_.size(), false);
  std::size_t from = 0;
  for (std::size_t use = svg.find(kGlyphUse); use != std::string::npos;
       use = svg.find(kGlyphUse, from)) {
    const std::size_t start = svg.rfind(kGroupStart, use);
    if (start == std::string::npos || start < from) unknownForm("a glyph outside a group");
    const std::size_t end = svg.find(kGroupEnd, use);
    if (end == std::string::npos) unknownForm("an unclosed glyph group");
    const std::size_t line = lineNumber(std::string_view(svg).substr(start, use - start));
    if (line >= elements_.size()) unknownForm("a glyph group of no line");
    out.append(svg, from, start - from);
    // A line drawn in several runs (sub- and superscripts) has several groups, one after the
    // other: its text goes where the first is.
    if (!written[line]) out += elements_[line];
    written[line] = true;
    from = end + kGroupEnd.size();
    if (from < svg.size() && svg[from] == '\n') ++from;
  }
  out.append(svg, from, std::string::npos);

  // The outlines are used no more.
  std::string kept;
  kept.reserve(out.size());
  from = 0;
  for (std::size_t symbol = out.find(kSymbolStart); symbol != std::string::npos;
       symbol = out.find(kSymbolStart, from)) {
    const std::size_t tag_end = out.find('>', symbol);
    const std::size_t end = out.find(kSymbolEnd, symbol);
    if (tag_end == std::string::npos || end == std::string::npos) unknownForm("a glyph outline");
    const bool glyph = out.find(kGlyphSymbolId, symbol) < tag_end;
    kept.append(out, from, (glyph ? symbol : end + kSymbolEnd.size()) - from);
    from = end + kSymbolEnd.size();
    if (glyph && from < out.size() && out[from] == '\n') ++from;
  }
  kept.append(out, from, std::string::npos);
  // The group that held the outlines, now empty.
  if (const std::size_t empty = kept.find("<defs>\n<g>\n</g>\n"); empty != std::string::npos) {
    kept.erase(empty + std::string_view("<defs>\n").size(), std::string_view("<g>\n</g>\n").size());
  }
  return kept;
}

}  // namespace collide::render
