// SPDX-License-Identifier: MIT
#include "text/number_marks.hpp"

namespace collide::text {

// A decimal digit of the scripts collide writes numbers in: ASCII (U+0030..9), Arabic-Indic
// (U+0660..9), Eastern Arabic-Indic (U+06F0..9) and Devanagari (U+0966..F).
bool isScriptDigit(char32_t c) {
  return (c >= 0x0030 && c <= 0x0039) || (c >= 0x0660 && c <= 0x0669) ||
         (c >= 0x06F0 && c <= 0x06F9) || (c >= 0x0966 && c <= 0x096F);
}

// The code point a UTF-8 sequence starting at `at` encodes (0 where it is cut short).
char32_t utf8CodePointAt(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(at);
  const int length = lead < 0x80 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
  if (at + static_cast<std::size_t>(length) > text.size()) return 0;
  char32_t c = length == 1 ? lead : lead & (0x7F >> length);
  for (int k = 1; k < length; ++k) c = (c << 6) | (byte(at + static_cast<std::size_t>(k)) & 0x3F);
  return c;
}

bool startsWithDigit(std::string_view text) {
  return !text.empty() && isScriptDigit(utf8CodePointAt(text, 0));
}

bool endsWithDigit(std::string_view text) {
  std::size_t at = text.size();
  while (at > 0 && (static_cast<unsigned char>(text[at - 1]) & 0xC0) == 0x80) --at;
  return at > 0 && isScriptDigit(utf8CodePointAt(text, at - 1));
}

// A sign that belongs to the number after it: "+", "−", or Arabic's letter mark and minus.
bool startsWithSign(std::string_view word) {
  return word.starts_with("+") || word.starts_with("\u2212") || word.starts_with("\u061C\u2212");
}

// A vector's closing bracket after its last number, "0)" or "−0,500)": its unit follows
// ("(2,00; 0) kg·m/s") and stays with it where a line holds both.
bool endsWithNumberInBrackets(std::string_view text) {
  return text.ends_with(")") && endsWithDigit(text.substr(0, text.size() - 1));
}

// The brackets `word` leaves open (negative: it closes more than it opens).
int bracketsOpened(std::string_view word) {
  int depth = 0;
  for (const char c : word) depth += c == '(' || c == '[' ? 1 : c == ')' || c == ']' ? -1 : 0;
  return depth;
}

// A mark after which a list goes on (",", "，", "、", Arabic "،") or a clause does (";", "；").
bool endsWithListMark(std::string_view text) {
  return text.ends_with(",") || text.ends_with(";") || text.ends_with("\uFF0C") ||
         text.ends_with("\u3001") || text.ends_with("\uFF1B") || text.ends_with("\u060C");
}

// A direction, "2°" or "−143°" (a list mark may follow): after its speed's "m/s," it is one
// quantity with it.
bool isAngle(std::string_view word) {
  while (endsWithListMark(word)) {
    const bool ascii = word.ends_with(",") || word.ends_with(";");
    word.remove_suffix(ascii ? 1 : word.ends_with("\u060C") ? 2 : 3);
  }
  return (startsWithDigit(word) || startsWithSign(word)) && word.ends_with("\u00B0");
}

}  // namespace collide::text
