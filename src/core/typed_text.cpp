#include "core/typed_text.hpp"

#include <cstdio>

namespace collide::core {
namespace {

bool continuesCharacter(char c) {
  return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

// The escape echoTyped shows for code point `code_point` (a control or a non-character).
std::string escapedCodePoint(char32_t code_point) {
  switch (code_point) {
    case U'\n':
      return "\\n";
    case U'\r':
      return "\\r";
    case U'\t':
      return "\\t";
    default:
      break;
  }
  char escaped[16];
  if (code_point < 0x80) {
    std::snprintf(escaped, sizeof escaped, "\\x%02X", static_cast<unsigned>(code_point));
  } else {
    std::snprintf(escaped, sizeof escaped, "\\u{%04X}", static_cast<unsigned>(code_point));
  }
  return escaped;
}

}  // namespace

std::size_t utf8Length(std::string_view text) {
  std::size_t characters = 0;
  for (const char c : text) {
    if (!continuesCharacter(c)) ++characters;
  }
  return characters;
}

std::size_t decodeUtf8(std::string_view text, std::size_t i, char32_t& code_point) {
  if (i >= text.size()) return 0;
  const auto lead = static_cast<unsigned char>(text[i]);
  if (lead < 0x80) {
    code_point = lead;
    return 1;
  }
  const std::size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 ? 2 : 0;
  if (length == 0 || lead > 0xF4 || i + length > text.size()) return 0;
  char32_t value = lead & (0x7F >> length);
  for (std::size_t k = 1; k < length; ++k) {
    const auto next = static_cast<unsigned char>(text[i + k]);
    if ((next & 0xC0) != 0x80) return 0;
    value = (value << 6) | (next & 0x3F);
  }
  constexpr char32_t kSmallest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (value < kSmallest[length] || value > 0x10FFFF || (value >= 0xD800 && value <= 0xDFFF)) {
    return 0;
  }
  code_point = value;
  return length;
}

bool isControlCharacter(char32_t code_point) {
  return code_point < 0x20 || (code_point >= 0x7F && code_point <= 0x9F);
}

bool isNonCharacter(char32_t code_point) {
  return (code_point >= 0xFDD0 && code_point <= 0xFDEF) || (code_point & 0xFFFE) == 0xFFFE;
}

std::string codePointName(char32_t code_point) {
  char name[16];
  std::snprintf(name, sizeof name, "U+%04X", static_cast<unsigned>(code_point));
  return name;
}

std::string echoTyped(std::string_view text, std::size_t max_characters) {
  std::string shown;
  std::size_t characters = 0;
  for (std::size_t i = 0; i < text.size();) {
    if (++characters > max_characters) {
      shown += "...";
      break;
    }
    char32_t code_point = 0;
    const std::size_t length = decodeUtf8(text, i, code_point);
    if (length == 0) {  // not UTF-8: the byte, escaped
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02X", static_cast<unsigned char>(text[i]));
      shown += escaped;
      ++i;
      continue;
    }
    if (isControlCharacter(code_point) || isNonCharacter(code_point)) {
      shown += escapedCodePoint(code_point);
    } else {
      shown.append(text.substr(i, length));
    }
    i += length;
  }
  return shown;
}

}  // namespace collide::core
