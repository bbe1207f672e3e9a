#include "render/text.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace collide::render {
namespace {

constexpr double kSubscriptDrop = 0.18;   // em below the baseline
constexpr double kSuperscriptRise = 0.4;  // em above the baseline
constexpr double kCapHalf = 0.36;         // half the capital height, em (DejaVu: 0.73 / 2)
constexpr char32_t kPrime = U'\u2032';
constexpr char32_t kEllipsis = U'\u2026';

// The ordinary character a sub- or superscript stands for; 0 if `c` is neither.
char32_t subscriptBase(char32_t c) {
  if (c >= 0x2080 && c <= 0x2089) return U'0' + (c - 0x2080);
  static constexpr char32_t kRest[] = {U'+', U'\u2212', U'=', U'(',      U')', 0,    U'a',
                                       U'e', U'o',      U'x', U'\u0259', U'h', U'k', U'l',
                                       U'm', U'n',      U'p', U's',      U't'};
  if (c >= 0x208A && c <= 0x209C) return kRest[c - 0x208A];
  return 0;
}

char32_t superscriptBase(char32_t c) {
  switch (c) {
    case 0x00B9:
      return U'1';
    case 0x00B2:
      return U'2';
    case 0x00B3:
      return U'3';
    case 0x2070:
      return U'0';
    case 0x2071:
      return U'i';
    case 0x207A:
      return U'+';
    case 0x207B:
      return U'\u2212';
    case 0x207F:
      return U'n';
    default:
      break;
  }
  if (c >= 0x2074 && c <= 0x2079) return U'4' + (c - 0x2074);
  return 0;
}

}  // namespace

