// SPDX-License-Identifier: MIT
// Rolling balls on a cloth: one ball's law of motion between events (rolling_law.hpp).
//
// A ball of radius R is a solid sphere, I = 2/5 m R^2, carrying a spin (omega_x, omega_y) about
// the table's axes (the spin about the vertical is not followed). Its contact point moves at the
// slip u = v + omega x (-R z) = (v_x - R omega_y, v_y + R omega_x). While u != 0 the ball slides:
// the cloth pushes with mu m g_n against u, so dv/dt = -mu g_n u/|u| and the torque R z x F turns
// the spin by (5 / (2R)) (a_y, -a_x); u then changes by 7/2 of the acceleration, along itself, so
// it keeps its direction and shrinks linearly to zero at t = 2|u0| / (7 mu g_n). The acceleration
// is constant: the path is a parabola, and the ball leaves it rolling at v0 - (2/7) u0. Rolling,
// the ball slows by rolling resistance, mu_r g_n against v, on a straight line to a stop. The
// cloth's work is mu m g_n |u| while sliding (the power at the slipping contact) and, rolling,
// the fall of the rolling ball's kinetic energy 7/10 m v^2: 7/5 mu_r m g_n |v|. Both are linear
// in time within a phase, so each piece of motion books them in closed form.
#include <cmath>

#include "physics/rolling_law.hpp"
#include "physics/toi.hpp"

namespace collide::physics::detail {
namespace {

// The contact point's velocity changes by 1 + m R^2 / I = 7/2 times the centre's under a force
// at the contact point; the spin by 5 / (2R) times the centre's acceleration.
constexpr double kSlipGain = 3.5;
constexpr double kSpinGain = 2.5;
// The kinetic energy of a rolling ball over that of its translation: 1 + I / (m R^2).
constexpr double kRollingEnergy = 1.4;

// The spin of a ball rolling at v: its contact point at rest.
core::Vec2 rollingSpin(const core::Vec2& v, double radius_m) {
  return {-v.y() / radius_m, v.x() / radius_m};
}

void setRolling(UnitState& ball, const Cloth& cloth) {
  ball.rolls = true;
  ball.friction_mps2 = frictionInPlane(ball.v_mps, cloth.roll_mps2);
  const core::Vec2& a = ball.friction_mps2;
  ball.spin_rate_radps2 = rollingSpin(a, cloth.radius_m);
  ball.cloth_power_Wpkg = kRollingEnergy * cloth.roll_mps2 * ball.v_mps.norm();
  ball.cloth_power_rate_Wpkgps = -kRollingEnergy * cloth.roll_mps2 * cloth.roll_mps2;
  if (a.x() == 0.0 && a.y() == 0.0) ball.cloth_power_rate_Wpkgps = 0.0;
}

}  // namespace

Cloth clothOf(const WorldDef& world, int body) {
  const BodyDef& def = world.bodies[body];
  return {def.size_m, def.friction * world.surface_gravity_mps2,
          def.rolling_friction * world.surface_gravity_mps2};
}

core::Vec2 slipOf(const UnitState& ball, double radius_m) {
  return {ball.v_mps.x() - radius_m * ball.spin_radps.y(),
          ball.v_mps.y() + radius_m * ball.spin_radps.x()};
}

void setRollingLaw(UnitState& ball, const Cloth& cloth) {
  const core::Vec2 slip = slipOf(ball, cloth.radius_m);
  const double slip_mps = slip.norm();
  if (ball.rolls || slip_mps == 0.0) {
    setRolling(ball, cloth);
  } else {
    ball.friction_mps2 = frictionInPlane(slip, cloth.slide_mps2);
    const core::Vec2& a = ball.friction_mps2;
    ball.spin_rate_radps2 = (kSpinGain / cloth.radius_m) * core::Vec2(a.y(), -a.x());
    ball.cloth_power_Wpkg = cloth.slide_mps2 * slip_mps;
    ball.cloth_power_rate_Wpkgps = -kSlipGain * cloth.slide_mps2 * cloth.slide_mps2;
  }
  ball.a_mps2 = ball.friction_mps2;
}

double phaseEnd(const UnitState& ball, const Cloth& cloth) {
  if (!ball.alive || (ball.friction_mps2.x() == 0.0 && ball.friction_mps2.y() == 0.0)) {
    return kNever;
  }
  if (ball.rolls) return ball.t_ref_s + ball.v_mps.norm() / cloth.roll_mps2;
  return ball.t_ref_s + slipOf(ball, cloth.radius_m).norm() / (kSlipGain * cloth.slide_mps2);
}

void endPhase(UnitState& ball, const Cloth& cloth, double t, EngineState& state) {
  const double m = ball.mass_kg;
  core::Vec2 impulse;
  if (ball.rolls) {
    // To rest, |v|^2 / (2 mu_r g_n) further on: the cloth took the rolling ball's kinetic energy
    // and all its momentum.
    const double speed = ball.v_mps.norm();
    state.energy_to_surface.add(0.5 * kRollingEnergy * m * speed * speed);
    impulse = -m * ball.v_mps;
    ball.x_ref_m += (0.5 * speed / cloth.roll_mps2) * ball.v_mps;
    ball.v_mps.setZero();
  } else {
    // The slip ends after |u0| / (7/2 mu g_n): the cloth took m |u0|^2 / 7 (the energy of the
    // slip's effective mass 2/7 m) and the impulse -(2/7) m u0.
    const core::Vec2 slip = slipOf(ball, cloth.radius_m);
    const double tau = slip.norm() / (kSlipGain * cloth.slide_mps2);
    state.energy_to_surface.add(m * slip.squaredNorm() / 7.0);
    impulse = (-2.0 / 7.0) * m * slip;
    ball.x_ref_m += ball.v_mps * tau + 0.5 * ball.a_mps2 * tau * tau;
    ball.v_mps -= (2.0 / 7.0) * slip;
  }
  state.friction_impulse_x.add(impulse.x());
  state.friction_impulse_y.add(impulse.y());
  ball.spin_radps = rollingSpin(ball.v_mps, cloth.radius_m);
  ball.rolls = true;
  ball.t_ref_s = t;
}

double clothWork(const UnitState& ball, double dt) {
  return ball.mass_kg * (ball.cloth_power_Wpkg + 0.5 * ball.cloth_power_rate_Wpkgps * dt) * dt;
}

void advanceRolling(UnitState& ball, double t, EngineState& state) {
  const double dt = t - ball.t_ref_s;
  if (dt == 0.0) return;
  state.energy_to_surface.add(clothWork(ball, dt));
  state.friction_impulse_x.add(ball.mass_kg * ball.friction_mps2.x() * dt);
  state.friction_impulse_y.add(ball.mass_kg * ball.friction_mps2.y() * dt);
  ball.spin_radps += ball.spin_rate_radps2 * dt;
}

}  // namespace collide::physics::detail
