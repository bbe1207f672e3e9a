// SPDX-License-Identifier: MIT
#pragma once
// Rolling balls on a cloth (WorldDef::rolling): the law of motion of one ball between events, the
// motion model of Leckie and Greenspan, "An event-based pool physics simulator" (Advances in
// Computer Games, 2006). See plane_rolling.cpp and docs/physics.md ("Rolling balls").
#include "physics/engine.hpp"

namespace collide::physics::detail {

// The cloth under one ball: the ball's radius, sliding friction's deceleration mu g_n and rolling
// resistance's mu_r g_n.
struct Cloth {
  double radius_m = 0.0;
  double slide_mps2 = 0.0;
  double roll_mps2 = 0.0;
};

Cloth clothOf(const WorldDef& world, int body);

// The velocity of the ball's contact point with the cloth at t_ref: v + omega x (-R z).
core::Vec2 slipOf(const UnitState& ball, double radius_m);

// Sets a ball's acceleration, spin rate and the cloth's power from its velocity and spin: sliding
// while its contact point slips (u != 0), rolling once the phase event says it rolls.
void setRollingLaw(UnitState& ball, const Cloth& cloth);

// When the ball's phase ends: its slip stops (sliding) or it comes to rest (rolling); kNever where
// it never does.
double phaseEnd(const UnitState& ball, const Cloth& cloth);

// Ends the ball's phase at t, in closed form: the sliding ball rolls at v - (2/7) u, the rolling
// ball rests. Books what the cloth took into `state`.
void endPhase(UnitState& ball, const Cloth& cloth, double t, EngineState& state);

// Books the piece of motion from t_ref to t (the cloth's work and impulse) and turns the spin to
// t; the engine moves the centre. The ball leaves the phase's law (an impact follows).
void advanceRolling(UnitState& ball, double t, EngineState& state);

// The cloth's work on a ball from t_ref to t_ref + dt, J (the piece in progress).
double clothWork(const UnitState& ball, double dt);

}  // namespace collide::physics::detail
