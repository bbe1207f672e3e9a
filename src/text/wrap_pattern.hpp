// SPDX-License-Identifier: MIT
#pragma once
// Text wrapped once for a span of a video (a shot, docs/architecture.md's layout over time): a
// readout whose numbers change from frame to frame ("now (0.00419, 0.00242) kg·m/s") is broken
// before the same words in every frame of the span, where a pattern of its widest values breaks,
// so that no line re-wraps while the video plays. The pattern is the text with each word the
// widest it is in the span (widerWords over the span's frames); the painter and the layout wrap
// the pattern and break the text as it breaks (breakLike).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "text/text_wrap.hpp"

namespace collide::text {

// How many words `text` has: the pieces between its ASCII spaces, empty ones where spaces run
// together ("collisions: 4   Σp" has five), a piece also ending after a mark Chinese and Japanese
// close up to the next character ("kg·m/s，当前" has two; text::closedUpMarkBytes).
std::size_t wordCount(std::string_view text);

// `a` and `b` word by word, each word the wider of the two at size_px (a's on a tie), a vector's
// words all from the text whose vector is wider, so the pattern shows a vector a frame shows;
// empty where they differ in their number of words. An empty `a` gives `b`.
std::string widerWords(std::string_view a, std::string_view b, double size_px,
                       const TextWidth& width);

// `text` broken before the same words as `pattern_lines`, the lines `pattern` was wrapped into
// (each a piece of it, in order, the spaces at their ends dropped), the spaces at each line's ends
// dropped; nothing where the two differ in their number of words, where a pattern line starts
// or ends inside a word (a word parted between its characters, an ellipsis) or where a line
// would be empty.
std::optional<std::vector<std::string>> breakLike(std::string_view text, std::string_view pattern,
                                                  const std::vector<std::string>& pattern_lines);

// `text` with each number (its digits, the marks between them and its sign) written "#": the
// texts of a video's frames that differ only in their numbers have the same shape, and are
// wrapped like one pattern ("t = 0.001 s: no energy lost" and "t = 0.5 s: energy lost 198 J"
// are of two shapes).
std::string wordShape(std::string_view text);

// The lines `text` is drawn in at max_width_px: where `pattern` is set and `text` breaks like it
// (breakLike) into lines that each fit, those; else text::wrapText's. Where that gives fewer
// than `least_lines` (a text of its shot takes that many), spread over more lines, as evenly as
// they go without parting what belongs together (text::widestUnbrokenPx): the pattern spread
// and the text broken like it where it can be, else the text itself.
std::vector<std::string> wrapLike(std::string_view text, std::string_view pattern, double size_px,
                                  double max_width_px, const TextWidth& width,
                                  std::size_t least_lines = 0);

}  // namespace collide::text
