// SPDX-License-Identifier: MIT
#include "working_result.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace collide::test {
namespace {

double prefixScale(const std::string& unit) {
  if (unit.rfind("kJ", 0) == 0) return 1e3;
  if (unit.rfind("mJ", 0) == 0) return 1e-3;
  if (unit.rfind("µJ", 0) == 0) return 1e-6;
  if (unit.rfind("MJ", 0) == 0) return 1e6;
  return 1.0;
}

// "−0.250" (true minus, grouping commas) -> -0.25 and its decimals.
double readNumber(std::string text, int& decimals) {
  const std::string minus = "\u2212";
  if (text.rfind(minus, 0) == 0) text = "-" + text.substr(minus.size());
  std::string plain;
  for (char c : text) {
    if (c != ',') plain += c;
  }
  const std::size_t point = plain.find('.');
  decimals = point == std::string::npos ? 0 : int(plain.size() - point - 1);
  return std::stod(plain);
}

}  // namespace

ShownNumber readShown(const std::string& text) {
  ShownNumber shown;
  std::string numbers = text, unit;
  if (text.front() == '(') {
    const std::size_t close = text.find(')');
    numbers = text.substr(1, close - 1);
    unit = close + 2 < text.size() ? text.substr(close + 2) : "";
  } else if (const std::size_t space = text.find(' '); space != std::string::npos) {
    numbers = text.substr(0, space);
    unit = text.substr(space + 1);
  }
  const double scale = prefixScale(unit);
  int fewest_decimals = 99;
  std::istringstream parts(numbers);
  for (std::string part; std::getline(parts, part, ',');) {
    if (part.front() == ' ') part.erase(0, 1);
    int decimals = 0;
    shown.values.push_back(readNumber(part, decimals) * scale);
    fewest_decimals = std::min(fewest_decimals, decimals);
  }
  shown.tolerance = 0.5 * std::pow(10.0, -fewest_decimals) * scale * (1.0 + 1e-9);
  return shown;
}

std::map<std::string, ShownNumber> workingResults(const std::string& working) {
  std::map<std::string, ShownNumber> found;
  const std::size_t start = working.find("\nResult\n");
  if (start == std::string::npos) return found;
  std::istringstream lines(working.substr(start + 8));
  for (std::string line; std::getline(lines, line) && !line.empty();) {
    const std::size_t first = line.find_first_not_of(' ');
    const std::size_t equals = line.find(" = ");
    const std::size_t last = line.rfind(" = ");
    if (equals == std::string::npos) continue;
    found[line.substr(first, equals - first)] = readShown(line.substr(last + 3));
  }
  return found;
}

}  // namespace collide::test
