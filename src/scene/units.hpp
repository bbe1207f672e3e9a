// SPDX-License-Identifier: MIT
#pragma once
// Internal to collide_scene: unit strings ("km/h", "g", "deg") through UDUNITS-2. Only the units a
// physics class uses are allowed (quantity.hpp's kinds); any spelling UDUNITS-2 reads as one of
// them
// ("kilometer/hour", "km h-1") is that unit.
#include <optional>
#include <string>
#include <vector>

#include "scene/quantity.hpp"

namespace collide::scene::detail {

// The allowed units of `kind` as typed in docs and messages ("kg", "g", ...); empty for kNumber.
const std::vector<std::string>& allowedUnits(Quantity kind);

struct UnitConversion {
  bool is_unit = false;         // UDUNITS-2 read the text as a unit (of any kind)
  std::optional<double> value;  // the value in kind's base unit, when the unit is allowed
  std::string problem;          // why not, when is_unit and no value
};

// `value` given in `unit`, converted to the base unit of `kind`. Thread-safe; the first call reads
// the UDUNITS-2 database.
UnitConversion convertToBase(double value, const std::string& unit, Quantity kind);

}  // namespace collide::scene::detail
