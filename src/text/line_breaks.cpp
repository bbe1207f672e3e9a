#include "text/line_breaks.hpp"

#include <unicode/brkiter.h>
#include <unicode/locid.h>
#include <unicode/uchar.h>
#include <unicode/unistr.h>
#include <unicode/utf8.h>

#include <memory>

namespace collide::text {
namespace {

// A character whose neighbourhood UAX #14 breaks without spaces: Han ideographs, kana and the
// full-width punctuation set with them. Hangul is wide too but Korean breaks at spaces.
bool breaksWithoutSpaces(UChar32 c) {
  const auto width = static_cast<UEastAsianWidth>(u_getIntPropertyValue(c, UCHAR_EAST_ASIAN_WIDTH));
  if (width != U_EA_WIDE && width != U_EA_FULLWIDTH) return false;
  const auto line_class = static_cast<ULineBreak>(u_getIntPropertyValue(c, UCHAR_LINE_BREAK));
  return line_class != U_LB_H2 && line_class != U_LB_H3 && line_class != U_LB_JL &&
         line_class != U_LB_JV && line_class != U_LB_JT;
}

// The code point that starts at byte `at` and the one that ends there.
UChar32 codePointAt(std::string_view utf8, std::size_t at) {
  int32_t i = static_cast<int32_t>(at);
  UChar32 c = 0;
  U8_NEXT(utf8.data(), i, static_cast<int32_t>(utf8.size()), c);
  return c;
}
UChar32 codePointBefore(std::string_view utf8, std::size_t at) {
  int32_t i = static_cast<int32_t>(at);
  UChar32 c = 0;
  U8_PREV(utf8.data(), 0, i, c);
  return c;
}

// Whether `utf8` may have a break to report: a break needs a character for which
// breaksWithoutSpaces holds on one side of it, so well-formed text without one has none. Ill-formed
// text is left to ICU's own decoding.
bool mayHaveIdeographicBreaks(std::string_view utf8) {
  const auto length = static_cast<int32_t>(utf8.size());
  for (int32_t i = 0; i < length;) {
    UChar32 c = 0;
    U8_NEXT(utf8.data(), i, length, c);
    if (c < 0 || breaksWithoutSpaces(c)) return true;
  }
  return false;
}

// A line break iterator of its own for the caller. Building one decodes ICU's rule data, and
// frames wrap their texts word by word: built per word, it was 2 % of a batch's CPU. A clone of one
// built once shares that data (ICU clones a const iterator safely from any thread).
std::unique_ptr<icu::BreakIterator> lineIterator() {
  static const std::unique_ptr<const icu::BreakIterator> prototype = [] {
    UErrorCode status = U_ZERO_ERROR;
    // The root locale's rules are UAX #14's defaults, the same for every language: they forbid
    // a break before closing punctuation, small kana and the prolonged sound mark ("strict").
    std::unique_ptr<icu::BreakIterator> iterator(
        icu::BreakIterator::createLineInstance(icu::Locale::getRoot(), status));
    if (U_FAILURE(status)) iterator.reset();
    return std::unique_ptr<const icu::BreakIterator>(std::move(iterator));
  }();
  if (prototype == nullptr) return nullptr;
  return std::unique_ptr<icu::BreakIterator>(prototype->clone());
}

}  // namespace

std::vector<std::size_t> ideographicLineBreaks(std::string_view utf8) {
  std::vector<std::size_t> breaks;
  // Latin, Greek, Cyrillic, Arabic and the rest (nearly every word a frame wraps) skip ICU.
  if (!mayHaveIdeographicBreaks(utf8)) return breaks;
  const std::unique_ptr<icu::BreakIterator> lines = lineIterator();
  if (lines == nullptr) return breaks;
  const icu::UnicodeString text = icu::UnicodeString::fromUTF8(
      icu::StringPiece(utf8.data(), static_cast<int32_t>(utf8.size())));
  lines->setText(text);
  // UTF-16 offsets from the iterator, walked alongside UTF-8 offsets.
  int32_t utf16_at = 0;
  std::size_t utf8_at = 0;
  for (int32_t next = lines->next(); next != icu::BreakIterator::DONE && next < text.length();
       next = lines->next()) {
    while (utf16_at < next) {
      const UChar32 c = text.char32At(utf16_at);
      utf16_at += U16_LENGTH(c);
      utf8_at += static_cast<std::size_t>(U8_LENGTH(c));
    }
    const UChar32 before = codePointBefore(utf8, utf8_at), after = codePointAt(utf8, utf8_at);
    if (u_isUWhiteSpace(before) || u_isUWhiteSpace(after)) continue;
    if (breaksWithoutSpaces(before) || breaksWithoutSpaces(after)) breaks.push_back(utf8_at);
  }
  return breaks;
}

std::vector<std::size_t> characterBreaks(std::string_view utf8) {
  std::vector<std::size_t> breaks;
  if (utf8.empty()) return breaks;
  UErrorCode status = U_ZERO_ERROR;
  std::unique_ptr<icu::BreakIterator> characters(
      icu::BreakIterator::createCharacterInstance(icu::Locale::getRoot(), status));
  if (U_FAILURE(status)) return breaks;
  const icu::UnicodeString text = icu::UnicodeString::fromUTF8(
      icu::StringPiece(utf8.data(), static_cast<int32_t>(utf8.size())));
  characters->setText(text);
  int32_t utf16_at = 0;
  std::size_t utf8_at = 0;
  for (int32_t next = characters->next(); next != icu::BreakIterator::DONE && next < text.length();
       next = characters->next()) {
    while (utf16_at < next) {
      const UChar32 c = text.char32At(utf16_at);
      utf16_at += U16_LENGTH(c);
      utf8_at += static_cast<std::size_t>(U8_LENGTH(c));
    }
    breaks.push_back(utf8_at);
  }
  return breaks;
}

}  // namespace collide::text
