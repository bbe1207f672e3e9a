// SPDX-License-Identifier: MIT
#pragma once
// Reads back the "Result" step of a working (`collide solve`), as the tests of the working check
// it against the laws: each number in SI units and half a step of its last shown digit (what
// rounding may have moved it by).
#include <map>
#include <string>
#include <vector>

namespace collide::test {

struct ShownNumber {
  std::vector<double> values;  // one, or a 2D vector's two components
  double tolerance = 0.0;
  double value() const { return values.front(); }
};

// "+1.25 m/s", "−2.00 m/s", "(0.375, 0.650) m/s", "186 kJ", "314".
ShownNumber readShown(const std::string& text);

// The lines of the "Result" step: symbol -> the last side of its equation.
std::map<std::string, ShownNumber> workingResults(const std::string& working);

}  // namespace collide::test
