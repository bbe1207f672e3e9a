#pragma once
// Numbers and bodies in words, for text a person reads (captions, alt text, metadata). Data files
// use shortestDecimal() instead, which reads back exactly.
#include <string>

#include "core/vec.hpp"
#include "physics/timeline.hpp"

namespace collide::report {

// text::formatPlain: three significant digits, no exponent, no trailing zeros: 2 -> "2",
// 0.5 -> "0.5", 2.6667 -> "2.67", 1234.5 -> "1230", 0.000123 -> "0.000123", -0 -> "0".
std::string plainNumber(double value);

// plainNumber with a unit, for a value someone typed: "2 m/s", "0.5 m".
std::string quantity(double value, const std::string& unit);

// A computed amount with three significant figures and its own SI prefix where the unit takes
// one (text::formatValue): "0.170 m/s", "8.00 mJ", "186 kJ".
std::string amount(double value, const std::string& unit);

// A percentage of `whole` with three significant figures: "25.0%", "9.70%"; round-off of zero
// (below a billionth of the whole) and a whole of 0 read "0%".
std::string percentOf(double part, double whole);

// How a body moves, in words. 1D: "at rest", "moving right at 2.00 m/s", "moving left at
// 0.170 m/s". 2D: "moving at 2.00 m/s towards 30°" (angle counter-clockwise from +x, in
// (-180°, 180°] as on the pictures), or "at rest".
std::string motionInWords(const core::Vec2& velocity_mps, int dimensions);

// The collision partner `body_b` of an event in words: the body's name, or "the wall \"left\"".
std::string partnerName(const physics::Timeline& timeline, int partner);

// Kinetic energy of the two partners just before the impact, J (a wall contributes nothing).
double pairKineticEnergyBefore(const physics::Timeline& timeline,
                               const physics::CollisionEvent& event);

}  // namespace collide::report
