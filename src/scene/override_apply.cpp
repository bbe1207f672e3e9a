// --set KEY=VALUE and the two-body shortcuts, applied to a scene table. Key paths are the ones the
// reader uses in its messages: "restitution", "view.theme", "body.2.mass" (1-based indices into
// [[body]], [[wall]] and [[pair]]).
#include "scene/override_apply.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <sstream>

#include "core/typed_text.hpp"
#include "scene/fields.hpp"
#include "scene/heading.hpp"
#include "scene/quantity.hpp"
#include "scene/toml_guard.hpp"
#include "scene/unquoted_value.hpp"

namespace collide::scene::detail {
namespace {

std::vector<std::string> splitKey(const std::string& key) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(key);
  while (std::getline(in, part, '.')) parts.push_back(part);
  if (!key.empty() && key.back() == '.') parts.push_back("");
  return parts;
}

bool isIndex(const std::string& text) {
  return !text.empty() && text.size() <= 6 &&
         text.find_first_not_of("0123456789") == std::string::npos;
}

// A decimal number beyond the range of a double: "1e999" (toml++ refuses it, and it is no word)
// or "1e-999" (toml++ reads 0). The first becomes +-inf, so the key's own check says "not a
// finite number" and what is allowed instead of "wrong type (a string)".
struct OutOfRange {
  bool found = false;
  double value = 0.0;  // +-inf for an overflow, the rounded value (0 or subnormal) otherwise
};

OutOfRange outOfRangeNumber(const std::string& text) {
  if (text.empty() || text.find_first_not_of("0123456789+-.eE") != std::string::npos ||
      text.find_first_of("0123456789") == std::string::npos) {
    return {};
  }
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (*end != '\0' || errno != ERANGE) return {};
  return {true, value};
}

// The value as TOML reads it, when it does.
std::optional<toml::table> parseAsToml(const std::string& value) {
  std::string text;
  if (detail::tryAsciiForToml("v = " + value + "\n", text)) {  // toml++ sees ASCII only
    try {
      toml::table parsed = toml::parse(text);
      if (parsed.size() == 1 && parsed.contains("v")) return parsed;
    } catch (const toml::parse_error&) {
    }
  }
  return std::nullopt;
}

// The value as a TOML node. A bare word that is not TOML (dark, spring-damper) is a string, so
// `--set view.theme=dark` needs no quotes; so is arithmetic or a unit ("2/3", "25g"), and in
// "[sqrt(3)/2, 1/2]" each such element, as the file would quote them.
std::optional<toml::table> parseValue(const std::string& value) {
  if (std::optional<toml::table> parsed = parseAsToml(value)) return parsed;
  if (const std::optional<UnquotedValue> unquoted = unquotedValue("v = " + value, 1)) {
    if (std::optional<toml::table> parsed = parseAsToml(unquoted->quoted)) return parsed;
  }
  const bool bare = !value.empty() && value.find_first_of("[]{}\"'=#\n") == std::string::npos;
  if (!bare) return std::nullopt;
  toml::table parsed;
  parsed.insert("v", value);
  return parsed;
}

class Applier {
 public:
  Applier(toml::table& root, const Override& change, Origins& origins, Problems& problems)
      : root_(root), change_(change), origins_(origins), problems_(problems) {}

  void run() {
    const std::vector<std::string> parts = splitKey(change_.key);
    if (parts.empty()) return fail("empty key; allowed: KEY=VALUE");
    for (const std::string& part : parts) {
      if (part.empty())
        return fail(
            "not a key path; allowed: KEY=VALUE with KEY such as "
            "restitution, body.2.mass or view.theme");
    }
    toml::table* table = &root_;
    std::string path;
    const std::size_t last =
        change_.kind == Override::Kind::kValue ? parts.size() - 1 : parts.size();
    for (std::size_t i = 0; i < last; ++i) {
      path += (path.empty() ? "" : ".") + parts[i];
      if (toml::array* array = arrayOfTables(*table, parts[i])) {
        table = element(*array, parts, i, path);
        if (table == nullptr) return;
        path += "." + parts[++i];
      } else {
        table = descend(*table, parts, i, path);
        if (table == nullptr) return;
      }
    }
    if (change_.kind == Override::Kind::kValue) return setValue(*table, parts.back());
    setVelocity(*table);
  }

 private:
  void fail(const std::string& message) {
    problems_.add(change_.origin + ": " + core::echoTyped(change_.key) + ": " +
                      core::echoTyped(change_.value) + ": " + message,
                  message);
  }

