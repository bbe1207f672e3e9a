// The 2D broad phase (a uniform grid, on from 32 disks): it decides only which impacts are
// predicted, so a scene with many disks must miss no contact (no overlap at any sampled time),
// keep its energy (e = 1) and its books, including disks that leave the cells of their starting
// extent for the outer cells, and scenes where stuck clusters form (the grid is then dropped).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace {

using testing::disk;
using testing::numbered;

// n disks of radius 0.02 m on a jittered lattice inside [-start, start]^2, walls at +-box.
WorldDef crowd(int n, double start_m, double box_m, double e) {
  WorldDef world;
  world.dimensions = 2;
  world.restitution = e;
  world.duration_s = 3.0;
  world.walls = testing::boxWalls(box_m);
  std::mt19937_64 dice(7);
  auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(dice() >> 11) * 0x1.0p-53;
  };
  int side = 1;
  while (side * side < n) ++side;
  const double pitch = 2.0 * start_m / side;
  for (int k = 0; k < n; ++k) {
    const core::Vec2 centre(-start_m + pitch * (k % side + 0.5),
                            -start_m + pitch * (k / side + 0.5));
    const core::Vec2 jitter(uniform(-0.2, 0.2) * pitch, uniform(-0.2, 0.2) * pitch);
    world.bodies.push_back(disk(numbered("d", k), uniform(0.5, 2.0), 0.02, centre + jitter,
                                {uniform(-1.0, 1.0), uniform(-1.0, 1.0)}));
  }
  return world;
}

// No two disks and no disk and wall overlap beyond rounding at any of the samples.
void expectNoOverlap(const Timeline& timeline, int samples) {
  const WorldDef& world = timeline.world();
  for (int k = 0; k <= samples; ++k) {
    const double t = timeline.simulatedUntil_s() * k / samples;
    const Snapshot s = timeline.sample(t);
    for (std::size_t a = 0; a < s.bodies.size(); ++a) {
      for (std::size_t b = a + 1; b < s.bodies.size(); ++b) {
        const double gap = (s.bodies[b].position_m - s.bodies[a].position_m).norm() -
                           world.bodies[a].size_m - world.bodies[b].size_m;
        ASSERT_GE(gap, -1e-10) << "t " << t << " disks " << a << ", " << b;
      }
      for (const WallDef& w : world.walls) {
        ASSERT_GE((s.bodies[a].position_m - w.point_m).dot(w.normal) - world.bodies[a].size_m,
                  -1e-10)
            << "t " << t << " disk " << a << " wall " << w.name;
      }
    }
  }
}

TEST(PlaneGridTest, ACrowdedElasticBoxMissesNoContact) {
  const Timeline timeline = simulate(crowd(100, 0.5, 0.5, 1.0));
  ASSERT_EQ(timeline.status(), SimulationStatus::kComplete);
  ASSERT_GT(timeline.collisionCount(), 2000);
  expectNoOverlap(timeline, 60);
  // Elastic: the kinetic energy at the end is the energy at the start, and nothing is booked.
  const double start = timeline.kineticEnergy(timeline.sample(0.0));
  EXPECT_NEAR(timeline.kineticEnergy(timeline.sample(3.0)), start, 1e-12 * start);
  EXPECT_EQ(timeline.totalEnergyLost(), 0.0);
}

TEST(PlaneGridTest, DisksLeavingTheirStartingCellsStillMeet) {
  // Started within 0.3 m of the centre of a 2 m box: the disks spread into the grid's outer
  // cells, which reach to infinity, and keep colliding there and with the walls.
  const Timeline timeline = simulate(crowd(64, 0.3, 1.0, 0.8));
  ASSERT_EQ(timeline.status(), SimulationStatus::kComplete);
  ASSERT_GT(timeline.collisionCount(), 200);
  expectNoOverlap(timeline, 60);
  EXPECT_LE(std::abs(timeline.energyLostMeasured() - timeline.totalEnergyLost()),
            timeline.energyLedgerTolerance());
}

TEST(PlaneGridTest, StuckClustersDropTheGridAndMissNothing) {
  WorldDef world = crowd(40, 0.4, 0.5, 0.0);
  world.inelastic_mode = InelasticMode::kStick;
  world.duration_s = 1.0;
  const Timeline timeline = simulate(world);
  ASSERT_GT(timeline.collisionCount(), 10);
  expectNoOverlap(timeline, 40);
}

}  // namespace
}  // namespace collide::physics
