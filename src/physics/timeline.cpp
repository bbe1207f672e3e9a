#include "physics/timeline.hpp"

#include <algorithm>
#include <limits>

#include "core/error.hpp"
#include "physics/timeline_data.hpp"

namespace collide::physics {

Timeline::Timeline(std::shared_ptr<const detail::TimelineData> data) : data_(std::move(data)) {
  COLLIDE_ASSERT(data_ && !data_->keyframes.empty(), "a timeline starts with a keyframe at t = 0");
}

const WorldDef& Timeline::world() const {
  return data_->model.world;
}
const std::vector<CollisionEvent>& Timeline::collisions() const {
  return data_->events;
}
std::int64_t Timeline::collisionCount() const {
  return data_->collision_count;
}
SimulationStatus Timeline::status() const {
  return data_->status;
}
double Timeline::simulatedUntil_s() const {
  return data_->simulated_until_s;
}
const std::vector<Warning>& Timeline::warnings() const {
  return data_->warnings;
}
const std::vector<SoftContact>& Timeline::softContacts() const {
  return data_->soft_contacts;
}
double Timeline::totalEnergyLost() const {
  return data_->energy_lost_J;
}
double Timeline::totalEnergyReleased() const {
  return data_->energy_released_J;
}

double Timeline::totalEnergyToSurface() const {
  return data_->energy_to_surface_J;
}

double Timeline::totalEnergyToAir() const {
  return data_->energy_to_air_J;
}

double Timeline::energyLostMeasured() const {
  return data_->energy_lost_measured_J;
}
double Timeline::energyLedgerTolerance() const {
  return data_->energy_tolerance_J;
}

void Timeline::replayCollisions(const std::function<void(const CollisionEvent&)>& visit) const {
  detail::Recorder recorder;
  recorder.stream = &visit;
  auto engine = detail::makeEngine(data_->model, data_->keyframes.front(), recorder);
  engine->run(world().duration_s, data_->collision_count);
}

void Timeline::replayEvents(const std::function<void(const CollisionEvent&)>& visit,
                            const std::function<void(const StringEvent&)>& visit_string) const {
  detail::Recorder recorder;
  recorder.stream = &visit;
  recorder.string_stream = &visit_string;
  auto engine = detail::makeEngine(data_->model, data_->keyframes.front(), recorder);
  // Past the last collision too: string events after it are part of the run (the engines stop
  // before the next collision at the count limit, not before a string event).
  engine->run(data_->simulated_until_s, data_->collision_count);
}

Snapshot Timeline::sample(double t_s) const {
  // simulatedUntil_s() is the duration unless the run stopped early; see the header.
  const double t = std::clamp(t_s, 0.0, data_->simulated_until_s);
  const auto& keyframes = data_->keyframes;
  // The last checkpoint at or before t.
  auto after =
      std::upper_bound(keyframes.begin(), keyframes.end(), t,
                       [](double time, const detail::EngineState& k) { return time < k.time_s; });
  const std::size_t k = std::max<std::ptrdiff_t>(after - keyframes.begin(), 1) - 1;
  const detail::EngineState& base = keyframes[k];
  // No event between this checkpoint and t: evaluate directly; otherwise replay up to t.
  // (A string going slack or taut between them is an event too.)
  const bool next_is_single_event =
      k + 1 < keyframes.size() ? keyframes[k + 1].collision_count == base.collision_count + 1 &&
                                     keyframes[k + 1].string_events == base.string_events
                               : base.collision_count == data_->collision_count &&
                                     base.string_events == data_->string_event_count;
  if (next_is_single_event) return detail::evaluate(data_->model, base, t);
  return data_->cursors.replayTo(*data_, k, t);
}

double Timeline::kineticEnergy(const Snapshot& snapshot) const {
  double energy = 0.0;
  for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
    const BodyState& body = snapshot.bodies[i];
    energy += 0.5 * world().bodies[i].mass_kg * body.velocity_mps.squaredNorm() +
              0.5 * data_->model.spin_inertia_kgm2[i] * body.angular_velocity_radps *
                  body.angular_velocity_radps +
              0.5 * data_->model.ball_inertia_kgm2[i] * body.spin_radps.squaredNorm();
  }
  return energy;
}

double Timeline::potentialEnergy(const Snapshot& snapshot) const {
  double energy = 0.0;
  for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
    energy -= world().bodies[i].mass_kg * world().gravity_mps2.dot(snapshot.bodies[i].position_m);
  }
  return energy;
}

core::Vec2 Timeline::momentum(const Snapshot& snapshot) const {
  core::Vec2 total = core::Vec2::Zero();
  for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
    total += world().bodies[i].mass_kg * snapshot.bodies[i].velocity_mps;
  }
  return total;
}

double Timeline::angularMomentum(const Snapshot& snapshot, core::Vec2 about_m) const {
  double total = 0.0;
  for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
    const BodyState& body = snapshot.bodies[i];
    const core::Vec2 r = body.position_m - about_m;
    const double m = world().bodies[i].mass_kg;
    total += m * (r.x() * body.velocity_mps.y() - r.y() * body.velocity_mps.x()) +
             data_->model.spin_inertia_kgm2[i] * body.angular_velocity_radps;
  }
  return total;
}

Snapshot Timeline::initialState() const {
  return detail::evaluate(data_->model, data_->keyframes.front(), 0.0);
}

double Timeline::initialKineticEnergy() const {
  return kineticEnergy(initialState());
}

}  // namespace collide::physics
