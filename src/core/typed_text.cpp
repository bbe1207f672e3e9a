#include "core/typed_text.hpp"

#include <cstdio>

namespace collide::core {
namespace {

bool continuesCharacter(char c) {
  return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

}  // namespace

std::size_t utf8Length(std::string_view text) {
  std::size_t characters = 0;
  for (const char c : text) {
    if (!continuesCharacter(c)) ++characters;
  }
  return characters;
}

std::string echoTyped(std::string_view text, std::size_t max_characters) {
  std::string shown;
  std::size_t characters = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (!continuesCharacter(c) && ++characters > max_characters) {
      shown += "...";
      break;
    }
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      shown += "\\n";
    } else if (c == '\r') {
      shown += "\\r";
    } else if (c == '\t') {
      shown += "\\t";
    } else if (byte < 0x20 || byte == 0x7F) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02X", byte);
      shown += escaped;
    } else {
      shown += c;
    }
  }
  return shown;
}

}  // namespace collide::core