  toml::array* arrayOfTables(toml::table& parent, const std::string& key) {
    toml::array* array = parent.get_as<toml::array>(key);
    return array != nullptr && (array->empty() || array->is_array_of_tables()) ? array : nullptr;
  }

  // The table at parent[parts[i]], created when absent.
  toml::table* descend(toml::table& parent, const std::vector<std::string>& parts, std::size_t i,
                       const std::string& path) {
    toml::node* node = parent.get(parts[i]);
    if (node == nullptr) {
      if (i + 1 < parts.size() && isIndex(parts[i + 1])) {
        fail(path + ": the scene has no " + parts[i] +
             " entries; allowed: an index of an "
             "existing [[" +
             parts[i] + "]]");
        return nullptr;
      }
      parent.insert(parts[i], toml::table{});
      node = parent.get(parts[i]);
      origins_.overridden[node] = change_.origin;
    }
    if (node->is_table()) return node->as_table();
    fail(path + " is not a table; allowed: a key path such as restitution or body.2.mass");
    return nullptr;
  }

  toml::table* element(toml::array& array, const std::vector<std::string>& parts, std::size_t i,
                       const std::string& path) {
    const std::string range = "1 to " + std::to_string(array.size());
    if (i + 1 >= parts.size() || !isIndex(parts[i + 1])) {
      fail(path + " needs an index; allowed: " + path + ".N." + "KEY with N from " + range);
      return nullptr;
    }
    const std::size_t index = std::stoul(parts[i + 1]);
    if (index < 1 || index > array.size()) {
      fail("no " + path + "." + parts[i + 1] + " in this scene; allowed: an index from " + range);
      return nullptr;
    }
    return array.get(index - 1)->as_table();
  }

  void setValue(toml::table& table, const std::string& key) {
    dropContradictingKeys(table, key);
    if (change_.number) {
      table.insert_or_assign(key, *change_.number);
      origins_.overridden[table.get(key)] = change_.origin;
      origins_.typed[table.get(key)] = change_.value;
      return;
    }
    const OutOfRange out_of_range = outOfRangeNumber(change_.value);
    std::optional<toml::table> parsed = parseValue(change_.value);
    if (out_of_range.found && std::isinf(out_of_range.value)) {
      parsed.emplace();
      parsed->insert("v", out_of_range.value);
    }
    if (!parsed) {
      return fail(
          "not a TOML value; allowed: a number, true or false, a word or \"string\", or "
          "[x, y]");
    }
    parsed->get("v")->visit([&](auto& value) { table.insert_or_assign(key, std::move(value)); });
    origins_.overridden[table.get(key)] = change_.origin;
    // Messages about this value echo what the user typed ("1e6"), not TOML's rendering of it
    // ("1e+06").
    origins_.typed[table.get(key)] = change_.value;
  }

  // A body's position or velocity set from the command line replaces the keys that set it
  // another way (a pendulum's length and angle, a target's struck_by, speed and heading), and a
  // length or angle replaces a position, so that no change contradicts the file.
  static void dropContradictingKeys(toml::table& table, const std::string& key) {
    if (key == "position") {
      for (const char* other : {"length", "angle", "struck_by", "impact_parameter", "gap"}) {
        table.erase(other);
      }
    } else if (key == "velocity") {
      table.erase("speed");
      table.erase("heading");
    } else if ((key == "length" || key == "angle") && table.contains("pivot")) {
      table.erase("position");
    }
  }

  // --v1 / --theta1: speed or direction of a body, keeping the other. The value may carry a unit
  // ("60 km/h", "0.5 rad") or be arithmetic ("pi/6 rad").
  void setVelocity(toml::table& body) {
    const bool speed_change = change_.kind == Override::Kind::kSpeed;
    const QuantityReading given =
        readQuantity(change_.value, speed_change ? Quantity::kSpeed : Quantity::kAngle);
    if (!given.value) return fail(given.problem);
    if (!std::isfinite(*given.value)) {
      return fail("not a finite number; allowed: " +
                  std::string(speed_change ? "a speed in m/s" : "an angle in degrees"));
    }
    const int dimensions = static_cast<int>(root_["dimensions"].value_or<std::int64_t>(1));
    if (dimensions == 1) {
      if (!speed_change) {
        return fail(
            "this is a 1D scene; allowed: angles only in 2D scenes (use a signed "
            "velocity instead)");
      }
      body.erase("speed");
      body.erase("heading");
      body.insert_or_assign("velocity", *given.value);
    } else if (!setPlaneVelocity(body, *given.value)) {
      return;
    }
    origins_.overridden[body.get("velocity")] = change_.origin;
  }

