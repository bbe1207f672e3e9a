#include "scene/fields.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "core/typed_text.hpp"
#include "scene/suggest.hpp"

namespace collide::scene::detail {
namespace {

constexpr std::size_t kMaxValueTextLength = 80;  // characters of a value quoted in a message

std::string typeName(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a number";
    case toml::node_type::boolean:
      return "a boolean";
    default:
      return "a date or time";
  }
}

// Why `text` cannot be a scene's text, or nullopt if it can: bytes that are not UTF-8, a control
// character (it would act on a terminal, end a line of a file collide writes, or be refused by a
// PDF font), a line or paragraph separator, or a non-character (which fonts, PDF and XML refuse).
std::optional<std::string> unprintable(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    char32_t code_point = 0;
    const std::size_t length = core::decodeUtf8(text, i, code_point);
    if (length == 0) return "bytes that are not UTF-8 (at byte " + std::to_string(i + 1) + ")";
    const std::string name = core::codePointName(code_point);
    if (core::isControlCharacter(code_point)) return name + ", a control character";
    if (code_point == 0x2028 || code_point == 0x2029) return name + ", a line break";
    if (core::isNonCharacter(code_point)) return name + ", a non-character";
    i += length;
  }
  return std::nullopt;
}

constexpr const char* kPrintable =
    "; text of printable characters: no control characters (U+0000..U+001F, U+007F..U+009F), "
    "line or paragraph separators (U+2028, U+2029) or non-characters (U+FDD0..U+FDEF, U+FFFE, "
    "U+FFFF and the last two of every plane up to U+10FFFF)";

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (std::size_t i = 0; i < words.size(); ++i) text += (i > 0 ? ", " : "") + words[i];
  return text;
}

}  // namespace

std::string Origins::where(const toml::node* node) const {
  if (node != nullptr) {
    const auto found = overridden.find(node);
    if (found != overridden.end()) return found->second;
    const toml::source_region& source = node->source();
    if (source.path && source.begin.line > 0) {
      return *source.path + ":" + std::to_string(source.begin.line) + ":" +
             std::to_string(source.begin.column);
    }
  }
  return fallback;
}

void Problems::throwIfAny() const {
  if (lines_.empty()) return;
  std::string message = lines_.front();
  if (lines_.size() > 1) {
    message += " (and " + std::to_string(lines_.size() - 1) + " more problem" +
               (lines_.size() > 2 ? "s" : "") + "; 'collide check' lists them)";
  }
  throw SceneError(message, lines_, kinds_);
}

