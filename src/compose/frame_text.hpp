#pragma once
// The words and numbers on a frame: labels with subscripts and primes, readouts and the caption,
// formatted the same way everywhere (fixed decimals, a true minus sign, units).
#include <string>

#include "core/vec.hpp"

namespace collide::compose {

// "₁", "₁₂": a 1-based index as Unicode subscript digits.
std::string subscript(int index);
// Fixed decimals with a true minus sign (U+2212); with_sign adds "+" to positives, e.g. "+2.00".
std::string number(double value, int decimals, bool with_sign = false);
// "t = 1.167 s".
std::string timeText(double t_s);
// "m₁ = 1.00 kg".
std::string massLabel(int index, double mass_kg);
// 1D: "v₁ = +2.00 m/s" (signed); 2D: "v₁ = 1.50 m/s, 30°" (speed and direction). `primed` marks a
// velocity after a collision of that body: "v₁′".
std::string velocityLabel(int index, const core::Vec2& velocity_mps, bool primed, int dimensions);
// 1D: "+1.00 kg·m/s"; 2D: "(1.00, −0.50) kg·m/s".
std::string momentumText(const core::Vec2& momentum_Ns, int dimensions);
// "KE₁ 0.25 J".
std::string energyLabel(const std::string& name, double energy_J);
// A value of a panel parameter as its heading: "e = 0.5", "m₂ = 3 kg", else "key = value".
std::string panelHeading(const std::string& key, double value);

}  // namespace collide::compose
