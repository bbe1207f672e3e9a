// SPDX-License-Identifier: MIT
#include "scene/heading.hpp"

#include <cctype>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

#include "scene/fields.hpp"
#include "scene/quantity.hpp"

namespace collide::scene::detail {
namespace {

std::string lowered(const std::string& text) {
  std::string result = text;
  for (char& c : result) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return result;
}

// Degrees from +x (east) of a compass point: "n", "north", "ne", "north-east", "northeast".
std::optional<double> compassPoint(const std::string& word) {
  static const std::pair<const char*, double> kPoints[] = {
      {"e", 0.0},   {"east", 0.0},    {"ne", 45.0},   {"northeast", 45.0},   {"north-east", 45.0},
      {"n", 90.0},  {"north", 90.0},  {"nw", 135.0},  {"northwest", 135.0},  {"north-west", 135.0},
      {"w", 180.0}, {"west", 180.0},  {"sw", -135.0}, {"southwest", -135.0}, {"south-west", -135.0},
      {"s", -90.0}, {"south", -90.0}, {"se", -45.0},  {"southeast", -45.0},  {"south-east", -45.0}};
  for (const auto& [name, degrees] : kPoints) {
    if (word == name) return degrees;
  }
  return std::nullopt;
}

// "ANGLE TOWARDS of FROM": FROM's direction turned ANGLE towards TOWARDS (a quarter turn away).
std::optional<double> angleOfFrom(const std::string& text, std::string& why) {
  std::vector<std::string> words;
  std::istringstream in(lowered(text));
  for (std::string word; in >> word;) words.push_back(word);
  if (words.size() < 4 || words[words.size() - 2] != "of") return std::nullopt;
  const std::optional<double> from = compassPoint(words.back());
  const std::optional<double> towards = compassPoint(words[words.size() - 3]);
  if (!from || !towards || words.back().size() < 4 || words[words.size() - 3].size() < 4) {
    return std::nullopt;
  }
  const double turn = std::remainder(*towards - *from, 360.0);
  if (std::abs(turn) != 90.0) {
    why = "'" + words[words.size() - 3] + " of " + words.back() +
          "' is no quarter turn; allowed: " + headingAllowed();
    return std::nullopt;
  }
  std::string angle_text;
  for (std::size_t i = 0; i + 3 < words.size(); ++i) angle_text += (i > 0 ? " " : "") + words[i];
  const QuantityReading angle = readQuantity(angle_text, Quantity::kAngle);
  if (!angle.value) {
    why = angle.problem;
    return std::nullopt;
  }
  return *from + (turn > 0 ? *angle.value : -*angle.value);
}

}  // namespace

core::Vec2 unitVectorAtDegrees(double degrees) {
  const double turned = std::remainder(degrees, 360.0);  // in [-180, 180]
  if (turned == 0.0) return {1.0, 0.0};
  if (turned == 90.0) return {0.0, 1.0};
  if (turned == -90.0) return {0.0, -1.0};
  if (std::abs(turned) == 180.0) return {-1.0, 0.0};
  const double radians = degrees * std::numbers::pi / 180.0;
  return {std::cos(radians), std::sin(radians)};
}

std::string headingAllowed() {
  return "degrees from +x, counter-clockwise (a number, or \"30 deg\", \"pi/6 rad\"), or compass "
         "words with +x east: \"N\", \"NE\", \"north\", \"60 deg north of east\"";
}

std::optional<double> headingDegrees(const toml::node& node, std::string& why) {
  const auto* text = node.as_string();
  if (text == nullptr) {
    const std::optional<double> degrees = asQuantity(node, Quantity::kAngle, why);
    if (!degrees) why += "; allowed: " + headingAllowed();
    return degrees;
  }
  std::string word = lowered(text->get());
  word.erase(0, word.find_first_not_of(" \t"));
  word.erase(word.find_last_not_of(" \t") + 1);
  if (const std::optional<double> point = compassPoint(word)) return point;
  if (const std::optional<double> degrees = angleOfFrom(text->get(), why)) return degrees;
  if (!why.empty()) return std::nullopt;
  const QuantityReading angle = readQuantity(text->get(), Quantity::kAngle);
  if (!angle.value) why = "not a direction; allowed: " + headingAllowed();
  return angle.value;
}

}  // namespace collide::scene::detail
