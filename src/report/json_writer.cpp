#include "report/json_writer.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace collide::report {

std::string shortestDecimal(double number) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, number);
  return std::string(buffer, result.ptr);
}

std::string jsonQuoted(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        quoted += "\\\"";
        break;
      case '\\':
        quoted += "\\\\";
        break;
      case '\n':
        quoted += "\\n";
        break;
      case '\t':
        quoted += "\\t";
        break;
      case '\r':
        quoted += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char escape[8];
          std::snprintf(escape, sizeof escape, "\\u%04x", c);
          quoted += escape;
        } else {
          quoted += c;
        }
    }
  }
  return quoted + "\"";
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
