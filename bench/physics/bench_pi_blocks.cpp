// Pi-blocks benchmark: runs the general 1D engine on Galperin's blocks and prints collisions per
// second (median of several runs). Compare with bench_pi_peer, a specialised two-block loop.
//   usage: bench_pi_blocks [digits=8] [runs=5]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include "physics/pi_blocks.hpp"
#include "physics/simulate.hpp"

namespace {

double cpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace collide::physics;
  const int digits = argc > 1 ? std::atoi(argv[1]) : 8;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
  const WorldDef world = piBlocksWorld(digits);
  std::vector<double> seconds, cpu;
  std::int64_t count = 0;
  for (int run = 0; run < runs; ++run) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = cpuSeconds();
    const Timeline timeline = simulate(world);
    cpu.push_back(cpuSeconds() - cpu_start);
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    count = timeline.collisionCount();
  }
  std::sort(seconds.begin(), seconds.end());
  std::sort(cpu.begin(), cpu.end());
  const double median = seconds[seconds.size() / 2];
  // The CPU time tells the cost on a loaded machine, where the wall time also holds the waiting.
  std::printf(
      "bench_pi_blocks digits=%d collisions=%lld median=%.3f s (cpu %.3f s) min=%.3f s (%d runs) "
      "rate=%.3g collisions/s\n",
      digits, static_cast<long long>(count), median, cpu[cpu.size() / 2], seconds.front(), runs,
      count / median);
  return 0;
}
