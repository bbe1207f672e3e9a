// SPDX-License-Identifier: MIT
#pragma once
// The symbols and numbers of a working: the picture's symbols in the active language (m₁, v₁′,
// e, KE) and its numbers as the readouts write them (three figures, the same units).
#include <string>

#include "core/vec.hpp"
#include "physics/timeline.hpp"
#include "text/math.hpp"
#include "text/number_format.hpp"

namespace collide::working {

// How each quantity of one working is written, from the largest value of it at the impact.
struct Formats {
  text::QuantityFormat speed;
  text::QuantityFormat energy;
  text::QuantityFormat time;
};

Formats formatsFor(const physics::Timeline& timeline, const physics::CollisionEvent& impact);

// Symbols. `body` is 0-based (written 1-based); `component` an index letter after it ("n", "t").
text::Math massSymbol(int body);
text::Math velocitySymbol(int body, int primes = 0, const std::string& component = "");
text::Math plainSymbol(const std::string& letter);  // "e", "g", "h", "u", "μ", "θ"
text::Math commonVelocitySymbol();                  // v′, of bodies moving on as one
text::Math energyLostSymbol();                      // ΔKE
text::Math restitutionSymbol();                     // e
text::Math squared(text::Math base);                // x², with brackets where it needs them
text::Math half();                                  // ½, as a fraction

// Numbers alone (for substituting) and with their unit (for results and given values).
text::Math plain(double value, int significant = 3);  // formatPlain: "0.5", "1.00"
text::Math massValue(double mass_kg);                 // "1.00" in kg
text::Math speedValue(double value_mps, const Formats& formats);
text::Math withUnit(text::Math number, const std::string& unit);
text::Math mass(double mass_kg);  // "1.00 kg"
// A 1D velocity signed as the readouts sign it ("+2.00 m/s"), a 2D one as "(x, y) m/s".
text::Math velocity(const core::Vec2& velocity_mps, int dimensions, const Formats& formats,
                    text::Sign sign = text::Sign::kAlways);
text::Math speed(double speed_mps, const Formats& formats, text::Sign sign = text::Sign::kAlways);
text::Math energy(double energy_J, const Formats& formats);
text::Math amount(double value, const std::string& base_unit);  // its own prefix: "0.200 m"

// "a = b" as an equation of a working.
struct Equation;
Equation equation(text::Math left, text::Math right, std::string note = "");
Equation equation3(text::Math left, text::Math middle, text::Math right, std::string note = "");

}  // namespace collide::working
