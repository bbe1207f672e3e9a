#pragma once
// Internal: the re-simulations Timeline::sample keeps between calls. A time with events between
// its checkpoint and itself is re-simulated; a new engine rebuilds every body's predictions from
// the checkpoint, which for many bodies costs more than the events between two frames (300 disks:
// about as much as 100 collisions). Frames ask for times in order, so an engine left where the
// last sample stopped is carried on instead, to the same state: an engine's run paused at t and
// resumed is the run it would have made, and every run from a checkpoint replays the original
// one bit for bit (engine.hpp).
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>

#include "physics/engine.hpp"

namespace collide::physics::detail {

struct TimelineData;

class SampleCursors {
 public:
  // The state at t_s, which lies after checkpoint `keyframe` of `data` with events between:
  // re-simulated from that checkpoint, or from an engine an earlier call left at or before t_s
  // where that has fewer events to catch up than a new engine costs. Safe from any thread (a
  // call that finds the cursors busy re-simulates on its own).
  Snapshot replayTo(const TimelineData& data, std::size_t keyframe, double t_s);

 private:
  struct Cursor {
    std::unique_ptr<Engine> engine;  // null: unused
    double time_s = 0.0;             // the engine has run every event at or before this, none after
    std::uint64_t last_use = 0;
  };
  // Three: a frame samples its own time, the instants of its latest collisions (its flashes, a
  // little earlier) and the start (the gas's speed histogram), or its trail up to now.
  std::array<Cursor, 3> cursors_;
  std::uint64_t uses_ = 0;
  std::mutex mutex_;
};

}  // namespace collide::physics::detail
