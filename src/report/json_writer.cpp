#include "report/json_writer.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/typed_text.hpp"

namespace collide::report {

std::string shortestDecimal(double number) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, number);
  return std::string(buffer, result.ptr);
}

std::string jsonQuoted(const std::string& text) {
  std::string quoted = "\"";
  for (std::size_t i = 0; i < text.size();) {
    char32_t code_point = 0;
    const std::size_t length = core::decodeUtf8(text, i, code_point);
    if (length == 0) {
      // Not UTF-8 (a file name's bytes, say): the replacement character keeps the JSON valid.
      quoted += "\\ufffd";
      ++i;
      continue;
    }
    const char c = text[i];
    if (c == '"') {
      quoted += "\\\"";
    } else if (c == '\\') {
      quoted += "\\\\";
    } else if (c == '\n') {
      quoted += "\\n";
    } else if (c == '\t') {
      quoted += "\\t";
    } else if (c == '\r') {
      quoted += "\\r";
    } else if (core::isControlCharacter(code_point) || code_point == 0x2028 ||
               code_point == 0x2029) {
      // Controls, and the two line separators JavaScript reads as line ends, as escapes.
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(code_point));
      quoted += escape;
    } else {
      quoted.append(text, i, length);
    }
    i += length;
  }
  return quoted + "\"";
}

namespace {

// Four hex digits at text[at]; nullopt if they are not there.
std::optional<char32_t> hexQuad(std::string_view text, std::size_t at) {
  if (at + 4 > text.size()) return std::nullopt;
  char32_t value = 0;
  for (std::size_t k = at; k < at + 4; ++k) {
    const char c = text[k];
    const int digit = c >= '0' && c <= '9'   ? c - '0'
                      : c >= 'a' && c <= 'f' ? c - 'a' + 10
                      : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                             : -1;
    if (digit < 0) return std::nullopt;
    value = value * 16 + static_cast<char32_t>(digit);
  }
  return value;
}

void appendUtf8(std::string& out, char32_t code_point) {
  if (code_point < 0x80) {
    out += static_cast<char>(code_point);
  } else if (code_point < 0x800) {
    out += static_cast<char>(0xC0 | (code_point >> 6));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else if (code_point < 0x10000) {
    out += static_cast<char>(0xE0 | (code_point >> 12));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code_point >> 18));
    out += static_cast<char>(0x80 | ((code_point >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  }
}

// The code point of the \u escape at text[at] (a surrogate pair taken whole); advances `at`.
std::optional<char32_t> unicodeEscape(std::string_view text, std::size_t& at) {
  const std::optional<char32_t> first = hexQuad(text, at);
  if (!first) return std::nullopt;
  at += 4;
  if (*first < 0xD800 || *first > 0xDFFF) return first;
  if (*first > 0xDBFF || text.substr(at, 2) != "\\u") return std::nullopt;
  const std::optional<char32_t> second = hexQuad(text, at + 2);
  if (!second || *second < 0xDC00 || *second > 0xDFFF) return std::nullopt;
  at += 6;
  return 0x10000 + ((*first - 0xD800) << 10) + (*second - 0xDC00);
}

}  // namespace

std::optional<std::string> jsonUnquoted(std::string_view text, std::size_t& used) {
  if (text.empty() || text[0] != '"') return std::nullopt;
  std::string out;
  for (std::size_t at = 1; at < text.size();) {
    const char c = text[at++];
    if (c == '"') {
      used = at;
      return out;
    }
    if (static_cast<unsigned char>(c) < 0x20) return std::nullopt;
    if (c != '\\') {
      out += c;
      continue;
    }
    if (at >= text.size()) return std::nullopt;
    const char escape = text[at++];
    switch (escape) {
      case '"':
      case '\\':
      case '/':
        out += escape;
        break;
      case 'b':
        out += '\b';
        break;
      case 'f':
        out += '\f';
        break;
      case 'n':
        out += '\n';
        break;
      case 'r':
        out += '\r';
        break;
      case 't':
        out += '\t';
        break;
      case 'u': {
        const std::optional<char32_t> code_point = unicodeEscape(text, at);
        if (!code_point) return std::nullopt;
        appendUtf8(out, *code_point);
        break;
      }
      default:
        return std::nullopt;
    }
  }
  return std::nullopt;
}

void JsonWriter::newline() {
  out_ << '\n' << std::string(2 * first_in_level_.size(), ' ');
}

void JsonWriter::beforeValue() {
  if (after_key_) {
    after_key_ = false;
    return;
  }
  if (first_in_level_.empty()) return;
  if (!first_in_level_.back()) out_ << ',';
  first_in_level_.back() = false;
  newline();
}

JsonWriter& JsonWriter::beginObject() {
  beforeValue();
  out_ << '{';
  first_in_level_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::endObject() {
  const bool empty = first_in_level_.back();
  first_in_level_.pop_back();
  if (!empty) newline();
  out_ << '}';
  if (first_in_level_.empty()) out_ << '\n';
  return *this;
}

JsonWriter& JsonWriter::beginArray() {
  beforeValue();
  out_ << '[';
  first_in_level_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::endArray() {
  const bool empty = first_in_level_.back();
  first_in_level_.pop_back();
  if (!empty) newline();
  out_ << ']';
  return *this;
}

JsonWriter& JsonWriter::key(const std::string& name) {
  beforeValue();
  out_ << jsonQuoted(name) << ": ";
  after_key_ = true;
  return *this;
}

JsonWriter& JsonWriter::value(double number) {
  beforeValue();
  out_ << (std::isfinite(number) ? shortestDecimal(number) : "null");
  return *this;
}

JsonWriter& JsonWriter::value(long long number) {
  beforeValue();
  out_ << number;
  return *this;
}

JsonWriter& JsonWriter::boolean(bool truth) {
  beforeValue();
  out_ << (truth ? "true" : "false");
  return *this;
}

JsonWriter& JsonWriter::value(const std::string& text) {
  beforeValue();
  out_ << jsonQuoted(text);
  return *this;
}

JsonWriter& JsonWriter::value(const core::Vec2& vector) {
  // Vectors stay on one line: [x, y].
  beforeValue();
  out_ << '[' << (std::isfinite(vector.x()) ? shortestDecimal(vector.x()) : "null") << ", "
       << (std::isfinite(vector.y()) ? shortestDecimal(vector.y()) : "null") << ']';
  return *this;
}

}  // namespace collide::report
