// The cap on collisions per simulated second (WorldDef::max_collisions_per_second): a cascade
// that piles up collisions faster than the cap stops with a status and a warning naming the time,
// the count and the limit. Expected stopping points come from the event log of an uncapped run.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "physics/pi_blocks.hpp"
#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace {

using testing::disk;
using testing::wall;

std::vector<double> collisionTimes(const Timeline& timeline) {
  std::vector<double> times;
  timeline.replayCollisions([&](const CollisionEvent& event) { times.push_back(event.time_s); });
  return times;
}

// Below 128 collisions per second the guard checks every collision, so the stop is exact: before
// the first collision k whose time is less than a second after that of collision k - cap (cap + 1
// collisions within one second).
TEST(RateCapTest, StopsBeforeTheFirstCollisionThatOverfillsASecond) {
  constexpr std::int64_t kCap = 100;
  WorldDef world = piBlocksWorld(3);  // 314 collisions between t = 1.3 s and 10.3 s
  world.max_collisions_per_second = 0;
  const std::vector<double> t = collisionTimes(simulate(world));
  ASSERT_EQ(t.size(), 314u);
  std::size_t stop = 0;
  for (std::size_t k = kCap; k < t.size() && stop == 0; ++k) {
    if (t[k] - t[k - kCap] < 1.0) stop = k;
  }
  ASSERT_GT(stop, 0u) << "the scene must pile up more than the cap within a second";

  world.max_collisions_per_second = kCap;
  const Timeline capped = simulate(world);
  EXPECT_EQ(capped.status(), SimulationStatus::kCollisionRateCapReached);
  EXPECT_EQ(capped.collisionCount(), static_cast<std::int64_t>(stop));
  EXPECT_EQ(capped.simulatedUntil_s(), t[stop - 1]);
  ASSERT_EQ(capped.warnings().size(), 1u);
  const Warning& warning = capped.warnings().front();
  EXPECT_EQ(warning.kind, WarningKind::kCollisionRateCap);
  EXPECT_EQ(warning.collision_index, static_cast<std::int64_t>(stop) - 1);
  EXPECT_EQ(warning.time_s, t[stop - 1]);
  // Everything up to the stop is the uncapped run, and replays give exactly the stored count.
  const std::vector<double> replayed = collisionTimes(capped);
  ASSERT_EQ(replayed.size(), stop);
  for (std::size_t k = 0; k < stop; ++k) EXPECT_EQ(replayed[k], t[k]) << k;
}

TEST(RateCapTest, MessageNamesTimeCountAndLimitInOneSentence) {
  WorldDef world = piBlocksWorld(3);
  world.max_collisions_per_second = 0;
  const std::vector<double> t = collisionTimes(simulate(world));
  world.max_collisions_per_second = 100;
  const Timeline capped = simulate(world);
  ASSERT_EQ(capped.warnings().size(), 1u);
  const std::size_t stop = static_cast<std::size_t>(capped.collisionCount());
  ASSERT_GE(stop, 100u);
  ASSERT_LT(stop, t.size());
  char expected[400];
  std::snprintf(expected, sizeof expected,
                "stopped at t = %.9g s after %zu collisions because they piled up faster than "
                "the limit of 100 collisions per simulated second (max_collisions_per_second): "
                "101 were due between t = %.9g s and t = %.9g s; later states are not simulated",
                t[stop - 1], stop, t[stop - 100], t[stop]);
  EXPECT_EQ(capped.warnings().front().message, expected);
}

// Two disks stick into a spinning cluster that falls onto a perfectly inelastic floor. With the
// collapse guard off (collapse_time_s = 0) the cluster chatters against the floor: each impulse
// stops the touching disk, the spin brings it back 1.5e-12 s later. Time advances, so only the
// rate cap ends the run.
WorldDef spinningClusterOnInelasticFloor() {
  WorldDef world;
  world.dimensions = 2;
  world.duration_s = 3.0;
  world.restitution = 0.0;
  world.inelastic_mode = InelasticMode::kStick;
  world.gravity_mps2 = {0.0, -9.81};
  world.walls = {wall("floor", {0.0, 0.0}, {0.0, 1.0}, 0.0)};
  world.bodies = {disk("a", 1.0, 0.2, {-1.0, 1.0}, {2.0, 0.0}),
                  disk("b", 2.0, 0.3, {0.0, 1.25}, {0.0, 0.0})};
  return world;
}

TEST(RateCapTest, ChatteringClusterStopsAtTheCapWithoutOverlap) {
  constexpr std::int64_t kCap = 100'000;
  WorldDef world = spinningClusterOnInelasticFloor();
  world.collapse_time_s = 0.0;
  world.max_collisions_per_second = kCap;
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.status(), SimulationStatus::kCollisionRateCapReached);
  ASSERT_EQ(timeline.warnings().back().kind, WarningKind::kCollisionRateCap);
  const std::vector<double> t = collisionTimes(timeline);
  ASSERT_EQ(static_cast<std::int64_t>(t.size()), timeline.collisionCount());
  EXPECT_EQ(timeline.simulatedUntil_s(), t.back());
  // More than the cap fell within the last second (counted from the log), and the guard, which
  // keeps every (cap / 64)-th time, stopped within two such strides of the cap.
  std::int64_t last_second = 0;
  for (double time : t) last_second += time > t.back() - 1.0 ? 1 : 0;
  EXPECT_GE(last_second, kCap);
  EXPECT_LE(timeline.collisionCount(), kCap + 2 * (kCap / 64));
  // Up to the stop the disks stay clear of the floor (radius 0.2 m and 0.3 m), to rounding.
  for (int k = 0; k <= 100; ++k) {
    const Snapshot s = timeline.sample(timeline.simulatedUntil_s() * k / 100.0);
    EXPECT_GE(s.bodies[0].position_m.y() - 0.2, -1e-9) << k;
    EXPECT_GE(s.bodies[1].position_m.y() - 0.3, -1e-9) << k;
  }
}

TEST(RateCapTest, CollapseGuardSettlesTheSameClusterInAFewCollisions) {
  const Timeline timeline = simulate(spinningClusterOnInelasticFloor());
  EXPECT_EQ(timeline.status(), SimulationStatus::kComplete);
  EXPECT_LE(timeline.collisionCount(), 10);
  // Resting on the floor at the end: no vertical motion, no spin, no overlap, and no energy
  // gained since the start (kinetic plus potential, m g y with g = 9.81 m/s^2).
  const Snapshot end = timeline.sample(timeline.duration_s());
  for (const BodyState& body : end.bodies) {
    EXPECT_NEAR(body.velocity_mps.y(), 0.0, 1e-12);
    EXPECT_EQ(body.angular_velocity_radps, 0.0);
  }
  EXPECT_GE(end.bodies[0].position_m.y() - 0.2, -1e-9);
  EXPECT_GE(end.bodies[1].position_m.y() - 0.3, -1e-9);
  EXPECT_LE(timeline.mechanicalEnergy(end), timeline.mechanicalEnergy(timeline.sample(0.0)));
}

TEST(RateCapTest, ZeroDisablesTheCap) {
  WorldDef world = piBlocksWorld(3);
  world.max_collisions_per_second = 0;
  const Timeline timeline = simulate(world);
  EXPECT_EQ(timeline.status(), SimulationStatus::kComplete);
  EXPECT_EQ(timeline.collisionCount(), 314);
}

}  // namespace
}  // namespace collide::physics
