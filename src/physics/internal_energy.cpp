// SPDX-License-Identifier: MIT
// The Borgnakke-Larsen exchange for hard disks; see internal_energy.hpp.
#include "physics/internal_energy.hpp"

#include <cmath>
#include <numbers>

#include "physics/plane_engine.hpp"

namespace collide::physics::detail {

double uniformDraw(std::uint64_t& state) {
  // splitmix64 (Steele, Lea & Flood, OOPSLA 2014).
  state += 0x9E3779B97F4A7C15ull;
  std::uint64_t z = state;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  // The top 53 bits, shifted by one so that 0 is never drawn (its logarithm is used below).
  return (static_cast<double>(z >> 11) + 1.0) * 0x1.0p-53;
}

double gammaOfHalfShape(int half_shapes, std::uint64_t& state) {
  // Shape 1 is an exponential variate, -ln U; shape 1/2 is Z^2 / 2 for a standard normal Z,
  // drawn as Box-Muller's -ln U1 cos^2(2 pi U2) (the square of its first normal, halved).
  double sum = 0.0;
  for (int k = 0; k + 2 <= half_shapes; k += 2) sum -= std::log(uniformDraw(state));
  if (half_shapes % 2 == 1) {
    const double radius = -std::log(uniformDraw(state));
    const double c = std::cos(2.0 * std::numbers::pi * uniformDraw(state));
    sum += radius * c * c;
  }
  return sum;
}

Shares borgnakkeLarsen(double translational_J, double internal_a_J, double internal_b_J,
                       int internal_dof, std::uint64_t& state) {
  const double total_J = translational_J + internal_a_J + internal_b_J;
  // X ~ Beta(3/2, zeta) as G(3/2) / (G(3/2) + G(zeta)); the two internal shares likewise.
  const double relative = gammaOfHalfShape(3, state);
  const double inside_a = gammaOfHalfShape(internal_dof, state);
  const double inside_b = gammaOfHalfShape(internal_dof, state);
  Shares out;
  out.translational_J = total_J * (relative / (relative + inside_a + inside_b));
  const double inside_J = total_J - out.translational_J;
  out.internal_a_J = inside_J * (inside_a / (inside_a + inside_b));
  out.internal_b_J = inside_J - out.internal_a_J;
  return out;
}

core::Vec2 exchangeImpulse(const core::Vec2& v_a, const core::Vec2& v_b, const core::Vec2& n,
                           double reduced_mass_kg, double translational_after_J) {
  const core::Vec2 g = v_a - v_b;
  const core::Vec2 rebound = g - 2.0 * g.dot(n) * n;
  const double speed_before = g.norm();
  const double speed_after = std::sqrt(2.0 * translational_after_J / reduced_mass_kg);
  const core::Vec2 g_after = speed_before > 0.0 ? core::Vec2(rebound * (speed_after / speed_before))
                                                : core::Vec2(-speed_after * n);
  return reduced_mass_kg * (g_after - g);
}

}  // namespace collide::physics::detail

namespace collide::physics::detail {

bool PlaneEngine::exchangeWithInsides(int a, int b, const PairResponse& r, const core::Vec2& n,
                                      CollisionEvent& event) {
  UnitState &ua = state_.units[state_.bodies[a].unit], &ub = state_.units[state_.bodies[b].unit];
  const bool free_disks = r.ca == 0.0 && r.cb == 0.0 && r.blocked_a == 0 && r.blocked_b == 0 &&
                          ua.omega_radps == 0.0 && ub.omega_radps == 0.0 && ua.resting_walls == 0 &&
                          ub.resting_walls == 0;
  if (!free_disks) return false;
  const double reduced_mass_kg = 1.0 / (1.0 / ua.mass_kg + 1.0 / ub.mass_kg);
  const double translational_J = 0.5 * reduced_mass_kg * (ua.v_mps - ub.v_mps).squaredNorm();
  const Shares shares = borgnakkeLarsen(translational_J, state_.internal_J[a], state_.internal_J[b],
                                        model_.world.internal_dof, state_.internal_rng);
  const core::Vec2 impulse =
      exchangeImpulse(ua.v_mps, ub.v_mps, n, reduced_mass_kg, shares.translational_J);
  ua.v_mps += impulse / ua.mass_kg;
  ub.v_mps -= impulse / ub.mass_kg;
  state_.internal_J[a] = shares.internal_a_J;
  state_.internal_J[b] = shares.internal_b_J;
  // Energy went inside or came out, not lost: the books hold it as internal energy.
  event.impulse_Ns = impulse.norm();
  event.energy_lost_J = 0.0;
  event.energy_lost_analytic_J = 0.0;
  return true;
}

}  // namespace collide::physics::detail
