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

using Spans = std::vector<std::pair<std::size_t, std::size_t>>;

// The index of the word of `text` that closes the brackets its word `first` opens ("(1.5," of
// "(1.5, 2)": that of "2)"); `first` where it opens none, the last word where they stay open.
std::size_t vectorEnd(std::string_view text, const Spans& words, std::size_t first) {
  int depth = 0;
  for (std::size_t k = first; k < words.size(); ++k) {
    for (const char c : text.substr(words[k].first, words[k].second - words[k].first)) {
      depth += c == '(' ? 1 : c == ')' ? -1 : 0;
    }
    if (depth <= 0) return k;
  }
  return words.size() - 1;
}

// The byte offsets where the words of `text` start (wordCount of them).
std::vector<std::size_t> wordStarts(std::string_view text) {
  std::vector<std::size_t> starts;
  for (const auto& span : wordSpans(text)) starts.push_back(span.first);
  return starts;
}

// The bytes of the decimal digit at byte `at` of `text`, 0 where none stands there: ASCII,
// Arabic-Indic (U+0660..9), Eastern Arabic-Indic (U+06F0..9) and Devanagari (U+0966..F).
std::size_t digitBytes(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t k) {
    return at + k < text.size() ? static_cast<unsigned char>(text[at + k]) : 0u;
  };
  if (byte(0) >= '0' && byte(0) <= '9') return 1;
  if (byte(0) == 0xD9 && byte(1) >= 0xA0 && byte(1) <= 0xA9) return 2;
  if (byte(0) == 0xDB && byte(1) >= 0xB0 && byte(1) <= 0xB9) return 2;
  if (byte(0) == 0xE0 && byte(1) == 0xA5 && byte(2) >= 0xA6 && byte(2) <= 0xAF) return 3;
  return 0;
}

// The bytes of a mark that may stand between two digits of one number at byte `at` (a decimal
// point or comma, Arabic's decimal and thousands separators, a thin or narrow no-break space),
// 0 where none does.
std::size_t numberMarkBytes(std::string_view text, std::size_t at) {
  for (const std::string_view mark : {".", ",", "\u066B", "\u066C", "\u2009", "\u202F"}) {
    if (text.substr(at).starts_with(mark)) return mark.size();
  }
  return 0;
}

std::string_view trimmed(std::string_view line) {
  while (!line.empty() && line.front() == ' ') line.remove_prefix(1);
  while (!line.empty() && line.back() == ' ') line.remove_suffix(1);
  return line;
}

// Where a pattern line after the first starts: the index of the word it starts in and how many
// bytes into it (0: at its start; more: a Chinese or Japanese word broken between characters).
struct WordBreak {
  std::size_t word = 0;
  std::size_t offset = 0;
};

// The index of the word of `words` that holds byte `at` (where a word starts there, that one).
std::optional<std::size_t> wordHolding(
    const std::vector<std::pair<std::size_t, std::size_t>>& words, std::size_t at) {
  for (std::size_t k = 0; k < words.size(); ++k) {
    if (words[k].first == at) return k;
  }
  for (std::size_t k = 0; k < words.size(); ++k) {
    if (words[k].first < at && at < words[k].second) return k;
  }
  return std::nullopt;
}

// Where each pattern line after the first starts; nothing where a line is no piece of the
// pattern, or one ends inside a word the next does not go on with.
std::optional<std::vector<WordBreak>> breakWords(std::string_view pattern,
                                                 const std::vector<std::string>& lines) {
  const std::vector<std::pair<std::size_t, std::size_t>> words = wordSpans(pattern);
  std::vector<WordBreak> breaks;
  std::size_t from = 0;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const std::size_t at = pattern.find(lines[k], from);
    if (lines[k].empty() || at == std::string_view::npos) return std::nullopt;
    const std::optional<std::size_t> first = wordHolding(words, at);
    if (!first || (k > 0 && words[*first].first != at && at != from)) return std::nullopt;
    if (k > 0) breaks.push_back({*first, at - words[*first].first});
    from = at + lines[k].size();
  }
  return breaks;
}

