#include "physics/timeline.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace collide::physics {

Timeline::Timeline(WorldDef world, std::vector<Snapshot> keyframes,
                   std::vector<CollisionEvent> collisions)
    : world_(std::move(world)), keyframes_(std::move(keyframes)), collisions_(std::move(collisions)) {
  COLLIDE_ASSERT(!keyframes_.empty() && keyframes_.front().time_s == 0.0,
                 "a timeline starts with a keyframe at t = 0");
}

Snapshot Timeline::sample(double t_s) const {
  const double t = std::clamp(t_s, 0.0, world_.duration_s);
  // Last keyframe at or before t: the state right after the latest event up to t.
  auto after = std::upper_bound(keyframes_.begin(), keyframes_.end(), t,
                                [](double time, const Snapshot& k) { return time < k.time_s; });
  const Snapshot& base = *std::prev(after);
  Snapshot result = base;
  result.time_s = t;
  const double dt = t - base.time_s;
  for (BodyState& body : result.bodies) {
    body.position_m += body.velocity_mps * dt + 0.5 * world_.gravity_mps2 * dt * dt;
    body.velocity_mps += world_.gravity_mps2 * dt;
  }
  return result;
}

double Timeline::kineticEnergy(const Snapshot& snapshot) const {
  double energy = 0.0;
  for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
    energy += 0.5 * world_.bodies[i].mass_kg * snapshot.bodies[i].velocity_mps.squaredNorm();
  }
  return energy;
}

core::Vec2 Timeline::momentum(const Snapshot& snapshot) const {
  core::Vec2 total = core::Vec2::Zero();
  for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
    total += world_.bodies[i].mass_kg * snapshot.bodies[i].velocity_mps;
  }
  return total;
}

double Timeline::initialKineticEnergy() const { return kineticEnergy(keyframes_.front()); }

}  // namespace collide::physics
