// Numbers someone typed, as text, in a language's signs and digits (number_format.hpp): a value
// typed into a title template, and the numbers a translator typed into a preset's words.
#include <string>
#include <string_view>

#include "text/number_format.hpp"

namespace collide::text {

std::string typedNumber(std::string_view ascii, const NumberStyle& style) {
  std::string out;
  for (char c : ascii) {
    if (c == '.') {
      out += style.decimal_separator;
    } else if (c == '-') {
      out += style.minus;
    } else {
      out += c;
    }
  }
  return withLocalDigits(out, style);
}

namespace {

bool asciiDigit(char c) {
  return c >= '0' && c <= '9';
}

bool asciiLetter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

// The length of the number typed at `text[at]` (a digit): its digits, and a point with digits
// after it.
std::size_t typedNumberLength(std::string_view text, std::size_t at) {
  std::size_t end = at;
  while (end < text.size() && asciiDigit(text[end])) ++end;
  if (end + 1 < text.size() && text[end] == '.' && asciiDigit(text[end + 1])) {
    ++end;
    while (end < text.size() && asciiDigit(text[end])) ++end;
  }
  return end - at;
}

}  // namespace

std::string typedNumbersIn(std::string_view text, const NumberStyle& style) {
  if (style.digits.size() != 10 || style.digits[0] == "0") return std::string(text);
  std::string out;
  int braces = 0;  // inside a {placeholder}
  std::size_t k = 0;
  while (k < text.size()) {
    const char c = text[k];
    braces += c == '{' ? 1 : (c == '}' && braces > 0 ? -1 : 0);
    if (asciiLetter(c)) {  // a word of ASCII letters, digits in it too ("x264")
      while (k < text.size() && (asciiLetter(text[k]) || asciiDigit(text[k]))) out += text[k++];
      continue;
    }
    if (!asciiDigit(c) || braces > 0) {
      out += c;
      ++k;
      continue;
    }
    const std::size_t length = typedNumberLength(text, k);
    const std::string_view number = text.substr(k, length);
    const bool word_follows = k + length < text.size() && asciiLetter(text[k + length]);
    out += word_follows ? std::string(number) : typedNumber(number, style);
    k += length;
  }
  return out;
}

}  // namespace collide::text