// Whether `text` ends with a digit (text::wordShape's scripts).
bool endsInDigit(std::string_view text) {
  for (std::size_t bytes = 1; bytes <= 3 && bytes <= text.size(); ++bytes) {
    if (digitBytes(text, text.size() - bytes) == bytes) return true;
  }
  return false;
}

// Where `text` breaks after its word `word`: at the first word start after it that stands
// outside brackets and after no digit, so never inside a vector nor between a number and its
// unit; nothing where none follows.
std::optional<std::size_t> breakAfter(std::string_view text, const Spans& words, std::size_t word) {
  for (std::size_t k = word + 1; k < words.size(); ++k) {
    const std::string_view before = text.substr(0, words[k].first);
    const auto opened = std::count(before.begin(), before.end(), '(') -
                        std::count(before.begin(), before.end(), ')');
    const std::string_view last =
        trimmed(text.substr(words[k - 1].first, words[k - 1].second - words[k - 1].first));
    if (opened <= 0 && !endsInDigit(last)) return words[k].first;
  }
  return std::nullopt;
}

// Where `text`, of as many words as `pattern`, breaks as `pattern` does at `at`: the same word's
// start, or as far into it as the pattern's where both words begin with the same characters
// there (a Chinese word whose number differs). A word the pattern parts between its characters
// (a value too wide for a line) where the text's differs: the text breaks after it instead
// (breakAfter), as it does in every frame.
std::optional<std::size_t> textBreak(std::string_view text, std::string_view pattern,
                                     const Spans& text_words, const Spans& pattern_words,
                                     const WordBreak& at) {
  const std::pair<std::size_t, std::size_t>& text_word = text_words[at.word];
  if (at.offset == 0) return text_word.first;
  if (text_word.first + at.offset < text_word.second &&
      text.substr(text_word.first, at.offset) ==
          pattern.substr(pattern_words[at.word].first, at.offset)) {
    return text_word.first + at.offset;
  }
  return breakAfter(text, text_words, at.word);
}

// `text` spread over `count` lines, as evenly as they go: wrapped at the narrowest room under
// max_width_px that takes no more, never narrower than what must stay whole on a line
// (text::widestUnbrokenPx); nothing where that does not give more lines than its own wrap.
std::optional<std::vector<std::string>> spread(std::string_view text, std::size_t count,
                                               double size_px, double max_width_px,
                                               const TextWidth& width) {
  // More lines the narrower the room: the narrowest that still gives `count` is found by halving.
  double narrow = std::min(widestUnbrokenPx(text, size_px, width), max_width_px);
  double wide = max_width_px;
  if (wrapText(text, size_px, narrow, width).size() <= count) wide = narrow;
  for (int k = 0; k < kNarrowingSteps && wide > narrow; ++k) {
    const double mid = 0.5 * (narrow + wide);
    (wrapText(text, size_px, mid, width).size() <= count ? wide : narrow) = mid;
  }
  std::vector<std::string> lines = wrapText(text, size_px, wide, width);
  if (lines.size() <= wrapText(text, size_px, max_width_px, width).size()) return std::nullopt;
  return lines;
}

// `text` broken like `pattern` into lines that each fit; nothing where it does not break like it.
std::optional<std::vector<std::string>> fittingLike(std::string_view text, std::string_view pattern,
                                                    const std::vector<std::string>& pattern_lines,
                                                    double size_px, double max_width_px,
                                                    const TextWidth& width) {
  std::optional<std::vector<std::string>> like = breakLike(text, pattern, pattern_lines);
  if (like && std::all_of(like->begin(), like->end(), [&](const std::string& line) {
        return width(line, size_px) <= max_width_px;
      })) {
    return like;
  }
  return std::nullopt;
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
    // A vector's words are taken together, all from one text: its components at their widest
    // each would make a vector no frame shows, wider than any ("(−0.0000846, 0.0000293)" from
    // "(−0.0000846, −0.0129)" and "(0.000177, 0.0000293)").
    const std::size_t last = std::min(vectorEnd(a, spans_a, k), vectorEnd(b, spans_b, k));
    const std::string_view words_a =
        a.substr(spans_a[k].first, spans_a[last].second - spans_a[k].first);
    const std::string_view words_b =
        b.substr(spans_b[k].first, spans_b[last].second - spans_b[k].first);
    const std::string_view wider =
        width(words_b, size_px) > width(words_a, size_px) ? words_b : words_a;
    // What stands between the words in `a`: a space, or nothing after a closed-up mark.
    if (k > 0) out += a.substr(spans_a[k - 1].second, spans_a[k].first - spans_a[k - 1].second);
    out += wider;
    k = last;
  }
  return out;
}

