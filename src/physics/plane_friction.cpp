// SPDX-License-Identifier: MIT
// Sliding friction on a table: the 2D engine's law of motion with friction, its stops and the
// time of impact of a slowing disk with a wall. See plane_engine.hpp and docs/physics.md
// ("Sliding friction").
//
// A unit slides with kinetic friction against its velocity, a = -k v / |v| (k = mu_k g_n,
// mass-weighted over its bodies). The acceleration is constant and along the velocity, so the
// unit moves on a straight line, quadratically in time, until v reaches 0 at t_ref + |v| / k: a
// stop, an event. The table is level (no gravity in the plane, scene/reader_friction.cpp), so
// static friction then holds it at rest. Between events every gap is a polynomial in time: a
// quadratic against a wall, a quartic between two disks slowing along different directions
// (plane_toi.cpp). Friction's work m k |dx| and impulse m a dt are booked per piece of motion,
// never as a difference of kinetic energies.
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "physics/plane_engine.hpp"
#include "physics/rolling_law.hpp"
#include "physics/toi.hpp"

namespace collide::physics::detail {
namespace {

constexpr double kStopRoundOff = std::numeric_limits<double>::epsilon();

core::Vec2 frictionArm(const core::Vec2& v, double angle_rad) {
  if (angle_rad == 0.0) return v;
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

bool vanishes(const core::Vec2& v) {
  return v.x() == 0.0 && v.y() == 0.0;
}

double frictionCross(const core::Vec2& a, const core::Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace

void PlaneEngine::setFrictionLaw(int id) {
  UnitState& u = state_.units[id];
  const WorldDef& world = model_.world;
  if (world.rolling) {
    setRollingLaw(u, clothOf(world, members_[id].front()));
    if (u.resting_walls != 0) pressed_ball_ = id;
    return;
  }
  // Sum of mu_i m_i, and of mu_i m_i r_i (r_i from the centre of mass): friction's resultant on
  // a sliding cluster that does not spin acts through the point sum / weight.
  double weight_kg = 0.0, spread_kgm = 0.0;
  core::Vec2 moment_kgm = core::Vec2::Zero();
  for (int body : members_[id]) {
    const BodyDef& def = world.bodies[body];
    weight_kg += def.friction * def.mass_kg;
    const core::Vec2 arm = frictionArm(state_.bodies[body].offset_m, u.angle_ref_rad);
    moment_kgm += def.friction * def.mass_kg * arm;
    spread_kgm += def.friction * def.mass_kg * arm.norm();
  }
  // A single disk's as initialState() sets it (mu g_n, not mu m g_n / m, which rounds apart).
  const int first = members_[id].front();
  kinetic_decel_[id] = members_[id].size() == 1
                           ? world.bodies[first].friction * world.surface_gravity_mps2
                           : weight_kg * world.surface_gravity_mps2 / u.mass_kg;
  u.friction_mps2 = frictionInPlane(u.v_mps, kinetic_decel_[id]);
  u.a_mps2 = world.gravity_mps2 + u.friction_mps2;
  if (members_[id].size() < 2 || weight_kg == 0.0) return;
  // A stuck cluster turns under friction when it spins, or when friction's resultant misses its
  // centre of mass (a torque): then its disks' velocities, and so their friction, change
  // direction continuously, a motion with no closed form.
  const double torque = std::abs(frictionCross(moment_kgm, u.v_mps));
  const bool spinning = u.omega_radps != 0.0;
  if (spinning || torque > 16.0 * kStopRoundOff * spread_kgm * u.v_mps.norm())
    turning_cluster_ = id;
}

double PlaneEngine::stopTime(int id) const {
  const UnitState& u = state_.units[id];
  if (!u.alive) return kNever;
  if (model_.world.rolling) return phaseEnd(u, clothOf(model_.world, members_[id].front()));
  if (vanishes(u.friction_mps2)) return kNever;
  return u.t_ref_s + u.v_mps.norm() / kinetic_decel_[id];
}

void PlaneEngine::pushStop(int id) {
  const double t = stopTime(id);
  if (t < kNever && !members_[id].empty()) push(kStop, members_[id].front(), 0, t);
}

void PlaneEngine::bookSurface(UnitState& u, double t) {
  if (model_.world.rolling) {
    advanceRolling(u, t, state_);
    return;
  }
  const double dt = t - u.t_ref_s;
  if (vanishes(u.friction_mps2) || dt == 0.0) return;
  const core::Vec2 step = u.v_mps * dt + 0.5 * u.a_mps2 * dt * dt;
  state_.energy_to_surface.add(-u.mass_kg * u.friction_mps2.dot(step));
  state_.friction_impulse_x.add(u.mass_kg * u.friction_mps2.x() * dt);
  state_.friction_impulse_y.add(u.mass_kg * u.friction_mps2.y() * dt);
}

void PlaneEngine::stopUnit(int id, double t) {
  UnitState& u = state_.units[id];
  if (model_.world.rolling) {
    // A ball's phase ends: it rolls, or it rests. Not renew(), which would make it slide.
    endPhase(u, clothOf(model_.world, members_[id].front()), t, state_);
    ++state_.string_events;
    version_[id] = ++last_stamp_;
    setFrictionLaw(id);
    predictUnit(id, -1);
    return;
  }
  const double speed = u.v_mps.norm();
  // The distance to rest in closed form, |v|^2 / (2k) along v: the same to rounding as the
  // position at t. Friction took all the kinetic energy and all the momentum the unit had.
  state_.energy_to_surface.add(0.5 * u.mass_kg * speed * speed);
  state_.friction_impulse_x.add(-u.mass_kg * u.v_mps.x());
  state_.friction_impulse_y.add(-u.mass_kg * u.v_mps.y());
  u.x_ref_m += (0.5 * speed / kinetic_decel_[id]) * u.v_mps;
  u.angle_ref_rad += u.omega_radps * (t - u.t_ref_s);
  u.v_mps.setZero();
  u.t_ref_s = t;
  ++state_.string_events;  // an event, no collision: sampling replays across it
  renew(id);
  predictUnit(id, -1);
}

bool PlaneEngine::stopDue(double t_end_s) {
  Event next;
  return nextEvent(next) && next.kind == kStop && next.time_s <= t_end_s;
}

double PlaneEngine::slowingWallTime(int id, double s0, double s1, double s2, double t0) const {
  const double tau_stop = stopTime(id) - t0;
  if (model_.world.rolling && !state_.units[id].rolls) {
    // A sliding ball's path is a parabola, which may bend towards the wall: the first root
    // before its slip ends.
    const double root = firstClosingRoot(s0, s1, s2);
    return root <= tau_stop ? root : kNever;
  }
  // Moving away from the wall or along it: friction slows that motion, never turns it round.
  if (!(s1 < 0.0)) return kNever;
  if (s0 <= 0.0) return 0.0;  // touching and approaching
  // Approaching and slowing (s2 >= 0): the smaller root, if the unit gets there before it stops.
  const double root = firstClosingRoot(s0, s1, s2);
  return root <= tau_stop ? root : kNever;
}

bool PlaneEngine::frictionStalls(double t) {
  const WorldDef& world = model_.world;
  if (pressed_ball_ >= 0) {
    char text[500];
    std::snprintf(text, sizeof text,
                  "stopped at t = %.9g s after %lld collisions because ball \"%s\" came to rest "
                  "against a cushion that its spin on the cloth presses it onto, a lasting contact "
                  "that the event-driven model does not follow; later states are not simulated "
                  "(cushions with a higher restitution avoid it)",
                  t, static_cast<long long>(state_.collision_count),
                  world.bodies[members_[pressed_ball_].front()].name.c_str());
    out_.warn({WarningKind::kStalled, state_.collision_count - 1, t, text});
    return true;
  }
  if (turning_cluster_ < 0) return false;
  const std::vector<int>& bodies = members_[turning_cluster_];
  char text[600];
  std::snprintf(text, sizeof text,
                "stopped at t = %.9g s after %lld collisions because the stuck cluster of disk "
                "\"%s\" and %d more would turn as it slides with friction (it spins, or its "
                "disks' friction pulls off its centre of mass), a motion with no closed form that "
                "the event-driven model does not follow; later states are not simulated "
                "(inelastic = \"slip\" avoids it)",
                t, static_cast<long long>(state_.collision_count),
                world.bodies[bodies[0]].name.c_str(), static_cast<int>(bodies.size()) - 1);
  out_.warn({WarningKind::kStalled, state_.collision_count - 1, t, text});
  return true;
}

}  // namespace collide::physics::detail
