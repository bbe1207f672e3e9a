#include "app/simulation_progress.hpp"

namespace collide::app {
namespace {

const SimulationReportScope* g_innermost_scope = nullptr;

}  // namespace

SimulationReportScope::SimulationReportScope(std::ostream& out, core::ProgressStyle style,
                                             Clock::duration quiet_time)
    : out_(&out), style_(style), quiet_time_(quiet_time), previous_(g_innermost_scope) {
  g_innermost_scope = this;
}

SimulationReportScope::~SimulationReportScope() {
  g_innermost_scope = previous_;
}

physics::Timeline simulateReporting(const physics::WorldDef& world) {
  const SimulationReportScope* scope = g_innermost_scope;
  if (scope == nullptr || scope->style_ == core::ProgressStyle::kSilent)
    return physics::simulate(world);
  const core::RunLimits limits{world.duration_s, world.max_collisions,
                               world.collapse_time_s <= 0.0};
  core::SimulationReport report(*scope->out_, scope->style_, limits,
                                core::SimulationReport::Clock::now(), scope->quiet_time_);
  physics::Timeline timeline =
      physics::simulate(world, [&report](double simulated_s, std::int64_t collisions) {
        report.update(simulated_s, collisions);
      });
  report.finish(timeline.simulatedUntil_s(), timeline.collisionCount());
  return timeline;
}

}  // namespace collide::app
