// SPDX-License-Identifier: MIT
// The curvature bound of two swings on strings of one length (see swing_pair_bound.hpp).
#include "physics/swing_pair_bound.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace collide::physics::detail {

double swingPairCurvature_mps2(const SwingPair& pair, double horizon_s) {
  const double w0 = pair.omega0_rad_s;
  const double delta = pair.b.angle_rad - pair.a.angle_rad;
  const double rate = pair.b.angular_velocity_rad_s - pair.a.angular_velocity_rad_s;
  const double kappa =
      pair.largest_angle_rad >= std::numbers::pi ? 2.0 : 1.0 - std::cos(pair.largest_angle_rad);
  const double energy = (rate * rate + w0 * w0 * delta * delta) * std::exp(w0 * kappa * horizon_s);
  const double a = std::sqrt(energy) / w0;  // bound on |delta| over the horizon
  const double fast = w0 + pair.angular_speed_bound_rad_s;
  const double offset_rate = pair.length_m * a * fast;
  const double offset_curve = pair.length_m * a * (fast * fast + w0 * w0);
  return offset_curve + offset_rate * offset_rate / pair.reach_m;
}

}  // namespace collide::physics::detail
