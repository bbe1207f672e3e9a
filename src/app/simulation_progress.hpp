#pragma once
// Where the progress of a long simulation (core/simulation_report.hpp) goes while a command runs,
// and physics::simulate reporting to it.
#include <chrono>
#include <ostream>

#include "core/progress.hpp"
#include "core/simulation_report.hpp"
#include "physics/simulate.hpp"

namespace collide::app {

// Where simulation progress goes while a command runs. runCli sets it for the command; a scope
// inside (a batch worker, whose stderr is its log) may silence it. Scopes nest: the destructor
// restores the previous one. One command runs at a time on the simulating thread.
class SimulationReportScope {
 public:
  using Clock = std::chrono::steady_clock;

  // `quiet_time`: how long a run says nothing (tests shorten it).
  SimulationReportScope(std::ostream& out, core::ProgressStyle style,
                        Clock::duration quiet_time = core::kQuietSimulationTime);
  ~SimulationReportScope();
  SimulationReportScope(const SimulationReportScope&) = delete;
  SimulationReportScope& operator=(const SimulationReportScope&) = delete;

 private:
  std::ostream* out_;
  core::ProgressStyle style_;
  Clock::duration quiet_time_;
  const SimulationReportScope* previous_;
  friend physics::Timeline simulateReporting(const physics::WorldDef& world);
};

// physics::simulate, reporting its progress where the innermost scope says (silent without one).
physics::Timeline simulateReporting(const physics::WorldDef& world);

}  // namespace collide::app
