#include "physics/string_impact.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace collide::physics::detail {
namespace {

// Velocities after impulses J (contact), Ta, Tb (strings).
void apply(const ImpactPartner& a, const ImpactPartner& b, const core::Vec2& n, double J, double Ta,
           double Tb, StringImpact& out) {
  out.velocity_a_mps = a.velocity_mps - a.inverse_mass_per_kg * (J * n + Ta * a.string_out);
  out.velocity_b_mps = b.velocity_mps + b.inverse_mass_per_kg * (J * n - Tb * b.string_out);
  out.contact_impulse_Ns = J;
  out.tension_impulse_a_Ns = Ta;
  out.tension_impulse_b_Ns = Tb;
}

}  // namespace

StringImpact resolveStringImpact(const ImpactPartner& a, const ImpactPartner& b,
                                 const core::Vec2& n, double restitution) {
  const double wa = a.inverse_mass_per_kg, wb = b.inverse_mass_per_kg;
  const double closing = n.dot(a.velocity_mps - b.velocity_mps);
  const double na = n.dot(a.string_out), nb = n.dot(b.string_out);
  const double speed_scale = a.velocity_mps.norm() + b.velocity_mps.norm();
  StringImpact best;
  // Choices of holding strings, most constrained first; a string that is not taut never holds.
  for (int choice = 0; choice < 4; ++choice) {
    const bool hold_a = a.taut && wa > 0.0 && (choice & 1) == 0;
    const bool hold_b = b.taut && wb > 0.0 && (choice & 2) == 0;
    if ((choice & 1) != 0 && !(a.taut && wa > 0.0)) continue;
    if ((choice & 2) != 0 && !(b.taut && wb > 0.0)) continue;
    // Unknowns (J, Ta, Tb). Rows: the restitution law along n, then each holding string's
    // radial velocity after = 0. Free unknowns of strings that do not hold are fixed at 0.
    Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    m(0, 0) = wa + wb;
    m(0, 1) = hold_a ? wa * na : 0.0;
    m(0, 2) = hold_b ? -wb * nb : 0.0;
    rhs(0) = (1.0 + restitution) * closing;
    if (hold_a) {
      m(1, 0) = wa * na;
      m(1, 1) = wa;
      rhs(1) = a.string_out.dot(a.velocity_mps);
    }
    if (hold_b) {
      m(2, 0) = -wb * nb;
      m(2, 2) = wb;
      rhs(2) = b.string_out.dot(b.velocity_mps);
    }
    const Eigen::Vector3d x = m.partialPivLu().solve(rhs);
    StringImpact out;
    apply(a, b, n, x(0), hold_a ? x(1) : 0.0, hold_b ? x(2) : 0.0, out);
    out.string_a_holds = hold_a;
    out.string_b_holds = hold_b;
    // Consistent: holding strings pull (T >= 0), strings let go only where the body then moves
    // towards its pivot (radial velocity <= 0), each to within rounding.
    const double slack_tol = 1e-12 * speed_scale;
    const double pull_tol = -1e-12 * (std::abs(x(0)) + 1e-300);
    bool consistent = true;
    if (hold_a && x(1) < pull_tol) consistent = false;
    if (hold_b && x(2) < pull_tol) consistent = false;
    if (a.taut && wa > 0.0 && !hold_a && a.string_out.dot(out.velocity_a_mps) > slack_tol) {
      consistent = false;
    }
    if (b.taut && wb > 0.0 && !hold_b && b.string_out.dot(out.velocity_b_mps) > slack_tol) {
      consistent = false;
    }
    out.energy_lost_J = 0.5 * out.contact_impulse_Ns * closing * (1.0 - restitution);
    if (consistent) return out;
    if (choice == 0) best = out;
  }
  return best;  // not reached for a positive definite problem; the all-holding answer
}

}  // namespace collide::physics::detail
