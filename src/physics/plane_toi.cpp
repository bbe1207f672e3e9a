// Times of impact in 2D. Translating units: the separation is a polynomial in time (a quadratic
// for disks sharing one acceleration, a quartic when a unit rests on a wall). Rotating clusters:
// conservative advancement, which steps by gap / (bound on the closing speed) and so can never
// step past a contact.
#include <algorithm>
#include <cmath>

#include "physics/plane_engine.hpp"
#include "physics/toi.hpp"

namespace collide::physics::detail {
namespace {

// Relative size of a normal speed that is only rounding of the velocities involved.
constexpr double kRoundingSpeed = 1e-12;
// Deepest overlap a step forced past a grazing contact may leave, m: a tenth of the overlap the
// property tests accept, far below anything drawn.
constexpr double kGrazeDepth_m = 1e-10;

}  // namespace
double PlaneEngine::predictPair(int a, int b) const {
  const UnitState& ua = state_.units[state_.bodies[a].unit];
  const UnitState& ub = state_.units[state_.bodies[b].unit];
  const double t0 = std::max(ua.t_ref_s, ub.t_ref_s);
  const double tau_max = model_.world.duration_s - t0;
  if (ua.omega_radps != 0.0 || ub.omega_radps != 0.0) {
    return conservativeAdvance(a, b, false, t0, tau_max);
  }
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
  if (d2.x() == 0.0 && d2.y() == 0.0) return t0 + firstClosingRoot(c0, c1, d1.squaredNorm());
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
  const WallDef& w = model_.world.walls[wall];
  const Kin k = kinematics(body, t0);
  const double s0 = (k.x - w.point_m).dot(w.normal) - model_.half_size_m[body];
  double s1 = k.v.dot(w.normal);
  if (s0 <= 0.0 && s1 < 0.0 && s1 > -kRoundingSpeed * k.v.norm()) s1 = 0.0;
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
  auto gapAndRate = [&](double tau, double& gap, double& rate) {
    const Kin ka = kinematics(a, t0 + tau);
    if (wall) {
      gap = (ka.x - w->point_m).dot(w->normal) - reach;
      rate = ka.v.dot(w->normal);
    } else {
      const Kin kb = kinematics(other, t0 + tau);
      const core::Vec2 d = kb.x - ka.x;
      const double distance = d.norm();
      gap = distance - reach;
      rate = distance > 0.0 ? d.dot(kb.v - ka.v) / distance : -1.0;
    }
  };
  auto centreSpeed = [&](double tau) {
    if (wall) return std::abs((ua.v_mps + ua.a_mps2 * (t0 + tau - ua.t_ref_s)).dot(w->normal));
    const core::Vec2 va = ua.v_mps + ua.a_mps2 * (t0 + tau - ua.t_ref_s);
    const core::Vec2 vb = ub->v_mps + ub->a_mps2 * (t0 + tau - ub->t_ref_s);
    return (vb - va).norm();
  };
  const double tolerance = 1e-12 * std::max(1.0, reach);
  // Bound on |gap''|: relative acceleration, centripetal terms, and (between disks) the
  // curvature of the distance, |tangential relative velocity|^2 / distance.
  const double centripetal =
      ua.omega_radps * ua.omega_radps * state_.bodies[a].offset_m.norm() +
      (wall ? 0.0 : ub->omega_radps * ub->omega_radps * state_.bodies[other].offset_m.norm());
  double tau = 0.0;
  // Floor on the step, doubled each time it binds: leaving a grazing contact costs a few dozen
  // steps instead of millions (a contact found after such a jump is late by under one step).
  double min_step = 1e-13 * std::max(1.0, t0);
  for (int iteration = 0; iteration < 20000 && tau <= tau_max; ++iteration) {
    double gap, rate;
    gapAndRate(tau, gap, rate);
    const double speed = centreSpeed(tau) + spin;
    if (gap <= tolerance && rate < -kRoundingSpeed * speed) return t0 + tau;
    // Over the next step the speed stays below twice its present bound (the step is capped so
    // that acceleration cannot add more), which bounds the curvature term.
    double curvature = accel_bound + centripetal;
    if (!wall) curvature += 4.0 * speed * speed / (0.5 * reach);
    double h;
    if (curvature <= 0.0) {
      h = rate < 0.0 ? (gap - tolerance) / -rate : kNever;
    } else {
      // gap(tau + s) >= gap + rate s - curvature s^2 / 2: step to where that bound reaches zero
      // (from an overlap that is opening, to where the bound turns positive and back to zero).
      const double disc = rate * rate + 2.0 * curvature * (gap - tolerance);
      h = disc > 0.0 ? (rate + std::sqrt(disc)) / curvature : std::max(rate, 0.0) / curvature;
    }
    if (accel_bound > 0.0) h = std::min(h, std::max(speed, 1e-9) / accel_bound);
    if (!std::isfinite(h)) return kNever;
    if (h < min_step) {
      // A forced step may pass a contact, but never by more than kGrazeDepth_m: the gap falls
      // at most curvature s^2 / 2 below its linear bound over a step s.
      h = curvature > 0.0 ? std::min(min_step, std::sqrt(2.0 * kGrazeDepth_m / curvature))
                          : min_step;
      min_step *= 2.0;
    } else {
      min_step = 1e-13 * std::max(1.0, t0 + tau);
    }
    tau += h;
  }
  return kNever;
}

}  // namespace collide::physics::detail
