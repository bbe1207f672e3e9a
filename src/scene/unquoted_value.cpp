// SPDX-License-Identifier: MIT
#include "scene/unquoted_value.hpp"

#include <sstream>
#include <vector>

#include "scene/quantity.hpp"

namespace collide::scene::detail {
namespace {

std::string trimmed(const std::string& text) {
  const std::size_t a = text.find_first_not_of(" \t\r");
  const std::size_t b = text.find_last_not_of(" \t\r");
  return a == std::string::npos ? std::string() : text.substr(a, b - a + 1);
}

std::string lineOf(const std::string& text, std::size_t line) {
  std::istringstream in(text);
  std::string current;
  for (std::size_t i = 0; i < line && std::getline(in, current); ++i) {
  }
  return current;
}

// A plain TOML number needs no quotes ("0.5", "-3", "1e-3").
bool isPlainNumber(const std::string& text) {
  if (text.empty() || text.find_first_not_of("0123456789+-.eE_") != std::string::npos) return false;
  return text.find_first_of("0123456789") != std::string::npos;
}

// One element: itself when a plain number, quoted when it reads as a quantity; nullopt otherwise.
std::optional<std::string> quotedElement(const std::string& element) {
  if (isPlainNumber(element)) return element;
  if (!looksLikeQuantity(element)) return std::nullopt;
  return "\"" + element + "\"";
}

// "[a, b]": each element quoted as needed; nullopt when one is neither number nor quantity.
std::optional<std::string> quotedArray(const std::string& value) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(value.substr(1, value.size() - 2));
  while (std::getline(in, part, ',')) parts.push_back(trimmed(part));
  std::string quoted = "[";
  bool any_quantity = false;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::optional<std::string> element = quotedElement(parts[i]);
    if (!element) return std::nullopt;
    any_quantity = any_quantity || *element != parts[i];
    quoted += (i > 0 ? ", " : "") + *element;
  }
  if (!any_quantity) return std::nullopt;
  return quoted + "]";
}

}  // namespace

std::optional<UnquotedValue> unquotedValue(const std::string& text, std::size_t line) {
  const std::string content = lineOf(text, line);
  const std::size_t equals = content.find('=');
  if (equals == std::string::npos || content.find_first_of("\"'") != std::string::npos) {
    return std::nullopt;
  }
  UnquotedValue result;
  result.key = trimmed(content.substr(0, equals));
  std::string value = content.substr(equals + 1);
  if (const std::size_t comment = value.find('#'); comment != std::string::npos) {
    value.resize(comment);
  }
  result.value = trimmed(value);
  if (result.key.empty() || result.value.empty()) return std::nullopt;
  result.column = content.find(result.value, equals + 1) + 1;
  std::optional<std::string> quoted;
  if (result.value.front() == '[' && result.value.back() == ']') {
    quoted = quotedArray(result.value);
  } else if (!isPlainNumber(result.value) && looksLikeQuantity(result.value)) {
    quoted = "\"" + result.value + "\"";
  }
  if (!quoted) return std::nullopt;
  result.quoted = *quoted;
  return result;
}

}  // namespace collide::scene::detail