std::u32string decodeUtf8(std::string_view text) {
  std::u32string out;
  std::size_t i = 0;
  while (i < text.size()) {
    const auto byte = static_cast<unsigned char>(text[i]);
    int extra = 0;
    char32_t c = 0;
    if (byte < 0x80) {
      c = byte;
    } else if ((byte & 0xE0) == 0xC0) {
      c = byte & 0x1F, extra = 1;
    } else if ((byte & 0xF0) == 0xE0) {
      c = byte & 0x0F, extra = 2;
    } else if ((byte & 0xF8) == 0xF0) {
      c = byte & 0x07, extra = 3;
    } else {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    bool ok = true;
    for (int k = 1; ok && k <= extra; ++k) {
      if (i + k >= text.size()) {
        ok = false;
        break;
      }
      const auto next = static_cast<unsigned char>(text[i + k]);
      if ((next & 0xC0) != 0x80) ok = false;
      c = (c << 6) | (next & 0x3F);
    }
    if (!ok) {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    out.push_back(c);
    i += extra + 1;
  }
  return out;
}

std::string encodeUtf8(const std::u32string& text) {
  std::string out;
  for (char32_t c : text) {
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else if (c < 0x800) {
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
      out += static_cast<char>(0xE0 | (c >> 12));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (c >> 18));
      out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    }
  }
  return out;
}

std::vector<TextPainter::Piece> TextPainter::shape(std::string_view text, double size_px) {
  const int size = std::max(1, static_cast<int>(std::lround(size_px)));
  const int script = std::max(1, static_cast<int>(std::lround(kScriptScale * size)));
  std::vector<Piece> pieces;
  for (char32_t c : decodeUtf8(text)) {
    if (const char32_t base = subscriptBase(c); base != 0) {
      pieces.push_back({base, c, script, std::round(kSubscriptDrop * size)});
    } else if (const char32_t up = superscriptBase(c); up != 0) {
      pieces.push_back({up, c, script, -std::round(kSuperscriptRise * size)});
    } else if (c == kPrime && !atlas_.font().hasGlyph(kPrime)) {
      pieces.push_back({U'\'', c, size, 0.0});
    } else {
      pieces.push_back({c, c, size, 0.0});
    }
  }
  return pieces;
}

double TextPainter::advance(const Piece& piece) {
  return atlas_.glyph(piece.codepoint, piece.pixel_size).advance_px;
}

double TextPainter::width(std::string_view text, double size_px) {
  double w = 0.0;
  for (const Piece& piece : shape(text, size_px)) w += advance(piece);
  return w;
}

std::string TextPainter::elide(std::string_view text, double size_px, double max_width_px) {
  if (width(text, size_px) <= max_width_px) return std::string(text);
  std::u32string chars = decodeUtf8(text);
  while (!chars.empty()) {
    chars.pop_back();
    while (!chars.empty() && (chars.back() == U' ' || chars.back() == U',')) chars.pop_back();
    const std::string candidate = encodeUtf8(chars + kEllipsis);
    if (width(candidate, size_px) <= max_width_px) return candidate;
  }
  return {};
}

std::string TextPainter::fitWhole(std::string_view text, double size_px, double max_width_px) {
  if (width(text, size_px) <= max_width_px) return std::string(text);
  static const std::vector<std::vector<std::string_view>> kBoundaries = {
      {"; ", "   "}, {", ", " ("}, {" "}};
  for (const std::vector<std::string_view>& kind : kBoundaries) {
    // Cut points of this kind, last first: the longest beginning that fits wins.
    std::vector<std::size_t> cuts;
    for (std::string_view separator : kind) {
      for (std::size_t at = text.find(separator); at != std::string_view::npos;
           at = text.find(separator, at + 1)) {
        if (at > 0) cuts.push_back(at);
      }
    }
    std::sort(cuts.rbegin(), cuts.rend());
    for (std::size_t cut : cuts) {
      std::string candidate(text.substr(0, cut));
      while (!candidate.empty() && (candidate.back() == ':' || candidate.back() == ',' ||
                                    candidate.back() == ';' || candidate.back() == ' ')) {
        candidate.pop_back();
      }
      // Never part a name from its value ("t =" without the time).
      // Nor a number from its unit ("2.27" without "N·s").
      const std::string_view after = text.substr(cut);
      const bool unit_follows = after.size() > 1 && after[0] == ' ' &&
                                !std::isdigit(static_cast<unsigned char>(after[1])) &&
                                after[1] != '(';
      const bool dangling =
          (!candidate.empty() && candidate.back() == '=') || after.starts_with(" =") ||
          (!candidate.empty() && std::isdigit(static_cast<unsigned char>(candidate.back())) &&
           unit_follows && kind.front() == " ");
      candidate += encodeUtf8(std::u32string(1, kEllipsis));
      if (!dangling && candidate.size() > 3 && width(candidate, size_px) <= max_width_px) {
        return candidate;
      }
    }
  }
  return elide(text, size_px, max_width_px);
}

std::vector<std::string> TextPainter::wrap(std::string_view text, double size_px,
                                           double max_width_px, int max_lines) {
  const TextWidth measure = [this](std::string_view line, double size) {
    return width(line, size);
  };
  std::vector<std::string> lines = wrapText(text, size_px, max_width_px, measure);
  const std::size_t most = static_cast<std::size_t>(std::max(1, max_lines));
  if (lines.size() > most) {
    std::string rest = lines[most - 1];
    for (std::size_t i = most; i < lines.size(); ++i) rest += " " + lines[i];
    lines.resize(most);
    lines.back() = rest;
  }
  for (std::string& line : lines) line = fitWhole(line, size_px, max_width_px);
  return lines;
}

double TextPainter::ascender(double size_px) {
  return atlas_.font().metrics(std::max(1, static_cast<int>(std::lround(size_px)))).ascender_px;
}

double TextPainter::descender(double size_px) {
  return atlas_.font().metrics(std::max(1, static_cast<int>(std::lround(size_px)))).descender_px;
}

PlacedLine TextPainter::place(std::string_view text, const core::Vec2& anchor_px, double size_px,
                              HAlign h, VAlign v) {
  const std::vector<Piece> pieces = shape(text, size_px);
  double total = 0.0;
  for (const Piece& piece : pieces) total += advance(piece);
  const double asc = ascender(size_px), desc = descender(size_px);

  double x = anchor_px.x();
  if (h == HAlign::kCenter) x -= 0.5 * total;
  if (h == HAlign::kRight) x -= total;
  double baseline = anchor_px.y();
  if (v == VAlign::kTop) baseline += asc;
  if (v == VAlign::kMiddle) baseline += kCapHalf * std::lround(size_px);
  if (v == VAlign::kBottom) baseline -= desc;
  baseline = std::round(baseline);

  PlacedLine line;
  line.box = {x, baseline - asc, x + total, baseline + desc};
  line.glyphs.reserve(pieces.size());
  for (const Piece& piece : pieces) {
    line.glyphs.push_back(
        {piece.codepoint, piece.source, piece.pixel_size, x, baseline + piece.shift_px});
    x += advance(piece);
  }
  return line;
}

PixelRect TextPainter::draw(std::string_view text, const core::Vec2& anchor_px, double size_px,
                            const Rgba& color, HAlign h, VAlign v, std::vector<TextVertex>& out) {
  const PlacedLine line = place(text, anchor_px, size_px, h, v);
  for (const PlacedGlyph& placed : line.glyphs) {
    const AtlasGlyph& g = atlas_.glyph(placed.drawn, placed.pixel_size);
    if (g.width <= 0 || g.rows <= 0) continue;
    // Whole-pixel placement: one texel per pixel, no filtering.
    const float x0 = static_cast<float>(std::round(placed.pen_x_px) + g.left);
    const float y0 = static_cast<float>(placed.baseline_px - g.top);
    const float x1 = x0 + static_cast<float>(g.width), y1 = y0 + static_cast<float>(g.rows);
    const float u0 = static_cast<float>(g.x), v0 = static_cast<float>(g.y);
    const float u1 = u0 + static_cast<float>(g.width), v1 = v0 + static_cast<float>(g.rows);
    const TextVertex a{x0, y0, u0, v0, color.r, color.g, color.b, color.a};
    const TextVertex b{x1, y0, u1, v0, color.r, color.g, color.b, color.a};
    const TextVertex c{x1, y1, u1, v1, color.r, color.g, color.b, color.a};
    const TextVertex d{x0, y1, u0, v1, color.r, color.g, color.b, color.a};
    out.insert(out.end(), {a, b, c, a, c, d});
  }
  return line.box;
}

}  // namespace collide::render
