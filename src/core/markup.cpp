// SPDX-License-Identifier: MIT
#include "core/markup.hpp"

namespace collide::core {

void appendMarkupEscaped(std::string& out, std::string_view text) {
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
}

std::string markupEscaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  appendMarkupEscaped(out, text);
  return out;
}

}  // namespace collide::core