std::string plainNumber(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string numberText(double value) {
  std::string text = plainNumber(value);
  // TOML needs a '.' or an exponent to read a float back as a float.
  if (text.find_first_of(".en") == std::string::npos) text += ".0";
  return text;
}

namespace {

// TOML text of a value, compact: "0.6", "[0.6, 0.6]", "\"dark\"", "{...}".
void writeValue(std::ostream& out, const toml::node& node) {
  if (const auto* number = node.as_floating_point()) {
    out << numberText(number->get());
  } else if (const auto* string = node.as_string()) {
    out << '"';
    for (const char c : string->get()) out << (c == '"' || c == '\\' ? "\\" : "") << c;
    out << '"';
  } else if (const auto* array = node.as_array()) {
    if (!array->empty() && array->is_array_of_tables()) {
      out << "[" << array->size() << " tables]";
      return;
    }
    out << "[";
    for (std::size_t i = 0; i < array->size(); ++i) {
      if (i > 0) out << ", ";
      writeValue(out, *array->get(i));
    }
    out << "]";
  } else if (node.is_table()) {
    out << "{...}";
  } else {
    node.visit([&](const auto& value) { out << value; });
  }
}

}  // namespace

std::string valueText(const toml::node& node) {
  std::ostringstream out;
  writeValue(out, node);
  return core::echoTyped(out.str(), kMaxValueTextLength);
}

std::optional<double> asNumber(const toml::node& node) {
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  if (const auto* f = node.as_floating_point()) return f->get();
  return std::nullopt;
}

std::optional<double> asQuantity(const toml::node& node, Quantity kind, std::string& why) {
  if (const std::optional<double> number = asNumber(node)) return number;
  const auto* text = node.as_string();
  if (text == nullptr) {
    why = "wrong type (" + typeName(node) + ")";
    return std::nullopt;
  }
  QuantityReading reading = readQuantity(text->get(), kind);
  if (!reading.value) why = std::move(reading.problem);
  return reading.value;
}

std::string Range::text() const {
  const std::string low = (min_open ? "more than " : "from ") + plainNumber(min);
  const std::string high = (min_open ? " and at most " : " to ") + plainNumber(max);
  return noun + (min_open ? ", " : " ") + low + high + note;
}

Fields::Fields(const toml::table& table, std::string path, const Origins& origins,
               Problems& problems)
    : table_(table), path_(std::move(path)), origins_(origins), problems_(problems) {}

std::string Fields::keyPath(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

const toml::node* Fields::node(const std::string& key) const {
  return table_.get(key);
}

void Fields::problem(const toml::node* at, const std::string& key, const std::string& message) {
  std::string value = at != nullptr ? valueText(*at) : "(missing)";
  if (const auto typed = origins_.typed.find(at); at != nullptr && typed != origins_.typed.end()) {
    value = core::echoTyped(typed->second, kMaxValueTextLength);
  }
  problems_.add(origins_.where(at != nullptr ? at : &table_) + ": " + keyPath(key) + ": " + value +
                    ": " + message,
                message);
}

void Fields::missing(const std::string& key, const std::string& allowed) {
  problems_.add(
      origins_.where(&table_) + ": " + keyPath(key) + ": (missing): required; allowed: " + allowed,
      key + " required; allowed: " + allowed);
}

void Fields::allowOnly(const std::vector<std::string>& allowed) {
  // The unknown keys in the order the file has them (the table holds them sorted by name).
  std::vector<std::pair<const toml::key*, const toml::node*>> unknown;
  for (const auto& [key, value] : table_) {
    if (std::find(allowed.begin(), allowed.end(), key.str()) == allowed.end()) {
      unknown.emplace_back(&key, &value);
    }
  }
  std::stable_sort(unknown.begin(), unknown.end(), [](const auto& a, const auto& b) {
    const toml::source_position& p = a.first->source().begin;
    const toml::source_position& q = b.first->source().begin;
    return p.line != q.line ? p.line < q.line : p.column < q.column;
  });
  const std::string kind = "unknown key; allowed keys: " + joined(allowed);
  for (const auto& [key, value] : unknown) {
    const std::string name(key->str());
    const std::vector<std::string> near = nearMatches(name, allowed);
    std::string message = "unknown key;";
    if (!near.empty()) message += " did you mean '" + near.front() + "'?";
    // Point at the key itself when it has a place in a file.
    const toml::source_region& at = key->source();
    const bool overridden = origins_.overridden.count(value) > 0;
    if (!overridden && at.path && at.begin.line > 0) {
      problems_.add(*at.path + ":" + std::to_string(at.begin.line) + ":" +
                        std::to_string(at.begin.column) + ": " + core::echoTyped(keyPath(name)) +
                        ": " + valueText(*value) + ": " + message +
                        " allowed keys: " + joined(allowed),
                    kind);
      continue;
    }
    problem(value, core::echoTyped(name), message + " allowed keys: " + joined(allowed));
  }
}

std::optional<double> Fields::number(const std::string& key, const Range& range) {
  const toml::node* at = node(key);
  if (at == nullptr) return std::nullopt;
  std::string why;
  const std::optional<double> value = asQuantity(*at, range.kind, why);
  if (!value) {
    problem(at, key, at->is_string() ? why : why + "; allowed: " + range.text());
    return std::nullopt;
  }
  if (!std::isfinite(*value)) {
    problem(at, key, "not a finite number; allowed: " + range.text());
    return std::nullopt;
  }
  // Subnormal doubles carry fewer than 53 bits; the arithmetic on them (1/m, m u^2) underflows or
  // loses all precision, so every number must be zero or a normal double.
  if (*value != 0.0 && std::abs(*value) < std::numeric_limits<double>::min()) {
    problem(at, key,
            "a subnormal number (below 2.2e-308, where doubles lose precision); allowed: " +
                range.text());
    return std::nullopt;
  }
  const bool low = range.min_open ? *value <= range.min : *value < range.min;
  if (low || *value > range.max) {
    problem(at, key, "out of range; allowed: " + range.text());
    return std::nullopt;
  }
  return value;
}

std::optional<int> Fields::integer(const std::string& key, int min, int max,
                                   const std::string& noun) {
  const toml::node* at = node(key);
  if (at == nullptr) return std::nullopt;
  const std::string allowed = "allowed: " + noun + ", a whole number from " + std::to_string(min) +
                              " to " + std::to_string(max);
  const std::optional<double> value = asNumber(*at);
  if (!value || !std::isfinite(*value) || *value != std::floor(*value)) {
    problem(at, key,
            (value ? "not a whole number; " : "wrong type (" + typeName(*at) + "); ") + allowed);
    return std::nullopt;
  }
  if (*value < min || *value > max) {
    problem(at, key, "out of range; " + allowed);
    return std::nullopt;
  }
  return static_cast<int>(*value);
}

std::optional<bool> Fields::flag(const std::string& key) {
  const toml::node* at = node(key);
  if (at == nullptr) return std::nullopt;
  if (const auto* b = at->as_boolean()) return b->get();
  problem(at, key, "wrong type (" + typeName(*at) + "); allowed: true or false");
  return std::nullopt;
}

std::optional<std::string> Fields::text(const std::string& key, std::size_t max_length,
                                        const std::string& allowed) {
  const toml::node* at = node(key);
  if (at == nullptr) return std::nullopt;
  const auto* s = at->as_string();
  if (s == nullptr) {
    problem(at, key, "wrong type (" + typeName(*at) + "); allowed: " + allowed);
    return std::nullopt;
  }
  if (const std::optional<std::string> why = unprintable(s->get())) {
    problem(at, key, "holds " + *why + "; allowed: " + allowed + kPrintable);
    return std::nullopt;
  }
  if (core::utf8Length(s->get()) > max_length) {
    problem(at, key, "too long; allowed: " + allowed);
    return std::nullopt;
  }
  return s->get();
}

std::optional<std::string> Fields::choice(const std::string& key,
                                          const std::vector<std::string>& options) {
  std::string allowed;
  for (std::size_t i = 0; i < options.size(); ++i) {
    allowed += (i == 0 ? "" : (i + 1 == options.size() ? " or " : ", ")) + ("'" + options[i] + "'");
  }
  const std::optional<std::string> value = text(key, 100, allowed);
  if (!value) return std::nullopt;
  if (std::find(options.begin(), options.end(), *value) == options.end()) {
    problem(node(key), key,
            "not one of the choices; allowed: " + allowed + didYouMean(*value, options));
    return std::nullopt;
  }
  return value;
}

std::optional<core::Vec2> Fields::vector(const std::string& key, int dimensions, double max_abs,
                                         const std::string& noun, Quantity kind) {
  const toml::node* at = node(key);
  if (at == nullptr) return std::nullopt;
  const std::string limit = plainNumber(max_abs);
  const std::string allowed =
      dimensions == 1
          ? "allowed: " + noun + " as a number x (or [x, 0]), |x| at most " + limit
          : "allowed: " + noun + " as [x, y], each component at most " + limit + " in size";
  core::Vec2 result = {0.0, 0.0};
  std::string why;
  if (at->is_string() && dimensions == 1) {
    const std::optional<double> x = asQuantity(*at, kind, why);
    if (!x) {
      problem(at, key, why);
      return std::nullopt;
    }
    result.x() = *x;
  } else if (const std::optional<double> x = asNumber(*at); x && dimensions == 1) {
    result.x() = *x;
  } else if (const auto* array = at->as_array(); array != nullptr && array->size() == 2) {
    for (int i = 0; i < 2; ++i) {
      const std::optional<double> component = asQuantity(*array->get(i), kind, why);
      if (!component) {
        problem(at, key,
                array->get(i)->is_string()
                    ? why
                    : "wrong type (a component is " + typeName(*array->get(i)) + "); " + allowed);
        return std::nullopt;
      }
      result[i] = *component;
    }
    if (dimensions == 1 && result.y() != 0.0) {
      problem(at, key, "a 1D scene has no y; " + allowed);
      return std::nullopt;
    }
  } else {
    problem(at, key, "wrong type (" + typeName(*at) + "); " + allowed);
    return std::nullopt;
  }
  if (!result.allFinite()) {
    problem(at, key, "not a finite number; " + allowed);
    return std::nullopt;
  }
  for (int i = 0; i < 2; ++i) {
    if (result[i] != 0.0 && std::abs(result[i]) < std::numeric_limits<double>::min()) {
      problem(at, key,
              "a subnormal number (below 2.2e-308, where doubles lose precision); " + allowed);
      return std::nullopt;
    }
  }
  if (result.cwiseAbs().maxCoeff() > max_abs) {
    problem(at, key, "out of range; " + allowed);
    return std::nullopt;
  }
  return result;
}

std::optional<Rgb> Fields::color(const std::string& key) {
  const toml::node* at = node(key);
  if (at == nullptr) return std::nullopt;
  const std::string allowed = "allowed: \"#rrggbb\" (hexadecimal) or [r, g, b] with 0 to 255 each";
  int channel[3] = {0, 0, 0};
  if (const auto* s = at->as_string()) {
    const std::string& hex = s->get();
    const bool ok = hex.size() == 7 && hex[0] == '#' &&
                    hex.find_first_not_of("0123456789abcdefABCDEF", 1) == std::string::npos;
    if (!ok) {
      problem(at, key, "not a colour; " + allowed);
      return std::nullopt;
    }
    for (int i = 0; i < 3; ++i) channel[i] = std::stoi(hex.substr(1 + 2 * i, 2), nullptr, 16);
  } else if (const auto* array = at->as_array(); array != nullptr && array->size() == 3) {
    for (int i = 0; i < 3; ++i) {
      const auto* c = array->get(i)->as_integer();
      if (c == nullptr || c->get() < 0 || c->get() > 255) {
        problem(at, key, "not a colour; " + allowed);
        return std::nullopt;
      }
      channel[i] = static_cast<int>(c->get());
    }
  } else {
    problem(at, key, "wrong type (" + typeName(*at) + "); " + allowed);
    return std::nullopt;
  }
  return Rgb{channel[0], channel[1], channel[2]};
}

}  // namespace collide::scene::detail
