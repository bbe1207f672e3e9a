// SPDX-License-Identifier: MIT
#pragma once
// Internal: a bound on how fast the gap between two bodies on taut strings of one length can
// curve, from their relative motion (docs/physics.md, "Bodies on strings"). The general bound
// (relative speed squared over the radii plus the accelerations) does not shrink as two swings
// come into step, so the search for the next contact of a cradle's balls swinging together a
// hair apart crawled in steps of the square root of that hair. This one is proportional to the
// relative motion itself, and the search crosses a swing in a few steps however close the two are.
//
// With delta = theta_b - theta_a and omega0 = sqrt(g / L), each angle obeys
// theta'' = -omega0^2 sin(theta), so delta'' = -omega0^2 (sin theta_b - sin theta_a) and
//   E = delta'^2 + omega0^2 delta^2,  E' = 2 omega0^2 delta' (delta - (sin theta_b - sin theta_a)).
// The bracket is the integral of 1 - cos over [theta_a, theta_b], at most kappa |delta| with
// kappa = 1 - cos(largest angle) (2 for a swing over the top), so |E'| <= omega0 kappa E and
// E(t) <= E(t0) exp(omega0 kappa |t - t0|): over the horizon |delta| <= a = sqrt(E) / omega0 and
// |delta'| <= omega0 a. The offset between the bodies is D + L (s(theta_b) - s(theta_a)) with
// s = (sin, -cos) and D the step between the pivots, so with Omega a bound on both |theta'|:
//   |offset'| <= L a (omega0 + Omega),  |offset''| <= L a ((omega0 + Omega)^2 + omega0^2),
// and the gap |offset| - R curves by at most |offset''| + |offset'|^2 / R while it is >= 0.
#include "physics/pendulum_motion.hpp"

namespace collide::physics::detail {

struct SwingPair {
  double length_m = 0.0;                   // of both strings
  double omega0_rad_s = 0.0;               // sqrt(g / L)
  double reach_m = 0.0;                    // the sum of the radii: the distance at contact
  PendulumState a, b;                      // both at the start of the horizon
  double largest_angle_rad = 0.0;          // bound on |theta| of both over it (pi or more: any)
  double angular_speed_bound_rad_s = 0.0;  // bound on |theta'| of both over it
};

// A bound on |gap''| over [t0, t0 + horizon_s] while the gap is >= 0.
double swingPairCurvature_mps2(const SwingPair& pair, double horizon_s);

}  // namespace collide::physics::detail
