#pragma once
// Internal: how a unit hangs. A unit on a taut string follows the exact pendulum solution from
// its reference state (physics/pendulum_motion.hpp); a unit whose string is slack, or that has
// none, follows the parabola kept in its UnitState. Kept beside the engine state (one entry per
// unit) only in worlds with strings.
#include <cstdint>

#include "core/vec.hpp"
#include "physics/pendulum_motion.hpp"

namespace collide::physics::detail {

struct SwingState {
  bool has_string = false;          // the unit hangs from pivot_m (taut or slack)
  bool taut = false;                // the string is taut: the pendulum below gives the motion
  core::Vec2 pivot_m = {0.0, 0.0};  // fixed point the string hangs from
  double length_m = 0.0;            // from the pivot to the unit's centre of mass, > 0
  double t_ref_s = 0.0;             // time at which `start` holds
  PendulumState start;              // angle from straight down and its rate at t_ref_s
  // The unit is bodies on strings of one length swinging in step, touching (a contact that
  // persists): it parts into them when one is struck. A unit of several bodies that is no group
  // stuck together at e = 0 and never parts.
  bool group = false;
};

// Centre-of-mass position and velocity of a unit on a taut string at t_s (gravity g along -y).
struct SwingKinematics {
  core::Vec2 position_m, velocity_mps;
};
SwingKinematics swingAt(const SwingState& swing, double gravity_m_s2, double t_s);

}  // namespace collide::physics::detail
