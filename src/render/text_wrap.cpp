#include "render/text_wrap.hpp"

#include <algorithm>
#include <cctype>

#include "text/line_breaks.hpp"

namespace collide::render {
namespace {

// Splits `text` into lines of at most max_width_px where it can: breaks at spaces, never between
// a number and its unit nor next to "=" (so "1.38 J" and "t = 1.5 s" stay whole), and inside
// Chinese and Japanese runs where UAX #14 allows.
std::vector<std::string> wrapWords(std::string_view text, double size_px, double max_width_px,
                                   const TextWidth& width) {
  std::vector<std::string> words;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(' ', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view word = text.substr(start, end - start);
    const bool glue =
        !words.empty() &&
        (words.back().empty() || words.back().back() == '=' ||
         std::isdigit(static_cast<unsigned char>(words.back().back())) || word.starts_with("=") ||
         word.empty() || word.starts_with("+") || word.starts_with("\u2212") ||
         (!word.empty() && std::isdigit(static_cast<unsigned char>(word[0])) &&
          words.back().back() != ','));
    if (glue) {
      words.back() += " ";
      words.back() += word;
    } else {
      words.emplace_back(word);
    }
    start = end + 1;
  }
  // Chinese and Japanese words (runs without spaces) break where UAX #14 allows, with nothing
  // between the pieces; every other word stays whole.
  std::vector<std::string> lines;
  for (const std::string& word : words) {
    std::size_t piece_start = 0;
    std::vector<std::size_t> ends = text::ideographicLineBreaks(word);
    ends.push_back(word.size());
    for (const std::size_t piece_end : ends) {
      const std::string piece = word.substr(piece_start, piece_end - piece_start);
      const std::string joiner = piece_start == 0 ? " " : "";
      if (!lines.empty() && width(lines.back() + joiner + piece, size_px) <= max_width_px) {
        lines.back() += joiner + piece;
      } else {
        lines.push_back(piece);
      }
      piece_start = piece_end;
    }
  }
  // A clause gap ("a   b") at a break leaves no spaces at the line's end.
  for (std::string& line : lines) {
    while (line.ends_with(' ')) line.pop_back();
  }
  return lines;
}

}  // namespace

std::vector<std::string> wrapText(std::string_view text, double size_px, double max_width_px,
                                  const TextWidth& width) {
  if (text.empty()) return {};
  // Whole clauses ("   ", "; ") per line where each fits: a readout's parts stay together.
  std::vector<std::string> clauses;
  std::size_t start = 0;
  for (;;) {
    const std::size_t wide = text.find("   ", start), semi = text.find("; ", start);
    const std::size_t at = std::min(wide, semi);
    if (at == std::string_view::npos) {
      clauses.emplace_back(text.substr(start));
      break;
    }
    clauses.emplace_back(text.substr(start, at + (at == semi ? 1 : 0) - start));
    start = at + (at == semi ? 2 : 3);
  }
  const bool whole = std::all_of(clauses.begin(), clauses.end(), [&](const std::string& c) {
    return width(c, size_px) <= max_width_px;
  });
  if (clauses.size() < 2 || !whole) return wrapWords(text, size_px, max_width_px, width);
  std::vector<std::string> lines{clauses.front()};
  for (std::size_t i = 1; i < clauses.size(); ++i) {
    // Joined as in the text: the separator kept.
    const std::string joined =
        lines.back() + (lines.back().ends_with(";") ? " " : "   ") + clauses[i];
    if (width(joined, size_px) <= max_width_px) {
      lines.back() = joined;
    } else {
      lines.push_back(clauses[i]);
    }
  }
  return lines;
}

std::vector<std::string> captionLinesBesideScale(std::string_view caption, double size_px,
                                                 double caption_width_px, double scale_room_px,
                                                 const TextWidth& width) {
  std::vector<std::string> lines = wrapText(caption, size_px, caption_width_px, width);
  if (scale_room_px > 0.0 && !lines.empty() &&
      width(lines.back(), size_px) > caption_width_px - scale_room_px) {
    lines = wrapText(caption, size_px, std::max(0.0, caption_width_px - scale_room_px), width);
  }
  return lines;
}

}  // namespace collide::render
