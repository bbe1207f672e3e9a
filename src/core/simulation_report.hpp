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

class SimulationReport {
 public:
  using Clock = std::chrono::steady_clock;

  // A run of `duration_s` simulated seconds, starting at `start`, silent for `quiet_time`.
  SimulationReport(std::ostream& out, ProgressStyle style, double duration_s,
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
  // about 57 s left". The time left assumes the rest of the scene goes as fast as the run so far,
  // or as its recent pace (`recent_rate`: simulated seconds per second over the last few seconds,
  // when known) if that is slower: a run that slows down (disks gathering into a cluster) says
  // so, and one that has stopped gaining simulated time says it cannot tell.
  static std::string describe(double simulated_s, double duration_s, std::int64_t collisions,
                              double elapsed_s, double recent_rate = -1.0);

 private:
  void draw(double simulated_s, std::int64_t collisions, Clock::time_point now);

  std::ostream& out_;
  ProgressStyle style_;
  double duration_s_;
  Clock::time_point start_;
  Clock::duration quiet_time_;
  Clock::time_point last_drawn_;
  // The start of the recent pace: where the run was, and when (moved on every few seconds).
  double pace_simulated_s_ = 0.0;
  Clock::time_point pace_start_;
  double last_rate_ = -1.0;  // the pace last measured; < 0: none yet
  bool drawn_ = false;
  bool finished_ = false;
};

}  // namespace collide::core
