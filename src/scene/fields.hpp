#pragma once
// Internal to collide_scene: typed, checked access to the keys of one TOML table. Each accessor
// returns the value when present and valid, std::nullopt when absent or invalid; an invalid value
// adds one located problem ("where: key: value: what is allowed").
#include <optional>
#include <string>
#include <vector>

#include "scene/quantity.hpp"
#include "scene/toml_reader.hpp"

namespace collide::scene::detail {

// An allowed interval for a number, with the noun that names the quantity ("a mass in kg").
struct Range {
  double min = 0.0, max = 0.0;
  bool min_open = false;  // true: min itself is not allowed
  std::string noun;
  Quantity kind = Quantity::kNumber;  // what a quoted value's unit must measure
  std::string note = "";              // said after the limits: how to go beyond them
  std::string text() const;           // "a mass in kg, more than 0 and at most 1e+18"
};

class Fields {
 public:
  // `path` is the key path of the table itself ("" for the top level, "body.2", "view").
  Fields(const toml::table& table, std::string path, const Origins& origins, Problems& problems);

  const toml::table& table() const { return table_; }
  const std::string& path() const { return path_; }
  std::string keyPath(const std::string& key) const;
  const toml::node* node(const std::string& key) const;
  bool has(const std::string& key) const { return node(key) != nullptr; }

  // Reports every key not in `allowed`, with a did-you-mean suggestion.
  void allowOnly(const std::vector<std::string>& allowed);

  std::optional<double> number(const std::string& key, const Range& range);
  std::optional<int> integer(const std::string& key, int min, int max, const std::string& noun);
  std::optional<bool> flag(const std::string& key);
  std::optional<std::string> text(const std::string& key, std::size_t max_length,
                                  const std::string& allowed);
  std::optional<std::string> choice(const std::string& key,
                                    const std::vector<std::string>& options);
  // 2D: [x, y]. 1D: a number x or [x, 0]; the result has y = 0. Each component within
  // +-max_abs; a component may be a quoted quantity of `kind` ("12 cm").
  std::optional<core::Vec2> vector(const std::string& key, int dimensions, double max_abs,
                                   const std::string& noun, Quantity kind = Quantity::kNumber);
  // "#rrggbb" or [r, g, b] with integers 0..255.
  std::optional<Rgb> color(const std::string& key);

  // Adds "where(at): keyPath(key): value: message" (value from `at`, or "(missing)").
  void problem(const toml::node* at, const std::string& key, const std::string& message);
  // A note on how a value was read, for `collide check`: "body.2: position ... from struck_by".
  void note(const std::string& line) { problems_.note(line); }
  // A required key that is absent: located at this table.
  void missing(const std::string& key, const std::string& allowed);

 private:
  const toml::table& table_;
  std::string path_;
  const Origins& origins_;
  Problems& problems_;
};

// The node's number when it is an integer or a float; nullopt otherwise.
std::optional<double> asNumber(const toml::node& node);

// A number, or a string read as a quantity of `kind` ("25 g", "2/3"). Without a value, `why` says
// what is wrong: "wrong type (a table)", or readQuantity's problem with what is allowed.
std::optional<double> asQuantity(const toml::node& node, Quantity kind, std::string& why);

}  // namespace collide::scene::detail
