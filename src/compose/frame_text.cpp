#include "compose/frame_text.hpp"

#include <cmath>
#include <numbers>
#include <regex>

#include "text/translate.hpp"
#include "text/wording.hpp"

namespace collide::compose {

using text::Sign;
using text::Symbol;

PictureFormats pictureFormats(double energy_J, double speed_mps, double momentum_Ns,
                              double duration_s, double length_m) {
  PictureFormats formats;
  formats.energy = text::quantityFormat(energy_J, "J");
  formats.speed = text::quantityFormat(speed_mps, "m/s");
  formats.momentum = text::quantityFormat(momentum_Ns, "kg·m/s");
  formats.time = text::quantityFormat(duration_s, "s", 4);
  if (length_m > 0.0) formats.length = text::quantityFormat(length_m, "m");
  return formats;
}

std::string subscript(int index) {
  static const char* const kDigits[] = {"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
  std::string out;
  for (char c : std::to_string(index)) out += kDigits[c - '0'];
  return out;
}

std::string timeText(double t_s, const PictureFormats& formats) {
  return text::equation(text::symbol(Symbol::kTime), text::formatReading(t_s, formats.time));
}

std::string collisionsSoFar(int count) {
  // TRANSLATORS: the info line's count of collisions so far ("collisions: 3").
  return text::fill(text::tr("collisions: {count}"), {{"count", text::formatScaled(count, 0)}});
}

std::string massLabel(int index, double mass_kg, bool with_air_drag) {
  const std::string mass = text::equation(text::symbol(Symbol::kMass) + subscript(index),
                                          text::formatValue(mass_kg, "kg"));
  if (!with_air_drag) return mass;
  // TRANSLATORS: the mass label of a body that feels air drag, so that a picture of the same
  // throw with and without drag says which body is which ("m₂ = 0.200 kg, with drag").
  return text::fill(text::trc("mass label", "{mass}, with drag"), {{"mass", mass}});
}

std::string velocityLabel(int index, const core::Vec2& v, bool primed, int dimensions,
                          const PictureFormats& formats) {
  std::string name = text::symbol(Symbol::kVelocity) + subscript(index) + (primed ? "\u2032" : "");
  if (dimensions == 1) {
    return text::equation(
        name, text::formatQuantity(v.x(), formats.speed, text::defaultStyle(), Sign::kAlways));
  }
  const double speed = std::hypot(v.x(), v.y());  // norm() would square 1e-300 m/s to 0
  std::string label = text::equation(name, text::formatQuantity(speed, formats.speed));
  // A direction only where the speed shows as more than 0.
  if (!text::readsZero(speed, formats.speed)) {
    label += text::listSeparator() +
             text::formatAngle(std::atan2(v.y(), v.x()) * 180.0 / std::numbers::pi);
  }
  return label;
}

std::string momentumText(const core::Vec2& p, int dimensions, const PictureFormats& formats) {
  if (dimensions == 1) {
    return text::formatQuantity(p.x(), formats.momentum, text::defaultStyle(), Sign::kAlways);
  }
  return text::formatComponentsIn(p.x(), p.y(), formats.momentum) + " " + formats.momentum.unit;
}

std::string panelHeading(const std::string& key, double value) {
  const std::string shown = text::formatPlain(value);
  if (key == "restitution") return text::equation(text::symbol(Symbol::kRestitution), shown);
  static const std::regex body_key(R"(body\.(\d+)\.(mass|size|velocity|speed))");
  std::smatch match;
  if (std::regex_match(key, match, body_key)) {
    const int index = std::stoi(match[1]);
    const std::string what = match[2];
    if (what == "mass") {
      return text::equation(text::symbol(Symbol::kMass) + subscript(index), shown + " kg");
    }
    if (what == "size") {
      // TRANSLATORS: a panel's heading when the panels differ in a body's size: "size₂ = 0.5 m".
      return text::equation(text::trc("panel heading", "size") + subscript(index), shown + " m");
    }
    return text::equation(text::symbol(Symbol::kVelocity) + subscript(index), shown + " m/s");
  }
  return key + " = " + shown;
}

}  // namespace collide::compose
