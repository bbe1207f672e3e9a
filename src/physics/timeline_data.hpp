#pragma once
// Internal: what a Timeline holds. Checkpoints (keyframes) are full engine states taken after
// every `stride` collisions; the stride doubles whenever the keyframes outgrow their memory budget.
#include <cstdint>
#include <vector>

#include "physics/engine.hpp"
#include "physics/sample_cursors.hpp"

namespace collide::physics::detail {

struct TimelineData {
  explicit TimelineData(const WorldDef& world) : model(world) {}

  Model model;
  std::vector<EngineState> keyframes;  // [0] is the initial state; counts increase
  std::vector<CollisionEvent> events;  // the first max_recorded_collisions
  std::vector<SoftContact> soft_contacts;
  std::vector<Warning> warnings;
  std::int64_t collision_count = 0;
  std::int64_t string_event_count = 0;  // see EngineState::string_events
  double energy_lost_J = 0.0;           // booked, see EngineState::energy_lost
  double energy_released_J = 0.0;       // booked, see EngineState::energy_released
  double energy_to_surface_J = 0.0;     // booked, see EngineState::energy_to_surface
  double energy_to_air_J = 0.0;         // booked, see EngineState::energy_to_air
  double energy_lost_measured_J = 0.0;  // mechanical energy at t = 0 less at the end
  double energy_tolerance_J = 0.0;      // round-off allowed between the two
  SimulationStatus status = SimulationStatus::kComplete;
  double simulated_until_s = 0.0;
  // Engines kept between samples; last, so that they go before the model they point into.
  mutable SampleCursors cursors;
};

}  // namespace collide::physics::detail
