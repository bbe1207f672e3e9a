#include "compose/frame_text.hpp"

#include <cmath>
#include <numbers>
#include <regex>

namespace collide::compose {

using text::Sign;

PictureFormats pictureFormats(double energy_J, double speed_mps, double momentum_Ns,
                              double duration_s) {
  PictureFormats formats;
  formats.energy = text::quantityFormat(energy_J, "J");
  formats.speed = text::quantityFormat(speed_mps, "m/s");
  formats.momentum = text::quantityFormat(momentum_Ns, "kg·m/s");
  formats.time = text::quantityFormat(duration_s, "s", 4);
  return formats;
}

std::string subscript(int index) {
  static const char* const kDigits[] = {"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
  std::string out;
  for (char c : std::to_string(index)) out += kDigits[c - '0'];
  return out;
}

std::string timeText(double t_s, const PictureFormats& formats) {
  return "t = " + text::formatReading(t_s, formats.time);
}

std::string massLabel(int index, double mass_kg) {
  return "m" + subscript(index) + " = " + text::formatValue(mass_kg, "kg");
}

std::string velocityLabel(int index, const core::Vec2& v, bool primed, int dimensions,
                          const PictureFormats& formats) {
  std::string name = "v" + subscript(index) + (primed ? "\u2032" : "");
  if (dimensions == 1) {
    return name + " = " +
           text::formatQuantity(v.x(), formats.speed, text::defaultStyle(), Sign::kAlways);
  }
  const double speed = v.norm();
  std::string label = name + " = " + text::formatQuantity(speed, formats.speed);
  // A direction only where the speed shows as more than 0.
  if (!text::readsZero(speed, formats.speed)) {
    label += ", " + text::formatAngle(std::atan2(v.y(), v.x()) * 180.0 / std::numbers::pi);
  }
  return label;
}

std::string momentumText(const core::Vec2& p, int dimensions, const PictureFormats& formats) {
  if (dimensions == 1) {
    return text::formatQuantity(p.x(), formats.momentum, text::defaultStyle(), Sign::kAlways);
  }
  return "(" + text::formatIn(p.x(), formats.momentum) + ", " +
         text::formatIn(p.y(), formats.momentum) + ") " + formats.momentum.unit;
}

std::string panelHeading(const std::string& key, double value) {
  const std::string shown = text::formatPlain(value);
  if (key == "restitution") return "e = " + shown;
  static const std::regex body_key(R"(body\.(\d+)\.(mass|size|velocity|speed))");
  std::smatch match;
  if (std::regex_match(key, match, body_key)) {
    const int index = std::stoi(match[1]);
    const std::string what = match[2];
    if (what == "mass") return "m" + subscript(index) + " = " + shown + " kg";
    if (what == "size") return "size" + subscript(index) + " = " + shown + " m";
    return "v" + subscript(index) + " = " + shown + " m/s";
  }
  return key + " = " + shown;
}

}  // namespace collide::compose
