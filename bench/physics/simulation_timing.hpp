#pragma once
// What the physics benchmarks measure of a simulation run several times: the median wall and
// CPU seconds (the CPU time tells the cost on a loaded machine, where the wall time also holds
// the waiting), the fastest run, and the collisions of a run.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <ctime>
#include <vector>

#include "physics/simulate.hpp"

namespace collide::bench {

struct SimulationTiming {
  double seconds = 0.0;      // median wall time of a run
  double cpu_seconds = 0.0;  // median CPU time of a run
  double min_seconds = 0.0;  // the fastest run's wall time
  std::int64_t collisions = 0;
};

inline double cpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// Simulates `world` `runs` times (at least one).
inline SimulationTiming timeSimulation(const physics::WorldDef& world, int runs) {
  std::vector<double> seconds, cpu;
  SimulationTiming timing;
  for (int run = 0; run < runs; ++run) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = cpuSeconds();
    const physics::Timeline timeline = physics::simulate(world);
    cpu.push_back(cpuSeconds() - cpu_start);
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    timing.collisions = timeline.collisionCount();
  }
  std::sort(seconds.begin(), seconds.end());
  std::sort(cpu.begin(), cpu.end());
  timing.seconds = seconds[seconds.size() / 2];
  timing.cpu_seconds = cpu[cpu.size() / 2];
  timing.min_seconds = seconds.front();
  return timing;
}

}  // namespace collide::bench
