// SPDX-License-Identifier: MIT
#pragma once
// Internal to collide_scene: a value written as text, "25 g", "60 km/h", "sqrt(3)/2", "pi/6 rad",
// read into the number the scene stores (SI; angles in degrees). The arithmetic is muParser's, the
// units UDUNITS-2's, kept to the units a physics class uses (docs/scene-format.md lists them).
#include <optional>
#include <string>

namespace collide::scene::detail {

// What a number measures; it decides which units are allowed and what a bare number means.
enum class Quantity {
  kNumber,         // no unit (a coefficient, a factor, an exponent)
  kMass,           // kg
  kLength,         // m
  kTime,           // s
  kSpeed,          // m/s
  kAcceleration,   // m/s^2
  kAngle,          // degrees (a bare number is degrees, as the scene has always read angles)
  kFrequency,      // Hz
  kLinearDrag,     // kg/s: a drag force per speed
  kQuadraticDrag,  // kg/m: a drag force per speed squared
};

// "a mass", "a velocity", "a number without a unit".
std::string quantityName(Quantity kind);
// The units allowed for `kind`, comma-separated ("kg, g, mg, t, lb"); empty for kNumber.
std::string quantityUnits(Quantity kind);
// The unit a bare number is in, as docs/scene-format.md writes it ("kg", "m/s^2", "degrees").
std::string quantityBaseUnit(Quantity kind);

struct QuantityReading {
  std::optional<double> value;  // in the base unit; absent when `problem` says why
  std::string problem;          // "a mass, not a velocity; allowed: ..." (one line part)
};

// Reads "EXPR" or "EXPR UNIT" (EXPR: a number or muParser arithmetic with pi, sqrt, sin ...,
// evaluated once in double precision; UNIT: one of quantityUnits(kind), any spelling UDUNITS-2
// reads as that same unit). A result that is not finite is returned as it is, for the caller's
// range check. Thread-safe.
QuantityReading readQuantity(const std::string& text, Quantity kind);

// True when `text` looks like what readQuantity reads (arithmetic or a number with a unit): used
// to tell a user who wrote `restitution = 2/3` in TOML to quote it.
bool looksLikeQuantity(const std::string& text);

}  // namespace collide::scene::detail
