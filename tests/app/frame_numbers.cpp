// SPDX-License-Identifier: MIT
#include "frame_numbers.hpp"

#include <algorithm>
#include <cmath>
#include <regex>
#include <string>
#include <utility>
#include <vector>

namespace collide::frame_numbers {

// A displayed number back to a double: true minus sign, thousands commas ("12,500").
double parseShown(std::string text) {
  const bool negative = text.rfind(kMinus, 0) == 0;
  if (negative) text.erase(0, kMinus.size());
  text.erase(std::remove(text.begin(), text.end(), ','), text.end());
  return negative ? -std::stod(text) : std::stod(text);
}

// The number at the end of an energy label "KE₁ 12.3 mJ", its unit and its decimals.
bool labelValue(const std::string& label, double& value, std::string& unit, int& decimals) {
  static const std::regex pattern(R"(((?:\xE2\x88\x92)?[0-9][0-9,]*(?:\.([0-9]+))?) ([µmkMG]?J)$)");
  std::smatch match;
  if (!std::regex_search(label, match, pattern)) return false;
  value = parseShown(match[1]);
  decimals = match[2].matched ? static_cast<int>(match[2].length()) : 0;
  unit = match[3];
  return true;
}

double unitValue(const std::string& unit) {
  if (unit == "µJ") return 1e-6;
  if (unit == "mJ") return 1e-3;
  if (unit == "kJ") return 1e3;
  if (unit == "MJ") return 1e6;
  if (unit == "GJ") return 1e9;
  return 1.0;
}

std::vector<Picture>& everyPreset() {
  static std::vector<Picture> pictures = [] {
    std::vector<Picture> all;
    for (const scene::PresetInfo& info : scene::presetList()) {
      scene::SceneDesc scene = scene::loadPreset(info.name);
      app::Animation animation = app::animate(scene, {1280, 720});
      all.push_back({info.name, std::move(scene), std::move(animation)});
    }
    return all;
  }();
  return pictures;
}

double instant(const scene::SceneDesc& scene, int k) {
  return scene.duration_s * k / (kInstants - 1);
}

// Significant figures of a shown number with `decimals` decimals: "7.22" -> 3, "0.680" -> 3.
int figuresOf(double value, int decimals) {
  if (value == 0.0) return 0;
  return static_cast<int>(std::floor(std::log10(std::fabs(value)))) + decimals + 1;
}

// The signed number and its decimals in a velocity label "v₁′ = +0.170 m/s" (1D) or the speed in
// "v₁ = 4.26 m/s, −82°" (2D).
bool velocityValue(const std::string& label, double& value, int& decimals) {
  static const std::regex pattern(R"(= ((?:\+|\xE2\x88\x92)?)([0-9][0-9,]*(?:\.([0-9]+))?) m/s)");
  std::smatch match;
  if (!std::regex_search(label, match, pattern)) return false;
  value = parseShown(match[2]) * (match[1] == kMinus ? -1.0 : 1.0);
  decimals = match[3].matched ? static_cast<int>(match[3].length()) : 0;
  return true;
}

}  // namespace collide::frame_numbers
