#include "physics/sample_cursors.hpp"

#include "physics/timeline_data.hpp"

namespace collide::physics::detail {
namespace {

// What a new engine costs, in events to catch up per body. On the ideal gas a new engine from a
// checkpoint cost about as much as catching up a hundred or more collisions (with the cell
// crossings between them), so carrying on is cheaper up to about half an event per body
// (bench/results.md has the measurement). Two bodies catch up one event at most.
constexpr double kCatchUpEventsPerBody = 0.5;

std::int64_t eventsOf(const EngineState& state) {
  return state.collision_count + state.string_events;
}

}  // namespace

Snapshot SampleCursors::replayTo(const TimelineData& data, std::size_t keyframe, double t_s) {
  const EngineState& base = data.keyframes[keyframe];
  const Recorder quiet;
  const std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock()) {
    const std::unique_ptr<Engine> engine = makeEngine(data.model, base, quiet);
    engine->run(t_s, data.collision_count);
    return evaluate(data.model, engine->state(), t_s);
  }
  // The engine nearest t_s among those that have run no event after it.
  Cursor* cursor = nullptr;
  for (Cursor& c : cursors_) {
    if (c.engine == nullptr || c.time_s > t_s) continue;
    if (cursor == nullptr || eventsOf(c.engine->state()) > eventsOf(cursor->engine->state())) {
      cursor = &c;
    }
  }
  const auto catch_up_limit =
      static_cast<std::int64_t>(kCatchUpEventsPerBody * static_cast<double>(base.bodies.size()));
  if (cursor == nullptr || eventsOf(base) - eventsOf(cursor->engine->state()) > catch_up_limit) {
    // A new engine from the checkpoint, in the cursor used least recently.
    cursor = &cursors_[0];
    for (Cursor& c : cursors_) {
      if (c.last_use < cursor->last_use) cursor = &c;
    }
    cursor->engine.reset();  // before the new one: one engine's memory at a time
    cursor->engine = makeEngine(data.model, base, quiet);
  }
  cursor->engine->run(t_s, data.collision_count);
  cursor->time_s = t_s;
  cursor->last_use = ++uses_;
  return evaluate(data.model, cursor->engine->state(), t_s);
}

}  // namespace collide::physics::detail
