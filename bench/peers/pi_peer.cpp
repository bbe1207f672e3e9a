// A minimal, specialised peer for the pi-blocks benchmark: two point blocks and a wall, elastic,
// counting collisions with the same velocity-difference update the engine uses. No positions, no
// times, no event queue: the lower bound the general engine is compared with.
//   usage: pi_peer [digits=8] [runs=5]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv) {
  const int digits = argc > 1 ? std::atoi(argv[1]) : 8;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
  double big_mass = 1.0;
  for (int k = 1; k < digits; ++k) big_mass *= 100.0;
  std::vector<double> seconds;
  long long count = 0;
  for (int run = 0; run < runs; ++run) {
    const auto start = std::chrono::steady_clock::now();
    double v_small = 0.0, v_big = -1.0;
    const double m_small = 1.0, m_eff = 1.0 / (1.0 / m_small + 1.0 / big_mass);
    count = 0;
    for (;;) {
      if (v_small > v_big) {  // the small block catches up with (or is hit by) the big one
        const double impulse = 2.0 * (v_small - v_big) * m_eff;
        v_small -= impulse / m_small;
        v_big += impulse / big_mass;
      } else if (v_small < 0.0) {  // the small block heads for the wall
        v_small = -v_small;
      } else {
        break;
      }
      ++count;
    }
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(seconds.begin(), seconds.end());
  const double median = seconds[seconds.size() / 2];
  std::printf("pi_peer digits=%d collisions=%lld median=%.3f s (%d runs) rate=%.3g collisions/s\n",
              digits, count, median, runs, count / median);
  return 0;
}
