#pragma once
// Where a line of text may be broken, by the Unicode line breaking algorithm (UAX #14, ICU's line
// BreakIterator). Chinese and Japanese are written without spaces: a caption in them can only be
// wrapped between the characters the rules allow (never before "、", "。", "）" or a small kana,
// never after "（" or "「").
#include <cstddef>
#include <string_view>
#include <vector>

namespace collide::text {

// The byte offsets into `utf8` where a new line may start inside a run of Han, kana or full-width
// characters: the UAX #14 break opportunities with a Han, kana or full-width character on at
// least one side, and no space on either side (spaces are breaks of their own, which the caller
// handles with its rules for numbers and units). Ascending; neither 0 nor utf8.size(). Text in
// Latin, Greek, Cyrillic, Arabic, Devanagari and Korean (Hangul is written with spaces between
// words, which the caller already breaks at) gets none.
std::vector<std::size_t> ideographicLineBreaks(std::string_view utf8);

// The byte offsets into `utf8` between its user-perceived characters (grapheme clusters, ICU's
// character BreakIterator): where a word too wide for any line may be parted without splitting a
// letter from its accents or vowel signs. Ascending; neither 0 nor utf8.size().
std::vector<std::size_t> characterBreaks(std::string_view utf8);

}  // namespace collide::text