  // 2D: the body's speed and heading (from `velocity`, or `speed` and `heading`), one of them
  // changed, written back as `velocity`. False (with the problem added) when it cannot be.
  bool setPlaneVelocity(toml::table& body, double given) {
    const std::optional<core::Vec2> now = currentVelocity(body);
    if (!now) {
      fail("body's velocity is not valid yet; allowed: a valid velocity, or speed and heading");
      return false;
    }
    double speed = now->norm();
    double angle_deg = std::atan2(now->y(), now->x()) * 180.0 / std::numbers::pi;
    if (change_.kind == Override::Kind::kSpeed) {
      if (given < 0.0) {
        fail("negative; allowed: a speed in m/s, 0 or more (2D)");
        return false;
      }
      speed = given;
    } else {
      if (speed == 0.0) {
        fail(
            "the body is at rest, so a direction changes nothing; allowed: a direction with a "
            "speed (--v1/--v2 SPEED, applied first), or a body that moves");
        return false;
      }
      angle_deg = given;
    }
    body.erase("speed");
    body.erase("heading");
    const core::Vec2 velocity = speed * unitVectorAtDegrees(angle_deg);
    body.insert_or_assign("velocity", toml::array{velocity.x(), velocity.y()});
    return true;
  }

  // The velocity the body has now: `velocity`, or `speed` and `heading`; zero when none.
  std::optional<core::Vec2> currentVelocity(const toml::table& body) const {
    std::string why;
    if (const toml::node* speed = body.get("speed")) {
      const std::optional<double> s = asQuantity(*speed, Quantity::kSpeed, why);
      const toml::node* heading = body.get("heading");
      const std::optional<double> h =
          heading != nullptr ? headingDegrees(*heading, why) : std::optional<double>(0.0);
      if (!s || !h) return std::nullopt;
      return *s * unitVectorAtDegrees(*h);
    }
    const toml::array* v = body.get_as<toml::array>("velocity");
    if (v == nullptr || v->size() != 2) return core::Vec2(0.0, 0.0);
    const std::optional<double> x = asQuantity(*v->get(0), Quantity::kSpeed, why);
    const std::optional<double> y = asQuantity(*v->get(1), Quantity::kSpeed, why);
    if (!x || !y) return std::nullopt;
    return core::Vec2(*x, *y);
  }

  toml::table& root_;
  const Override& change_;
  Origins& origins_;
  Problems& problems_;
};

}  // namespace

void applyOverride(toml::table& table, const Override& change, Origins& origins,
                   Problems& problems) {
  Applier(table, change, origins, problems).run();
}

toml::table parseToml(const std::string& text, const std::string& source_name) {
  // toml++ sees ASCII only (see toml_guard.hpp).
  const std::string ascii =
      detail::asciiForToml(text, source_name.empty() ? std::string("scene") : source_name);
  try {
    return source_name.empty() ? toml::parse(ascii) : toml::parse(ascii, source_name);
  } catch (const toml::parse_error& e) {
    const toml::source_region& at = e.source();
    const std::string source = source_name.empty() ? "scene" : source_name;
    const auto whereAt = [&](std::size_t column) {
      return at.begin.line > 0
                 ? source + ":" + std::to_string(at.begin.line) + ":" + std::to_string(column)
                 : source;
    };
    if (const std::optional<UnquotedValue> unquoted = unquotedValue(ascii, at.begin.line)) {
      throw SceneError(whereAt(unquoted->column) + ": " + unquoted->key + ": " + unquoted->value +
                       ": arithmetic and units are written in quotes; allowed: " + unquoted->key +
                       " = " + unquoted->quoted);
    }
    const std::string where = whereAt(at.begin.column);
    std::string what(e.description());
    for (char& c : what) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    // toml++ calls a number beyond a double's range (1e999) malformed, pointing just past it; say
    // what is wrong with it, and where it starts.
    const std::size_t open = what.find('\'');
    const std::size_t close = open == std::string::npos ? open : what.find('\'', open + 1);
    if (close != std::string::npos) {
      const std::string token = what.substr(open + 1, close - open - 1);
      if (outOfRangeNumber(token).found && at.begin.column > token.size()) {
        throw SceneError(
            whereAt(at.begin.column - token.size()) + ": " + token +
            ": out of range of a number; allowed: numbers up to about 1.8e308 in size, "
            "within each key's own range (see docs/scene-format.md)");
      }
    }
    throw SceneError(where + ": malformed TOML: " + what +
                     "; allowed: TOML 1.0 (see docs/scene-format.md)");
  }
}

}  // namespace collide::scene::detail
