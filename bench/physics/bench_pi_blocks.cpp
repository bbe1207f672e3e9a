// Pi-blocks benchmark: runs the general 1D engine on Galperin's blocks and prints collisions per
// second (median of several runs). Compare with bench_pi_peer, a specialised two-block loop.
//   usage: bench_pi_blocks [digits=8] [runs=5]
#include <cstdio>
#include <cstdlib>

#include "physics/pi_blocks.hpp"
#include "simulation_timing.hpp"

int main(int argc, char** argv) {
  const int digits = argc > 1 ? std::atoi(argv[1]) : 8;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
  const collide::bench::SimulationTiming timing =
      collide::bench::timeSimulation(collide::physics::piBlocksWorld(digits), runs);
  std::printf(
      "bench_pi_blocks digits=%d collisions=%lld median=%.3f s (cpu %.3f s) min=%.3f s (%d runs) "
      "rate=%.3g collisions/s\n",
      digits, static_cast<long long>(timing.collisions), timing.seconds, timing.cpu_seconds,
      timing.min_seconds, runs, timing.collisions / timing.seconds);
  return 0;
}
