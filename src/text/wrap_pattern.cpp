// SPDX-License-Identifier: MIT
#include "text/wrap_pattern.hpp"

#include <algorithm>

namespace collide::text {
namespace {

// Halvings of the room in search of a wrap in a given number of lines: to a fraction of a pixel.
constexpr int kNarrowingSteps = 16;

// The words of `text`, [start, end) each: the pieces between its ASCII spaces (empty ones where
// spaces run together), and a piece parted after a mark Chinese and Japanese close up to the next
// character ("kg·m/s，" | "当前(1.05,"), as text::wrapText parts its words.
std::vector<std::pair<std::size_t, std::size_t>> wordSpans(std::string_view text) {
  std::vector<std::pair<std::size_t, std::size_t>> spans;
  std::size_t start = 0;
  for (std::size_t at = 0; at <= text.size();) {
    if (at == text.size() || text[at] == ' ') {
      spans.emplace_back(start, at);
      start = ++at;
      continue;
    }
    const std::size_t mark = closedUpMarkBytes(text, at);
    if (mark > 0 && at + mark < text.size() && text[at + mark] != ' ') {
      spans.emplace_back(start, at + mark);
      start = at += mark;
      continue;
    }
    ++at;
  }
  return spans;
}

// The byte offsets where the words of `text` start (wordCount of them).
std::vector<std::size_t> wordStarts(std::string_view text) {
  std::vector<std::size_t> starts;
  for (const auto& span : wordSpans(text)) starts.push_back(span.first);
  return starts;
}

std::string_view trimmed(std::string_view line) {
  while (!line.empty() && line.front() == ' ') line.remove_prefix(1);
  while (!line.empty() && line.back() == ' ') line.remove_suffix(1);
  return line;
}

// The index of the word each pattern line after the first starts with; nothing where one starts
// or ends inside a word.
std::optional<std::vector<std::size_t>> breakWords(std::string_view pattern,
                                                   const std::vector<std::string>& lines) {
  const std::vector<std::pair<std::size_t, std::size_t>> words = wordSpans(pattern);
  std::vector<std::size_t> breaks;
  std::size_t from = 0;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const std::size_t at = pattern.find(lines[k], from);
    if (lines[k].empty() || at == std::string_view::npos) return std::nullopt;
    const std::size_t end = at + lines[k].size();
    const auto first = std::find_if(words.begin(), words.end(),
                                    [&](const auto& word) { return word.first == at; });
    const bool ends_word = std::any_of(words.begin(), words.end(),
                                       [&](const auto& word) { return word.second == end; });
    if (first == words.end() || !ends_word) return std::nullopt;
    if (k > 0) breaks.push_back(static_cast<std::size_t>(first - words.begin()));
    from = end;
  }
  return breaks;
}

// `text` wrapped at the widest room under max_width_px that gives it `count` lines, where one
// does; else `lines`, its own wrap at max_width_px.
std::vector<std::string> inLines(std::string_view text, std::size_t count, double size_px,
                                 double max_width_px, const TextWidth& width,
                                 std::vector<std::string> lines) {
  // Fewer lines the wider the room: the widest that still gives `count` is found by halving.
  double narrow = 0.0, wide = max_width_px;
  for (int k = 0; k < kNarrowingSteps; ++k) {
    const double mid = 0.5 * (narrow + wide);
    (wrapText(text, size_px, mid, width).size() >= count ? narrow : wide) = mid;
  }
  std::vector<std::string> narrowed = wrapText(text, size_px, narrow, width);
  return narrowed.size() == count ? narrowed : lines;
}

}  // namespace

std::size_t wordCount(std::string_view text) {
  return wordStarts(text).size();
}

std::string widerWords(std::string_view a, std::string_view b, double size_px,
                       const TextWidth& width) {
  if (a.empty()) return std::string(b);
  const std::vector<std::pair<std::size_t, std::size_t>> spans_a = wordSpans(a);
  const std::vector<std::pair<std::size_t, std::size_t>> spans_b = wordSpans(b);
  if (spans_a.size() != spans_b.size()) return {};
  std::string out;
  for (std::size_t k = 0; k < spans_a.size(); ++k) {
    const std::string_view word_a =
        a.substr(spans_a[k].first, spans_a[k].second - spans_a[k].first);
    const std::string_view word_b =
        b.substr(spans_b[k].first, spans_b[k].second - spans_b[k].first);
    const std::string_view wider =
        width(word_b, size_px) > width(word_a, size_px) ? word_b : word_a;
    // What stands between the words in `a`: a space, or nothing after a closed-up mark.
    if (k > 0) out += a.substr(spans_a[k - 1].second, spans_a[k].first - spans_a[k - 1].second);
    out += wider;
  }
  return out;
}

std::optional<std::vector<std::string>> breakLike(std::string_view text, std::string_view pattern,
                                                  const std::vector<std::string>& pattern_lines) {
  if (wordCount(text) != wordCount(pattern)) return std::nullopt;
  const std::optional<std::vector<std::size_t>> breaks = breakWords(pattern, pattern_lines);
  if (!breaks) return std::nullopt;
  const std::vector<std::size_t> starts = wordStarts(text);
  std::vector<std::string> lines;
  std::size_t from = 0;
  for (std::size_t k = 0; k <= breaks->size(); ++k) {
    const std::size_t to = k < breaks->size() ? starts[(*breaks)[k]] : text.size();
    const std::string_view line = trimmed(text.substr(from, to - from));
    if (line.empty()) return std::nullopt;
    lines.emplace_back(line);
    from = to;
  }
  return lines;
}

std::vector<std::string> wrapLike(std::string_view text, std::string_view pattern, double size_px,
                                  double max_width_px, const TextWidth& width) {
  std::vector<std::string> lines = wrapText(text, size_px, max_width_px, width);
  if (pattern.empty()) return lines;
  const std::vector<std::string> pattern_lines = wrapText(pattern, size_px, max_width_px, width);
  const std::optional<std::vector<std::string>> like = breakLike(text, pattern, pattern_lines);
  if (like && std::all_of(like->begin(), like->end(), [&](const std::string& line) {
        return width(line, size_px) <= max_width_px;
      })) {
    return *like;
  }
  // The pattern itself parts a word (a value too wide for a line): the text keeps at least the
  // pattern's number of lines, as the layout counted them.
  return lines.size() < pattern_lines.size()
             ? inLines(text, pattern_lines.size(), size_px, max_width_px, width, std::move(lines))
             : lines;
}

}  // namespace collide::text
