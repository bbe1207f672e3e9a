#include "physics/simulate.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "core/stop_request.hpp"
#include "physics/engine.hpp"
#include "physics/timeline_data.hpp"

namespace collide::physics {
namespace {

std::size_t keyframeBytes(const detail::EngineState& state) {
  return sizeof(detail::EngineState) + state.units.size() * sizeof(detail::UnitState) +
         state.bodies.size() * (sizeof(detail::BodyLink) + sizeof(double));
}

std::string describeStop(const char* what, std::int64_t count, double t_s) {
  char text[200];
  std::snprintf(text, sizeof text,
                "%s after %lld collisions at t = %.9g s; later states are not "
                "simulated",
                what, static_cast<long long>(count), t_s);
  return text;
}

constexpr std::size_t kMaxKeyframes = 8192;

}  // namespace

Timeline simulate(const WorldDef& world) {
  auto data = std::make_shared<detail::TimelineData>(world);
  const detail::Model& model = data->model;
  detail::Recorder recorder;
  recorder.events = &data->events;
  recorder.event_limit = world.max_recorded_collisions;
  recorder.soft_contacts = &data->soft_contacts;
  recorder.warnings = &data->warnings;

  data->keyframes.push_back(detail::initialState(model));
  const std::size_t budget =
      static_cast<std::size_t>(std::max<std::int64_t>(world.max_keyframe_bytes, 0));
  // Enough checkpoints that a sample replays at most (collisions / 4096) events, few enough that
  // taking them costs little next to the simulation itself.
  const std::size_t max_keyframes =
      std::clamp<std::size_t>(budget / keyframeBytes(data->keyframes.front()), 64, kMaxKeyframes);
  std::unique_ptr<detail::Engine> engine =
      detail::makeEngine(model, data->keyframes.front(), recorder);
  std::int64_t stride = 1;
  detail::RunStop stop;
  for (;;) {
    // The only stop check in physics: a stop request (Ctrl-C, see core/stop_request.hpp) ends a
    // long run (31 million collisions for pi-blocks digits=8) by throwing core::StopRequested.
    // Checked once per checkpoint stride (1 collision at first, later the collisions so far over
    // the 64 to 8192 checkpoints kept: ~4,000 for pi-blocks digits=8), so it costs nothing and
    // answers within milliseconds.
    core::throwIfStopRequested();
    const std::int64_t count = engine->state().collision_count;
    stop = engine->run(world.duration_s, (count / stride + 1) * stride);
    if (stop != detail::RunStop::kCountLimit) break;
    data->keyframes.push_back(engine->state());
    if (data->keyframes.size() > max_keyframes) {
      // Keep every other checkpoint: those at multiples of the doubled stride.
      stride *= 2;
      std::vector<detail::EngineState> kept;
      for (detail::EngineState& k : data->keyframes) {
        if (k.collision_count % stride == 0) kept.push_back(std::move(k));
      }
      data->keyframes = std::move(kept);
    }
  }
  const detail::EngineState& last = engine->state();
  if (last.collision_count != data->keyframes.back().collision_count) {
    data->keyframes.push_back(last);
  }
  data->collision_count = last.collision_count;
  data->energy_lost_J = last.energy_lost_J;
  data->energy_lost_analytic_J = last.energy_lost_analytic_J;
  data->simulated_until_s = world.duration_s;
  if (stop == detail::RunStop::kCollisionCap) {
    data->status = SimulationStatus::kCollisionCapReached;
    data->simulated_until_s = last.time_s;
    data->warnings.push_back({WarningKind::kCollisionCap, last.collision_count - 1, last.time_s,
                              describeStop("stopped at the collision cap (max_collisions)",
                                           last.collision_count, last.time_s)});
  } else if (stop == detail::RunStop::kRateCap) {
    // Like the collision cap: the timeline holds up to the last simulated collision.
    data->status = SimulationStatus::kCollisionRateCapReached;
    data->simulated_until_s = last.time_s;
  } else if (stop == detail::RunStop::kStalled) {
    data->status = SimulationStatus::kStalled;
    data->simulated_until_s = last.time_s;
    // The 2D engine names the resting stack that stopped it; any other stall is events piling up
    // at one instant.
    const bool explained =
        !data->warnings.empty() && data->warnings.back().kind == WarningKind::kStalled;
    if (!explained) {
      data->warnings.push_back({WarningKind::kStalled, last.collision_count - 1, last.time_s,
                                describeStop("stalled: collisions kept happening at one instant",
                                             last.collision_count, last.time_s)});
    }
  }
  return Timeline(std::move(data));
}

}  // namespace collide::physics
