#pragma once
// Progress of a long simulation on stderr, for every command that simulates (data, still, strobe,
// chart, render before its frames): nothing while a run is young (most end within 2 s), then the
// way render shows its frames: a line redrawn in place on a terminal, a plain line every 5 s in a
// log, nothing under -q/--quiet.
#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>

#include "core/progress.hpp"

namespace collide::core {

// Runs shorter than this say nothing (issue 14: progress for any run over 2 s).
inline constexpr std::chrono::seconds kQuietSimulationTime{2};

// What bounds a run: the simulated time it is asked for, the collision count at which it stops
// (WorldDef::max_collisions; 0: none) and whether settling is off (contact.collapse_time = 0: a
// bounce series under gravity then never ends on its own).
struct RunLimits {
  double duration_s = 0.0;
  std::int64_t max_collisions = 0;
  bool settling_off = false;
};

// The run's pace over the last few seconds; negative: not measured yet.
struct RecentPace {
  double simulated_s_per_s = -1.0;
  double collisions_per_s = -1.0;
};

class SimulationReport {
 public:
  using Clock = std::chrono::steady_clock;

  // A run bounded by `limits`, starting at `start`, silent for `quiet_time`.
  SimulationReport(std::ostream& out, ProgressStyle style, RunLimits limits,
                   Clock::time_point start = Clock::now(),
                   Clock::duration quiet_time = kQuietSimulationTime);
  // A bar left mid-line (the run threw: a stop request) ends its line, so the error that follows
  // starts on its own.
  ~SimulationReport();
  SimulationReport(const SimulationReport&) = delete;
  SimulationReport& operator=(const SimulationReport&) = delete;
  // The run has reached `simulated_s` after `collisions`. Cheap: one clock reading, a line at most
  // 10 times a second (bar) or every 5 s (lines), none during the quiet time.
  void update(double simulated_s, std::int64_t collisions, Clock::time_point now = Clock::now());
  // The run is over, simulated up to `simulated_s` (the duration, or where a cap stopped it): a
  // shown bar gets its last state and ends its line; a log that got lines gets a last one. A run
  // that never showed anything stays silent.
  void finish(double simulated_s, std::int64_t collisions, Clock::time_point now = Clock::now());

  // The text of one report: "t = 120 of 3600 s simulated (3%), 81234 collisions, 2.1 s elapsed,
  // about 57 s left". The time left is stated only while the pace holds: the estimate from the
  // average pace and the one from the recent pace agree within a factor of 2. Otherwise the time
  // left is unknown, and says why; where the collision rate and the cap are known, the time the
  // cap leaves bounds it ("at most ... more").
  static std::string describe(double simulated_s, std::int64_t collisions, double elapsed_s,
                              const RunLimits& limits, const RecentPace& recent = {});
  // Collisions pile up while simulated time hardly advances: at the recent pace the rest of the
  // run would take over a thousand times as long as the run so far.
  static bool stalled(double simulated_s, double elapsed_s, const RunLimits& limits,
                      const RecentPace& recent);
  // The line said once when a run stalls: where, how fast the collisions come, and what ends it.
  static std::string stallNote(double simulated_s, const RunLimits& limits,
                               const RecentPace& recent);

 private:
  void draw(double simulated_s, std::int64_t collisions, Clock::time_point now);
  RecentPace measurePace(double simulated_s, std::int64_t collisions, Clock::time_point now);

  std::ostream& out_;
  ProgressStyle style_;
  RunLimits limits_;
  Clock::time_point start_;
  Clock::duration quiet_time_;
  Clock::time_point last_drawn_;
  // The start of the recent pace: where the run was, and when (moved on every second).
  double pace_simulated_s_ = 0.0;
  std::int64_t pace_collisions_ = 0;
  Clock::time_point pace_start_;
  RecentPace last_pace_;  // the pace last measured
  bool drawn_ = false;
  bool finished_ = false;
  bool stall_noted_ = false;
};

}  // namespace collide::core
