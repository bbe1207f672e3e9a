#include "render/text/text.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include "text/text_wrap.hpp"
#include "text/wrap_pattern.hpp"

namespace collide::render {
namespace {

constexpr double kCapHalf = 0.36;  // half the capital height, em (DejaVu: 0.73 / 2)
constexpr char32_t kEllipsis = U'\u2026';

}  // namespace

const ShapedLine& TextPainter::shaped(std::string_view text, double size_px) {
  const long size = std::lround(size_px);
  key_.assign(reinterpret_cast<const char*>(&size), sizeof size);
  key_.append(text);
  if (const auto found = recent_.find(key_); found != recent_.end()) return found->second;
  if (recent_.size() >= kLinesPerGeneration) {
    older_ = std::move(recent_);
    recent_.clear();
  }
  if (auto node = older_.extract(key_)) return recent_.insert(std::move(node)).position->second;
  return recent_.emplace(key_, shapeLine(fonts(), text, size_px)).first->second;
}

double TextPainter::width(std::string_view text, double size_px) {
  return shaped(text, size_px).width_px;
}

// Both shortenings below search by bisection: a shortened text is wider the more it keeps, and
// every width is a shaping of the whole candidate, so trying cut after cut from the end made a
// caption of a few hundred clauses (300 gas disks' velocities) cost seconds a frame.

std::string TextPainter::elide(std::string_view text, double size_px, double max_width_px) {
  if (width(text, size_px) <= max_width_px) return std::string(text);
  const std::u32string chars = decodeUtf8(text);
  // The first `kept` characters, without trailing spaces or commas, and "…".
  auto candidate = [&](std::size_t kept) {
    while (kept > 0 && (chars[kept - 1] == U' ' || chars[kept - 1] == U',')) --kept;
    return kept == 0 ? std::string() : encodeUtf8(chars.substr(0, kept) + kEllipsis);
  };
  // The most characters whose candidate fits: fits(lo) holds (0 keeps nothing), fits(hi) fails.
  std::size_t lo = 0, hi = chars.size();
  while (hi - lo > 1) {
    const std::size_t mid = lo + (hi - lo) / 2;
    (width(candidate(mid), size_px) <= max_width_px ? lo : hi) = mid;
  }
  return candidate(lo);
}

namespace {

// The beginning of `text` up to `cut`, without the punctuation before it, and "…"; `dangling` when
// the cut would part a name from its value ("t =" without the time) or a number from its unit
// ("2.27" without "N·s").
struct CutText {
  std::string text;
  bool dangling = false;
};

CutText cutBefore(std::string_view text, std::size_t cut, bool at_spaces) {
  CutText out{std::string(text.substr(0, cut))};
  std::string& candidate = out.text;
  while (!candidate.empty() && (candidate.back() == ':' || candidate.back() == ',' ||
                                candidate.back() == ';' || candidate.back() == ' ')) {
    candidate.pop_back();
  }
  const std::string_view after = text.substr(cut);
  const bool unit_follows = after.size() > 1 && after[0] == ' ' &&
                            !std::isdigit(static_cast<unsigned char>(after[1])) && after[1] != '(';
  out.dangling =
      (!candidate.empty() && candidate.back() == '=') || after.starts_with(" =") ||
      (!candidate.empty() && std::isdigit(static_cast<unsigned char>(candidate.back())) &&
       unit_follows && at_spaces);
  candidate += encodeUtf8(std::u32string(1, kEllipsis));
  return out;
}

}  // namespace

std::string TextPainter::fitWhole(std::string_view text, double size_px, double max_width_px) {
  if (width(text, size_px) <= max_width_px) return std::string(text);
  static const std::vector<std::vector<std::string_view>> kBoundaries = {
      {"; ", "   "}, {", ", " ("}, {" "}};
  for (const std::vector<std::string_view>& kind : kBoundaries) {
    std::vector<std::size_t> cuts;
    for (std::string_view separator : kind) {
      for (std::size_t at = text.find(separator); at != std::string_view::npos;
           at = text.find(separator, at + 1)) {
        if (at > 0) cuts.push_back(at);
      }
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    const bool at_spaces = kind.front() == " ";
    auto fits = [&](std::size_t i) {
      return width(cutBefore(text, cuts[i], at_spaces).text, size_px) <= max_width_px;
    };
    // How many cuts, from the first, give a beginning that fits: the longest fitting one is the
    // last of them; the ones before it are shorter and fit too.
    std::size_t fitting = 0, too_many = cuts.size() + 1;
    while (too_many - fitting > 1) {
      const std::size_t mid = fitting + (too_many - fitting) / 2;
      (fits(mid - 1) ? fitting : too_many) = mid;
    }
    // The longest fitting beginning that parts nothing that belongs together.
    for (std::size_t i = fitting; i-- > 0;) {
      const CutText candidate = cutBefore(text, cuts[i], at_spaces);
      if (!candidate.dangling && candidate.text.size() > 3 &&
          width(candidate.text, size_px) <= max_width_px) {
        return candidate.text;
      }
    }
  }
  return elide(text, size_px, max_width_px);
}

std::vector<std::string> TextPainter::wrap(std::string_view text, double size_px,
                                           double max_width_px, int max_lines,
                                           std::string_view pattern, std::size_t least_lines) {
  std::string key;
  for (const double number : {size_px, max_width_px}) {
    key.append(reinterpret_cast<const char*>(&number), sizeof number);
  }
  const std::size_t counts[] = {static_cast<std::size_t>(max_lines), least_lines, pattern.size()};
  key.append(reinterpret_cast<const char*>(counts), sizeof counts);
  key.append(pattern);
  key.append(text);
  if (const auto found = recent_wraps_.find(key); found != recent_wraps_.end()) {
    return found->second;
  }
  if (recent_wraps_.size() >= kWrapsPerGeneration) {
    older_wraps_ = std::move(recent_wraps_);
    recent_wraps_.clear();
  }
  if (auto node = older_wraps_.extract(key)) {
    return recent_wraps_.insert(std::move(node)).position->second;
  }
  return recent_wraps_
      .emplace(std::move(key),
               wrapAnew(text, size_px, max_width_px, max_lines, pattern, least_lines))
      .first->second;
}

std::vector<std::string> TextPainter::wrapAnew(std::string_view text, double size_px,
                                               double max_width_px, int max_lines,
                                               std::string_view pattern, std::size_t least_lines) {
  const text::TextWidth measure = [this](std::string_view line, double size) {
    return width(line, size);
  };
  std::vector<std::string> lines =
      text::wrapLike(text, pattern, size_px, max_width_px, measure, least_lines);
  const std::size_t most = static_cast<std::size_t>(std::max(1, max_lines));
  if (lines.size() > most) {
    // The last line takes the rest of the text as written (a Chinese or Japanese line break has
    // no space to put back): each line is a piece of the text, in order.
    std::size_t rest_at = 0;
    for (std::size_t i = 0; i < most; ++i) {
      rest_at = text.find(lines[i], rest_at);
      if (i + 1 < most) rest_at += lines[i].size();
    }
    lines.resize(most);
    if (rest_at != std::string_view::npos) lines.back() = std::string(text.substr(rest_at));
  }
  for (std::string& line : lines) line = fitWhole(line, size_px, max_width_px);
  return lines;
}

double TextPainter::ascender(double size_px) {
  return fonts().metrics(std::max(1, static_cast<int>(std::lround(size_px)))).ascender_px;
}

double TextPainter::descender(double size_px) {
  return fonts().metrics(std::max(1, static_cast<int>(std::lround(size_px)))).descender_px;
}

PlacedLine TextPainter::place(std::string_view text, const core::Vec2& anchor_px, double size_px,
                              HAlign h, VAlign v) {
  const double asc = ascender(size_px), desc = descender(size_px);
  const ShapedLine& shape = shaped(text, size_px);
  const double total = shape.width_px;

  double x = anchor_px.x();
  if (h == HAlign::kCenter) x -= 0.5 * total;
  if (h == HAlign::kRight) x -= total;
  double baseline = anchor_px.y();
  if (v == VAlign::kTop) baseline += asc;
  if (v == VAlign::kMiddle) baseline += kCapHalf * std::lround(size_px);
  if (v == VAlign::kBottom) baseline -= desc;
  baseline = std::round(baseline);

  PlacedLine line;
  line.text = shape.text;
  line.box = {x, baseline - asc, x + total, baseline + desc};
  line.glyphs.reserve(shape.glyphs.size());
  for (const ShapedGlyph& g : shape.glyphs) {
    line.glyphs.push_back({g.font, g.glyph_id, g.drawn, shape.text[g.cluster_begin],
                           g.cluster_begin, g.cluster_end, g.pixel_size, x + g.x_px,
                           baseline + std::round(g.shift_px), g.advance_px, g.right_to_left});
  }
  return line;
}

frame::PixelRect TextPainter::draw(std::string_view text, const core::Vec2& anchor_px,
                                   double size_px, const frame::Rgba& color, HAlign h, VAlign v,
                                   std::vector<TextVertex>& out) {
  const PlacedLine line = place(text, anchor_px, size_px, h, v);
  drawPlaced(line, color, out);
  return line.box;
}

void TextPainter::drawPlaced(const PlacedLine& line, const frame::Rgba& color,
                             std::vector<TextVertex>& out) {
  for (const PlacedGlyph& placed : line.glyphs) {
    const AtlasGlyph& g = atlas_.glyph(placed.font, placed.glyph_id, placed.pixel_size);
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
}

}  // namespace collide::render
