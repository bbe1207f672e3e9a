#pragma once
// The result of a simulation: piecewise-analytic trajectories that can be sampled exactly at any
// time, and the ordered log of collisions.
#include <cstddef>
#include <vector>

#include "core/vec.hpp"
#include "physics/world.hpp"

namespace collide::physics {

struct BodyState {
  core::Vec2 position_m = {0.0, 0.0};
  core::Vec2 velocity_mps = {0.0, 0.0};
};

// Partner index used in CollisionEvent::body_b for wall k: kWallPartnerBase - k (always negative).
inline constexpr int kWallPartnerBase = -1;

struct CollisionEvent {
  double time_s = 0.0;
  int body_a = 0;                           // index into WorldDef::bodies
  int body_b = 0;                           // body index, or kWallPartnerBase - wall index
  double restitution = 1.0;                 // e applied at this impact
  core::Vec2 normal = {1.0, 0.0};           // unit contact normal, from a towards b
  core::Vec2 velocity_a_before_mps, velocity_a_after_mps;
  core::Vec2 velocity_b_before_mps, velocity_b_after_mps;  // zero for walls
  double closing_speed_mps = 0.0;           // normal approach speed before impact, >= 0
  double energy_lost_J = 0.0;               // measured: KE before - KE after
  double energy_lost_analytic_J = 0.0;      // 1/2 mu (1 - e^2) u_n^2 (walls: mu = m)
};

// State of every body at one instant.
struct Snapshot {
  double time_s = 0.0;
  std::vector<BodyState> bodies;
  double energy_lost_J = 0.0;               // kinetic energy lost in collisions up to time_s
  int collision_count = 0;                  // collisions at or before time_s
};

class Timeline {
 public:
  Timeline(WorldDef world, std::vector<Snapshot> keyframes, std::vector<CollisionEvent> collisions);

  const WorldDef& world() const { return world_; }
  double duration_s() const { return world_.duration_s; }
  const std::vector<CollisionEvent>& collisions() const { return collisions_; }

  // Exact state at time t (clamped to [0, duration]): the latest keyframe at or before t advanced
  // analytically under gravity. A time equal to a collision time gives the state after it.
  Snapshot sample(double t_s) const;

  double kineticEnergy(const Snapshot& snapshot) const;   // J
  core::Vec2 momentum(const Snapshot& snapshot) const;    // kg m/s
  double initialKineticEnergy() const;                    // J

 private:
  WorldDef world_;
  std::vector<Snapshot> keyframes_;  // state right after each event, keyframes_[0] at t = 0
  std::vector<CollisionEvent> collisions_;
};

}  // namespace collide::physics
