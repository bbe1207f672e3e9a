#pragma once
// Internal to collide_scene: reading a TOML table into a SceneDesc with every problem located.
// toml++ stays out of the public headers (scene_io.hpp).
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/vec.hpp"
#include "scene/scene_desc.hpp"
#include "scene/toml_library.hpp"

namespace collide::scene::detail {

// Where each value came from, for messages.
struct Origins {
  // Used for nodes without a source of their own: "preset NAME", or the scene argument.
  std::string fallback;
  // Nodes put in by an override, with how the user wrote it ("--set body.2.mass=3").
  std::unordered_map<const toml::node*, std::string> overridden;
  // Override values whose node would echo differently from what was typed: a number beyond the
  // range of a double ("1e999", read as inf; "1e-999", read as 0). Messages echo this text.
  std::unordered_map<const toml::node*, std::string> typed;

  // "file:line:column", the override, or the fallback.
  std::string where(const toml::node* node) const;
};

// Problems found so far, each one complete line.
class Problems {
 public:
  // `line`: the whole problem, "WHERE: KEY: VALUE: what is wrong; allowed: ...". `kind`: what is
  // wrong, alike for every problem of its sort (`collide check` lists a few of each and counts
  // the rest); empty: the line is a kind of its own.
  void add(std::string line, std::string kind = {}) {
    kinds_.push_back(kind.empty() ? line : std::move(kind));
    lines_.push_back(std::move(line));
  }
  bool empty() const { return lines_.empty(); }
  const std::vector<std::string>& lines() const { return lines_; }
  // Throws SceneError with the first problem (and how many more) if there are any.
  void throwIfAny() const;
  // Notes, not problems: how a value was read (`collide check` prints them).
  void note(std::string line) { notes_.push_back(std::move(line)); }
  const std::vector<std::string>& notes() const { return notes_; }

 private:
  std::vector<std::string> lines_, kinds_;
  std::vector<std::string> notes_;
};

// The value as TOML writes it, shortened to one reasonable line.
std::string valueText(const toml::node& node);

// Shortest text that reads back as the same double in TOML ("0.1", "1e+16", "2.0").
std::string numberText(double value);
// The same for messages, without the TOML ".0" ("2", "0.1", "1e+18").
std::string plainNumber(double value);

// Reads and validates a whole scene. Problems go to `problems`; the result is only meaningful when
// none were added. `default_name` is used when the table has no `name`.
SceneDesc readScene(const toml::table& table, const Origins& origins, Problems& problems,
                    const std::string& default_name);

// Keys of a [[body]] table.
const std::vector<std::string>& bodyKeys();

// Top-level keys the reader accepts (for did-you-mean on overrides and unknown keys).
const std::vector<std::string>& topLevelKeys();

}  // namespace collide::scene::detail
