// SPDX-License-Identifier: MIT
#include "working/notation.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "text/wording.hpp"
#include "working/working.hpp"

namespace collide::working {
namespace {

using text::Math;

// The formatter writes "number unit" with one ASCII space (units hold none; group separators
// that are spaces are no-break ones), or a unit straight after the number ("°").
Math quantityMath(const std::string& formatted) {
  const std::size_t space = formatted.rfind(' ');
  if (space == std::string::npos) return text::number(formatted);
  return withUnit(text::number(formatted.substr(0, space)), formatted.substr(space + 1));
}

Math indexed(const std::string& base, int body, int primes, const std::string& component) {
  Math index = text::row({text::number(std::to_string(body + 1))});
  if (!component.empty()) index.parts.push_back(text::word(component));
  return text::scripts(text::symbol(base), std::move(index), {}, primes);
}

}  // namespace

Formats formatsFor(const physics::Timeline& timeline, const physics::CollisionEvent& impact) {
  double fastest_mps = 0.0;
  for (const core::Vec2& v : {impact.velocity_a_before_mps, impact.velocity_a_after_mps,
                              impact.velocity_b_before_mps, impact.velocity_b_after_mps}) {
    fastest_mps = std::max(fastest_mps, v.norm());
  }
  Formats formats;
  formats.speed = text::quantityFormat(fastest_mps > 0.0 ? fastest_mps : 1.0, "m/s");
  const double energy_J =
      std::max({timeline.initialKineticEnergy(), impact.energy_lost_J, impact.energy_released_J});
  formats.energy = text::quantityFormat(energy_J > 0.0 ? energy_J : 1.0, "J");
  formats.time = text::quantityFormat(timeline.duration_s(), "s", 4);
  return formats;
}

Math massSymbol(int body) {
  return indexed(text::symbol(text::Symbol::kMass), body, 0, "");
}

Math velocitySymbol(int body, int primes, const std::string& component) {
  return indexed(text::symbol(text::Symbol::kVelocity), body, primes, component);
}

Math plainSymbol(const std::string& letter) {
  return text::symbol(letter);
}

Math commonVelocitySymbol() {
  return text::scripts(plainSymbol(text::symbol(text::Symbol::kVelocity)), {}, {}, 1);
}

Math energyLostSymbol() {
  return text::row({text::op("Δ"), text::symbol(text::symbol(text::Symbol::kKineticEnergy))});
}

Math restitutionSymbol() {
  return text::symbol(text::symbol(text::Symbol::kRestitution));
}

Math squared(Math base) {
  return text::scripts(text::grouped(std::move(base)), {}, text::row({text::number("2")}));
}

Math half() {
  return text::fraction(text::number("1"), text::number("2"));
}

Math plain(double value, int significant) {
  return text::number(text::formatPlain(value, text::defaultStyle(), significant));
}

Math massValue(double mass_kg) {
  return text::number(text::formatIn(mass_kg, text::quantityFormat(mass_kg, "kg")));
}

Math speedValue(double value_mps, const Formats& formats) {
  return text::number(text::formatIn(value_mps, formats.speed));
}

Math withUnit(Math number, const std::string& unit) {
  return text::row({std::move(number), text::unit(unit)});
}

Math mass(double mass_kg) {
  return quantityMath(text::formatValue(mass_kg, "kg"));
}

Math velocity(const core::Vec2& velocity_mps, int dimensions, const Formats& formats,
              text::Sign sign) {
  if (dimensions == 1) return speed(velocity_mps.x(), formats, sign);
  // A component that is round-off of zero beside the other reads 0, as on the picture.
  const auto [x, y] = text::componentsIn(velocity_mps.x(), velocity_mps.y(), formats.speed);
  std::string separator = text::defaultStyle().list_separator;
  separator.erase(std::remove(separator.begin(), separator.end(), ' '), separator.end());
  Math pair = text::fenced(text::row({text::number(x), text::op(separator), text::number(y)}));
  return withUnit(std::move(pair), formats.speed.unit);
}

Math speed(double speed_mps, const Formats& formats, text::Sign sign) {
  return quantityMath(text::formatQuantity(speed_mps, formats.speed, text::defaultStyle(), sign));
}

Math energy(double energy_J, const Formats& formats) {
  return quantityMath(text::formatQuantity(energy_J, formats.energy));
}

Math amount(double value, const std::string& base_unit) {
  return quantityMath(text::formatValue(value, base_unit));
}

Equation equation(Math left, Math right, std::string note) {
  return Equation{{std::move(left), std::move(right)}, std::move(note)};
}

Equation equation3(Math left, Math middle, Math right, std::string note) {
  return Equation{{std::move(left), std::move(middle), std::move(right)}, std::move(note)};
}

}  // namespace collide::working
