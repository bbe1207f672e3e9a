// SPDX-License-Identifier: MIT
#pragma once
// Internal to collide_scene: directions in the plane as books state them: degrees from +x
// (counter-clockwise), or compass words with +x east and +y north ("N", "NE", "60 deg north of
// east", "30 south of west").
#include <optional>
#include <string>

#include "core/vec.hpp"
#include "scene/toml_reader.hpp"

namespace collide::scene::detail {

// (cos a, sin a) for an angle in degrees, exact at multiples of 90 degrees (a heading "N" is
// [0, 1], not [6e-17, 1]).
core::Vec2 unitVectorAtDegrees(double degrees);

// A heading node in degrees from +x: a number, an angle ("30 deg", "pi/6 rad") or compass words.
// Without a value, `why` says what is wrong and what is allowed.
std::optional<double> headingDegrees(const toml::node& node, std::string& why);

// What `heading` allows, for messages and docs.
std::string headingAllowed();

}  // namespace collide::scene::detail
