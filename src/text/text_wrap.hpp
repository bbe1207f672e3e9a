#pragma once
// Text broken into lines that fit a width: captions, titles and readouts. The width is measured by
// the caller (shaped advance widths), so the same breaks come out in every painter.
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace collide::text {

// Advance width in pixels of a line of text at an em size (TextPainter::width, TextMetrics::width).
using TextWidth = std::function<double(std::string_view text, double size_px)>;

// `text` in lines of at most max_width_px where it can be: broken at spaces, never between a
// number and its unit nor beside "=", between a word and the number after it ("image: 2") only
// where what they hold together is wider than a line; Chinese and Japanese also between the
// characters where UAX #14 allows a break (text::ideographicLineBreaks), so no line starts with
// "、" or "。". A word wider than the room is parted between its characters, each line holding
// as much of it as fits. Each line is a piece of `text`, with the spaces at its ends dropped.
std::vector<std::string> wrapText(std::string_view text, double size_px, double max_width_px,
                                  const TextWidth& width);

// The width of the widest piece of `text` that wrapText keeps on one line wherever a line has
// room for it: a number with its unit, a vector with its unit, "t = 1.5 s"; a Chinese or Japanese
// word only between its breaks. A room narrower than this parts what belongs together.
double widestUnbrokenPx(std::string_view text, double size_px, const TextWidth& width);

// The bytes of the full-width mark at byte `at` of `text` that Chinese and Japanese close up to
// the next character ("，" "、" "；" "：" "。"), 0 where none stands there: a word ends after it,
// as at a space, joined to the next with nothing.
std::size_t closedUpMarkBytes(std::string_view text, std::size_t at);

// The caption's lines (wrapText) in `most` lines of caption_width_px, with the scale arrow's room
// (captionScaleRoomPx) at the last line's end: when the last line runs into it, the caption is
// wrapped again with that room taken from every line.
std::vector<std::string> captionLinesBesideScale(std::string_view caption, double size_px,
                                                 double caption_width_px, double scale_room_px,
                                                 const TextWidth& width);

}  // namespace collide::text
