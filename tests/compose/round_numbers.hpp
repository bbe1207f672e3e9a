#pragma once
// Whether a scale a picture states (an arrow's speed, an impulse bar's size) is a round number,
// as a teacher reads one: 1, 2 or 5 times a power of ten.
#include <cmath>

namespace collide::test {

inline bool isRound(double value) {
  const double mantissa = value / std::pow(10.0, std::floor(std::log10(value)));
  return std::abs(mantissa - 1.0) < 1e-9 || std::abs(mantissa - 2.0) < 1e-9 ||
         std::abs(mantissa - 5.0) < 1e-9;
}

}  // namespace collide::test