std::optional<std::vector<std::string>> breakLike(std::string_view text, std::string_view pattern,
                                                  const std::vector<std::string>& pattern_lines) {
  const std::vector<std::pair<std::size_t, std::size_t>> text_words = wordSpans(text);
  const std::vector<std::pair<std::size_t, std::size_t>> pattern_words = wordSpans(pattern);
  if (text_words.size() != pattern_words.size()) return std::nullopt;
  const std::optional<std::vector<WordBreak>> breaks = breakWords(pattern, pattern_lines);
  if (!breaks) return std::nullopt;
  std::vector<std::string> lines;
  std::size_t from = 0;
  for (std::size_t k = 0; k <= breaks->size(); ++k) {
    std::size_t to = text.size();
    if (k < breaks->size()) {
      const WordBreak& at = (*breaks)[k];
      const std::optional<std::size_t> there =
          textBreak(text, pattern, text_words, pattern_words, at);
      if (!there || *there < from) return std::nullopt;
      to = *there;
    }
    const std::string_view line = trimmed(text.substr(from, to - from));
    if (line.empty()) return std::nullopt;
    lines.emplace_back(line);
    from = to;
  }
  return lines;
}

std::string wordShape(std::string_view text) {
  std::string shape;
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t digit = digitBytes(text, at);
    if (digit == 0) {
      shape += text[at++];
      continue;
    }
    // The sign before the number is part of it.
    for (const std::string_view sign : {"\u2212", "-", "+", "\u061C"}) {
      if (shape.ends_with(sign)) shape.resize(shape.size() - sign.size());
    }
    at += digit;
    while (at < text.size()) {
      const std::size_t mark = numberMarkBytes(text, at);
      const std::size_t next = digitBytes(text, at + mark);
      if (next == 0) break;
      at += mark + next;
    }
    shape += '#';
  }
  return shape;
}

std::vector<std::string> wrapLike(std::string_view text, std::string_view pattern, double size_px,
                                  double max_width_px, const TextWidth& width,
                                  std::size_t least_lines) {
  std::vector<std::string> lines = wrapText(text, size_px, max_width_px, width);
  std::vector<std::string> pattern_lines;
  if (!pattern.empty()) {
    pattern_lines = wrapText(pattern, size_px, max_width_px, width);
    if (auto like = fittingLike(text, pattern, pattern_lines, size_px, max_width_px, width)) {
      lines = std::move(*like);
    } else {
      // The pattern itself parts a word (a value too wide for a line): the text keeps at least
      // the pattern's number of lines, as the layout counted them.
      least_lines = std::max(least_lines, pattern_lines.size());
    }
  }
  if (lines.size() >= least_lines) return lines;
  // Spread over more lines: the pattern, where the text breaks like it, so every frame of the
  // same words breaks alike; else the text itself.
  if (!pattern.empty()) {
    if (auto spread_pattern = spread(pattern, least_lines, size_px, max_width_px, width)) {
      if (auto like = fittingLike(text, pattern, *spread_pattern, size_px, max_width_px, width)) {
        return *like;
      }
    }
  }
  std::optional<std::vector<std::string>> spread_text =
      spread(text, least_lines, size_px, max_width_px, width);
  return spread_text ? *spread_text : lines;
}

}  // namespace collide::text
