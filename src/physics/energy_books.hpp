#pragma once
// The energy books at one instant: where the mechanical energy of the start, and the stored energy
// released since (releases, super-elastic impacts), is now. Kinetic energy per body, potential
// energy of gravity, the energy stored in each soft contact's spring while it is compressed, and
// the energy lost so far. They add up to the energy at the start plus what was released at every
// instant, also in the middle of a soft contact, whose damping loss accrues as the contact goes
// on (the Timeline's snapshot books a contact's whole loss at its start).
#include <vector>

#include "core/vec.hpp"
#include "physics/timeline.hpp"

namespace collide::physics {

struct SpringEnergy {
  std::int64_t collision_index = 0;  // the soft contact's CollisionEvent::index
  int body_a = 0, body_b = 0;        // as in CollisionEvent (b < 0: a wall)
  double overlap_m = 0.0;            // compression, >= 0
  double energy_J = 0.0;             // k s^(n+1) / (n+1), >= 0
};

struct EnergyBooks {
  double time_s = 0.0;
  std::vector<double> kinetic_J;      // per body, translation and disk spin, in the given frame
  double gravity_J = 0.0;             // potential energy of gravity above the given floor
  std::vector<SpringEnergy> springs;  // soft contacts compressed at time_s
  double lost_J = 0.0;                // turned into heat and deformation up to time_s
  double surface_J = 0.0;             // sliding friction's work up to time_s: to the surface
  double air_J = 0.0;                 // air drag's work up to time_s: to the air
  // Stored energy turned into motion up to time_s: not a part of total_J() but what it grows
  // by (total_J() = the energy at the start + released_J).
  double released_J = 0.0;
  // Molecules with insides (WorldDef::internal_dof > 0): the disks' internal energy, a part of
  // total_J(); 0 elsewhere.
  double internal_J = 0.0;

  double kineticTotal_J() const;
  double springTotal_J() const;
  double total_J() const;  // all the parts: the energy at the start + released_J, at any instant
};

// Kinetic energy of one body, J, seen from a frame moving at frame_velocity: its centre's, and
// its spin's where it spins (a disk turning with a stuck cluster, I = m r^2 / 2; a ball rolling
// on a cloth, about the table's axes, I = 2/5 m r^2).
double bodyKineticEnergy_J(const BodyDef& def, const BodyState& state,
                           const core::Vec2& frame_velocity);

// The books at t_s for the bodies seen from a frame moving at frame_velocity_mps (the
// centre-of-momentum frame of a free system keeps its losses; zero: the lab frame). Gravity's
// potential energy is counted from gravity_floor_J (e.g. its lowest value over the run), so the
// bar shows what can still turn into motion.
EnergyBooks energyBooks(const Timeline& timeline, double t_s,
                        const core::Vec2& frame_velocity_mps = {0.0, 0.0},
                        double gravity_floor_J = 0.0);

}  // namespace collide::physics
