#include "compose/frame_text.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <regex>

namespace collide::compose {

std::string subscript(int index) {
  static const char* const kDigits[] = {"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
  std::string out;
  for (char c : std::to_string(index)) out += kDigits[c - '0'];
  return out;
}

std::string number(double value, int decimals, bool with_sign) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, std::abs(value));
  // Values that round to zero show as 0.00, never −0.00.
  bool zero = true;
  for (const char* p = text; *p != '\0'; ++p) zero = zero && (*p == '0' || *p == '.');
  if (zero) return text;
  if (value < 0.0) return "\u2212" + std::string(text);
  return with_sign ? "+" + std::string(text) : std::string(text);
}

std::string timeText(double t_s) {
  return "t = " + number(t_s, 3) + " s";
}

std::string massLabel(int index, double mass_kg) {
  const int decimals = mass_kg >= 1000.0 ? 0 : 2;
  return "m" + subscript(index) + " = " + number(mass_kg, decimals) + " kg";
}

std::string velocityLabel(int index, const core::Vec2& v, bool primed, int dimensions) {
  std::string name = "v" + subscript(index) + (primed ? "\u2032" : "");
  if (dimensions == 1) return name + " = " + number(v.x(), 2, true) + " m/s";
  const double speed = v.norm();
  std::string text = name + " = " + number(speed, 2) + " m/s";
  if (speed > 1e-9) {
    const double degrees = std::atan2(v.y(), v.x()) * 180.0 / std::numbers::pi;
    text += ", " + number(degrees, 0) + "°";
  }
  return text;
}

std::string momentumText(const core::Vec2& p, int dimensions) {
  if (dimensions == 1) return number(p.x(), 2, true) + " kg·m/s";
  return "(" + number(p.x(), 2) + ", " + number(p.y(), 2) + ") kg·m/s";
}

std::string energyLabel(const std::string& name, double energy_J) {
  return name + " " + number(energy_J, std::abs(energy_J) >= 100.0 ? 0 : 2) + " J";
}

std::string panelHeading(const std::string& key, double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  if (key == "restitution") return std::string("e = ") + text;
  static const std::regex body_key(R"(body\.(\d+)\.(mass|size|velocity|speed))");
  std::smatch match;
  if (std::regex_match(key, match, body_key)) {
    const int index = std::stoi(match[1]);
    const std::string what = match[2];
    if (what == "mass") return "m" + subscript(index) + " = " + text + " kg";
    if (what == "size") return "size" + subscript(index) + " = " + text + " m";
    return "v" + subscript(index) + " = " + text + " m/s";
  }
  return key + " = " + text;
}

}  // namespace collide::compose
