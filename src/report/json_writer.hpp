#pragma once
// A small streaming JSON writer: enough structure tracking to place commas, numbers written in the
// shortest form that reads back to the same double.
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "core/vec.hpp"

namespace collide::report {

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) {}

  JsonWriter& beginObject();
  JsonWriter& endObject();
  JsonWriter& beginArray();
  JsonWriter& endArray();
  JsonWriter& key(const std::string& name);  // inside an object, before its value
  JsonWriter& value(double number);          // non-finite numbers are written as null
  JsonWriter& value(long long number);
  JsonWriter& value(int number) { return value(static_cast<long long>(number)); }
  JsonWriter& value(const std::string& text);
  JsonWriter& value(const char* text) { return value(std::string(text)); }
  JsonWriter& value(const core::Vec2& vector);  // [x, y]
  JsonWriter& boolean(bool truth);  // not an overload of value: a pointer would convert to bool

 private:
  void beforeValue();
  void newline();

  std::ostream& out_;
  std::vector<bool> first_in_level_;  // one entry per open object/array
  bool after_key_ = false;
};

// `text` as a JSON string literal, quotes included. Control characters and U+2028/U+2029 are
// escaped; bytes that are not UTF-8 become U+FFFD, so the result is always valid JSON.
std::string jsonQuoted(const std::string& text);

// The JSON string literal at the start of `text` (as jsonQuoted writes it, or any valid one),
// unescaped; `used` is set to its length, quotes included. nullopt when `text` does not start with
// a whole, valid string literal.
std::optional<std::string> jsonUnquoted(std::string_view text, std::size_t& used);

// Shortest decimal that reads back as exactly `number` ("1", "0.1", "1.25e-07").
std::string shortestDecimal(double number);

}  // namespace collide::report
