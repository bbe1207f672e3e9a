// SPDX-License-Identifier: MIT
// Air drag's closed forms. See drag_motion.hpp.
#include "physics/drag_motion.hpp"

#include <cmath>
#include <limits>

#include "physics/engine.hpp"

namespace collide::physics::detail {
namespace {

// E(tau) = (1 - e^(-a tau)) / a, the decay's integral: tau when a = 0.
double decayIntegral(double a, double tau) {
  return a == 0.0 ? tau : -std::expm1(-a * tau) / a;
}

// F(tau) = (tau - E(tau)) / a, E's own integral: tau^2 / 2 when a = 0. Below a tau = 1 the
// difference would cancel, so there it is the series tau^2 sum_n (-a tau)^n / (n + 2)!.
double decaySecondIntegral(double a, double tau) {
  const double x = a * tau;
  if (std::abs(x) >= 1.0) return (x + std::expm1(-x)) / (a * a);
  double term = 0.5, sum = 0.5;
  for (int n = 1; n < 40 && term != 0.0; ++n) {
    term *= -x / (n + 2);
    sum += term;
  }
  return tau * tau * sum;
}

// The displacement and the velocity dt_s after the reference instant.
DragState dragStep(const UnitState& unit, double dt_s) {
  const double a = unit.drag_rate_per_s, b = unit.drag_per_m;
  const double decay = std::exp(-a * dt_s);
  const double e = decayIntegral(a, dt_s);
  if (b == 0.0) {
    return {unit.v_mps * e + unit.a_mps2 * decaySecondIntegral(a, dt_s),
            unit.v_mps * decay + unit.a_mps2 * e};
  }
  // Quadratic drag (no gravity): the velocity keeps its direction, the speed falls.
  const double speed = unit.v_mps.norm();
  if (speed == 0.0) return {{0.0, 0.0}, {0.0, 0.0}};
  const double growth = b * speed * e;
  return {unit.v_mps * (std::log1p(growth) / (b * speed)), unit.v_mps * (decay / (1.0 + growth))};
}

}  // namespace

bool hasDrag(const UnitState& unit) {
  return unit.drag_rate_per_s > 0.0 || unit.drag_per_m > 0.0;
}

DragState dragMotion(const UnitState& unit, double dt_s) {
  DragState out = dragStep(unit, dt_s);
  out.position_m += unit.x_ref_m;
  return out;
}

core::Vec2 dragAcceleration(const UnitState& unit, const core::Vec2& v_mps) {
  return unit.a_mps2 - unit.drag_rate_per_s * v_mps - unit.drag_per_m * v_mps.norm() * v_mps;
}

core::Vec2 terminalVelocity(const UnitState& unit) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  core::Vec2 out;
  for (int k = 0; k < 2; ++k) {
    const double g = unit.a_mps2[k];
    if (unit.drag_rate_per_s > 0.0) {
      out[k] = g / unit.drag_rate_per_s;
    } else if (g != 0.0) {
      out[k] = std::copysign(kInfinity, g);
    } else {
      out[k] = unit.drag_per_m > 0.0 ? 0.0 : unit.v_mps[k];
    }
  }
  return out;
}

double dragWork(const UnitState& unit, double dt_s) {
  const double a = unit.drag_rate_per_s, b = unit.drag_per_m;
  const DragState step = dragStep(unit, dt_s);
  const double e = decayIntegral(a, dt_s);
  core::Vec2 slowing;  // v0 - v, in closed form
  if (b == 0.0) {
    slowing = (a * unit.v_mps - unit.a_mps2) * e;
  } else {
    const double speed = unit.v_mps.norm();
    slowing = unit.v_mps * (e * (a + b * speed) / (1.0 + b * speed * e));
  }
  const double kinetic = 0.5 * unit.mass_kg * slowing.dot(unit.v_mps + step.velocity_mps);
  return kinetic + unit.mass_kg * unit.a_mps2.dot(step.position_m);
}

}  // namespace collide::physics::detail
