#pragma once
// Internal: a unit's exact motion under air drag, in closed form (docs/physics.md, "Air drag").
//
// A unit with linear drag rate a = k/m (1/s) and quadratic drag b = c/m (1/m) obeys
// dv/dt = g - a v - b |v| v, g the gravity in its a_mps2. The engines allow the quadratic part
// only without gravity (so v keeps its direction); with E(tau) = (1 - e^(-a tau)) / a (tau when
// a = 0) the motion from x0, v0 at t_ref is
//   b = 0 (linear drag, gravity):  v = v0 e^(-a tau) + g E,  x = x0 + v0 E + g F,
//                                   F = (tau - E) / a (tau^2 / 2 when a = 0);
//   g = 0 (both parts):            v = v0 e^(-a tau) / (1 + b |v0| E),
//                                   x = x0 + v0/|v0| ln(1 + b |v0| E) / b.
// Each is written so that no term cancels another at small a tau (expm1, log1p, a series for F).
// The drag's work (what went to the air) over a piece of motion is 1/2 m (v0 - v).(v0 + v) +
// m g.(x - x0), with v0 - v in a closed form free of cancellation.
#include "core/vec.hpp"

namespace collide::physics::detail {

struct UnitState;

struct DragState {
  core::Vec2 position_m;
  core::Vec2 velocity_mps;
};

// Whether the unit moves under drag (else its motion is the plain parabola).
bool hasDrag(const UnitState& unit);
// Position and velocity dt_s after the unit's reference instant.
DragState dragMotion(const UnitState& unit, double dt_s);
// The acceleration at velocity v_mps: gravity less the drag.
core::Vec2 dragAcceleration(const UnitState& unit, const core::Vec2& v_mps);
// The velocity the unit tends to (gravity's terminal velocity g / a; 0 without gravity),
// component by component; a component of gravity with no linear drag to balance it tends to
// +-infinity.
core::Vec2 terminalVelocity(const UnitState& unit);
// The drag's work over [t_ref, t_ref + dt_s], J (>= 0): what went to the air.
double dragWork(const UnitState& unit, double dt_s);

}  // namespace collide::physics::detail
