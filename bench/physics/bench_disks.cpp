// Many-body benchmark: 500 disks in a box against 2 disks in the same box, both elastic, each run
// to a fixed number of collisions (another count of disks gets a box of the same fill, 35 %).
// Prints seconds and collisions per second for both (medians of several runs) and the ratio of
// the times per collision: the cost of the many-body scene's event search (the 2D broad phase)
// beside the bare cost of an impact.
//   usage: bench_disks [collisions=1000000] [runs=3] [disks=500]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "physics/simulate.hpp"
#include "simulation_timing.hpp"

namespace {

using namespace collide::physics;

constexpr double kHalfBox_m = 0.5;   // for 500 disks the box is [-0.5, 0.5]^2
constexpr double kRadius_m = 0.015;  // 500 disks fill 35 % of it
constexpr int kDisksPerBox = 500;    // more or fewer disks: the box's area in proportion

WallDef wall(const char* name, collide::core::Vec2 point, collide::core::Vec2 normal) {
  WallDef w;
  w.name = name;
  w.point_m = point;
  w.normal = normal;
  w.restitution = 1.0;
  return w;
}

// Disks on a jittered square lattice (never overlapping), speeds up to 1 m/s in random
// directions, from a fixed seed: the same scene on every run and machine. The box is
// [-half_box_m, half_box_m]^2.
WorldDef box(int disks, std::int64_t collisions, double half_box_m) {
  WorldDef world;
  world.dimensions = 2;
  world.restitution = 1.0;
  world.duration_s = 1e9;  // the collision count ends the run
  world.max_collisions = collisions;
  world.max_recorded_collisions = 1000;
  world.walls = {wall("left", {-half_box_m, 0.0}, {1.0, 0.0}),
                 wall("right", {half_box_m, 0.0}, {-1.0, 0.0}),
                 wall("floor", {0.0, -half_box_m}, {0.0, 1.0}),
                 wall("ceiling", {0.0, half_box_m}, {0.0, -1.0})};
  std::mt19937_64 dice(2026);
  auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(dice() >> 11) * 0x1.0p-53;
  };
  int side = 1;
  while (side * side < disks) ++side;
  const double pitch = 2.0 * half_box_m / side;
  const double jitter = std::max(0.0, 0.5 * pitch - kRadius_m) * 0.9;
  for (int k = 0; k < disks; ++k) {
    BodyDef body;
    char name[16];
    std::snprintf(name, sizeof name, "d%d", k);  // (GCC 12 warns falsely on "d" + to_string)
    body.name = name;
    body.shape = Shape::kDisk;
    body.mass_kg = 1.0;
    body.size_m = kRadius_m;
    const double cx = -half_box_m + pitch * (k % side + 0.5);
    const double cy = -half_box_m + pitch * (k / side + 0.5);
    body.position_m = {cx + uniform(-jitter, jitter), cy + uniform(-jitter, jitter)};
    const double angle = uniform(0.0, 6.283185307179586), speed = uniform(0.1, 1.0);
    body.velocity_mps = {speed * std::cos(angle), speed * std::sin(angle)};
    world.bodies.push_back(body);
  }
  return world;
}

}  // namespace

int main(int argc, char** argv) {
  const std::int64_t collisions = argc > 1 ? std::atoll(argv[1]) : 1'000'000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 3;
  const int disks = argc > 3 ? std::atoi(argv[3]) : 500;
  using collide::bench::SimulationTiming;
  // 500 disks: exactly kHalfBox_m (sqrt(1) = 1).
  const double half_box_m = kHalfBox_m * std::sqrt(static_cast<double>(disks) / kDisksPerBox);
  const SimulationTiming two = collide::bench::timeSimulation(box(2, collisions, half_box_m), runs);
  const SimulationTiming many =
      collide::bench::timeSimulation(box(disks, collisions, half_box_m), runs);
  const double two_rate = two.collisions / two.seconds, many_rate = many.collisions / many.seconds;
  std::printf(
      "bench_disks 2 disks: collisions=%lld median=%.3f s (cpu %.3f s) rate=%.3g collisions/s\n",
      static_cast<long long>(two.collisions), two.seconds, two.cpu_seconds, two_rate);
  std::printf(
      "bench_disks %d disks: collisions=%lld median=%.3f s (cpu %.3f s) rate=%.3g collisions/s\n",
      disks, static_cast<long long>(many.collisions), many.seconds, many.cpu_seconds, many_rate);
  // Per collision: (many seconds / many collisions) / (two seconds / two collisions).
  std::printf("bench_disks time per collision, %d disks / 2 disks: %.2f (cpu %.2f; %d runs)\n",
              disks, two_rate / many_rate,
              (many.cpu_seconds / many.collisions) / (two.cpu_seconds / two.collisions), runs);
  return 0;
}
