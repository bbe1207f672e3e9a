// Times of impact in 2D. Translating units: the separation is a polynomial in time (a quadratic
// for disks sharing one acceleration, a quartic when a unit rests on a wall). Rotating clusters:
// conservative advancement (conservative_advance.hpp), which steps by gap / (bound on the closing
// speed) and so can never step past a contact.
#include <algorithm>
#include <cmath>

#include "physics/conservative_advance.hpp"
#include "physics/plane_engine.hpp"
#include "physics/toi.hpp"

namespace collide::physics::detail {
double PlaneEngine::predictPair(int a, int b) const {
  const UnitState& ua = state_.units[state_.bodies[a].unit];
  const UnitState& ub = state_.units[state_.bodies[b].unit];
  const double t0 = std::max(ua.t_ref_s, ub.t_ref_s);
  double tau_max = model_.world.duration_s - t0;
  // With friction the motion holds until the first of the two stops (which predicts again).
  if (friction_) {
    tau_max = std::min(
        {tau_max, stopTime(state_.bodies[a].unit) - t0, stopTime(state_.bodies[b].unit) - t0});
  }
  if (ua.omega_radps != 0.0 || ub.omega_radps != 0.0) {
    return conservativeAdvance(a, b, false, t0, tau_max);
  }
  if (model_.has_drag && (hasDrag(ua) || hasDrag(ub))) return predictDraggedPair(a, b, t0);
  const Kin ka = kinematics(a, t0), kb = kinematics(b, t0);
  const core::Vec2 d0 = kb.x - ka.x, d1 = kb.v - ka.v, d2 = ub.a_mps2 - ua.a_mps2;
  const double reach = model_.half_size_m[a] + model_.half_size_m[b];
  const double distance = d0.norm();
  // |d(tau)|^2 - R^2, its constant term factored to keep precision at contact.
  const double c0 = (distance - reach) * (distance + reach);
  double c1 = 2.0 * d0.dot(d1);
  // In contact, an approach below rounding of the velocities (left by an e = 0 impulse) is no
  // approach: treating it as one would replay the same impact forever.
  if (c0 <= 0.0 && c1 < 0.0 &&
      c1 > -kRoundingSpeed * 2.0 * distance * (ka.v.norm() + kb.v.norm())) {
    c1 = 0.0;
  }
  if (d2.x() == 0.0 && d2.y() == 0.0) {
    // Apart and not approaching: the gap only grows (half of all pairs; no root to look for).
    if (c0 > 0.0 && c1 >= 0.0) return kNever;
    return t0 + firstClosingRoot(c0, c1, d1.squaredNorm());
  }
  const double c[5] = {c0, c1, d1.squaredNorm() + d0.dot(d2), d1.dot(d2), 0.25 * d2.squaredNorm()};
  return t0 + firstClosingRootPoly(c, 4, tau_max);
}

double PlaneEngine::predictWall(int body, int wall) const {
  const UnitState& u = state_.units[state_.bodies[body].unit];
  if (wall < 32 && (u.resting_walls >> wall) & 1u) return kNever;  // sliding on it
  const double t0 = u.t_ref_s;
  if (u.omega_radps != 0.0) {
    return conservativeAdvance(body, wall, true, t0, model_.world.duration_s - t0);
  }
  if (model_.has_drag && hasDrag(u)) return predictDraggedWall(body, wall, t0);
  const WallDef& w = model_.world.walls[wall];
  const Kin k = kinematics(body, t0);
  const double s0 = (k.x - w.point_m).dot(w.normal) - model_.half_size_m[body];
  double s1 = k.v.dot(w.normal);
  if (s0 <= 0.0 && s1 < 0.0 && s1 > -kRoundingSpeed * k.v.norm()) s1 = 0.0;
  if (friction_ && (u.friction_mps2.x() != 0.0 || u.friction_mps2.y() != 0.0)) {
    return t0 + slowingWallTime(state_.bodies[body].unit, s0, s1, 0.5 * u.a_mps2.dot(w.normal), t0);
  }
  return t0 + firstClosingRoot(s0, s1, 0.5 * u.a_mps2.dot(w.normal));
}

double PlaneEngine::conservativeAdvance(int a, int other, bool wall, double t0,
                                        double tau_max) const {
  const int unit_a = state_.bodies[a].unit;
  const UnitState& ua = state_.units[unit_a];
  const UnitState* ub = wall ? nullptr : &state_.units[state_.bodies[other].unit];
  const WallDef* w = wall ? &model_.world.walls[other] : nullptr;
  const double reach = model_.half_size_m[a] + (wall ? 0.0 : model_.half_size_m[other]);
  // Speed of a disk centre relative to its unit's centre of mass is at most |omega| |offset|.
  const double spin =
      std::abs(ua.omega_radps) * state_.bodies[a].offset_m.norm() +
      (wall ? 0.0 : std::abs(ub->omega_radps) * state_.bodies[other].offset_m.norm());
  const core::Vec2 accel = wall ? ua.a_mps2 : core::Vec2(ub->a_mps2 - ua.a_mps2);
  const double accel_bound = wall ? std::abs(accel.dot(w->normal)) : accel.norm();
  auto gapAt = [&](double tau) {
    GapState s;
    const Kin ka = kinematics(a, t0 + tau);
    if (wall) {
      s.gap_m = (ka.x - w->point_m).dot(w->normal) - reach;
      s.rate_mps = ka.v.dot(w->normal);
      s.speed_mps =
          std::abs((ua.v_mps + ua.a_mps2 * (t0 + tau - ua.t_ref_s)).dot(w->normal)) + spin;
    } else {
      const Kin kb = kinematics(other, t0 + tau);
      const core::Vec2 d = kb.x - ka.x;
      const double distance = d.norm();
      s.gap_m = distance - reach;
      s.rate_mps = distance > 0.0 ? d.dot(kb.v - ka.v) / distance : -1.0;
      const core::Vec2 va = ua.v_mps + ua.a_mps2 * (t0 + tau - ua.t_ref_s);
      const core::Vec2 vb = ub->v_mps + ub->a_mps2 * (t0 + tau - ub->t_ref_s);
      s.speed_mps = (vb - va).norm() + spin;
    }
    return s;
  };
  AdvanceBounds bounds;
  bounds.start_s = t0;
  bounds.tau_max_s = tau_max;
  bounds.accel_mps2 = accel_bound;
  // Centripetal acceleration of the disk centres about their units' centres of mass.
  bounds.centripetal_mps2 =
      ua.omega_radps * ua.omega_radps * state_.bodies[a].offset_m.norm() +
      (wall ? 0.0 : ub->omega_radps * ub->omega_radps * state_.bodies[other].offset_m.norm());
  bounds.reach_m = wall ? 0.0 : reach;
  bounds.tolerance_m = 1e-12 * std::max(1.0, reach);
  return t0 + detail::conservativeAdvance(gapAt, bounds);
}

}  // namespace collide::physics::detail
