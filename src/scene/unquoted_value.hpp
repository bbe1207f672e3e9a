// SPDX-License-Identifier: MIT
#pragma once
// Internal to collide_scene: a TOML line such as `restitution = 2/3` or `mass = 25 g`, which TOML
// cannot read, recognised so that the message can say how to write it (`restitution = "2/3"`).
#include <optional>
#include <string>

namespace collide::scene::detail {

struct UnquotedValue {
  std::string key;         // as written before '='
  std::string value;       // as written after it, without a comment
  std::string quoted;      // the value as it should be written: "2/3", ["sqrt(3)/2", 0.5]
  std::size_t column = 0;  // 1-based column where the value starts
};

// The value on line `line` (1-based) of `text` when it is arithmetic or a number with a unit (or
// an array of such) written without quotes; nullopt for anything else.
std::optional<UnquotedValue> unquotedValue(const std::string& text, std::size_t line);

}  // namespace collide::scene::detail
