// Restitution per pair, per wall and as a function of impact speed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace {

using testing::block;
using testing::wall;

// One block (1 kg) at speed u into an elastic-by-default wall; returns the event.
CollisionEvent wallHit(const WorldDef& base, double u) {
  WorldDef world = base;
  world.duration_s = 2.0;
  world.bodies = {block("a", 1.0, 0.2, 1.0, -u)};
  world.walls = {wall("w", {0.0, 0.0}, {1.0, 0.0}, 0.8)};
  const Timeline timeline = simulate(world);
  EXPECT_EQ(timeline.collisionCount(), 1);
  return timeline.collisions().at(0);
}

TEST(RestitutionLawTest, SpeedThresholdLawFallsAsAPowerAboveTheThreshold) {
  WorldDef world;
  world.restitution_model.law = RestitutionLaw::kSpeedThreshold;
  world.restitution_model.threshold_speed_mps = 1.5;
  world.restitution_model.exponent = 0.25;
  const CollisionEvent slow = wallHit(world, 1.0);
  EXPECT_EQ(slow.restitution, 0.8);
  EXPECT_DOUBLE_EQ(slow.velocity_a_after_mps.x(), 0.8);
  const CollisionEvent fast = wallHit(world, 6.0);
  const double e = 0.8 * std::pow(1.5 / 6.0, 0.25);  // = 0.8 / sqrt(2)
  EXPECT_NEAR(fast.restitution, 0.8 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(fast.velocity_a_after_mps.x(), e * 6.0, 1e-12);
  EXPECT_NEAR(fast.energy_lost_J, 0.5 * (1 - e * e) * 36.0, 1e-12);
}

TEST(RestitutionLawTest, TableInterpolatesLinearlyAndClampsAtTheEnds) {
  WorldDef world;
  world.restitution_model.law = RestitutionLaw::kTable;
  world.restitution_model.table = {{1.0, 0.9}, {3.0, 0.5}, {5.0, 0.3}};
  EXPECT_DOUBLE_EQ(wallHit(world, 0.5).restitution, 0.9);
  EXPECT_DOUBLE_EQ(wallHit(world, 2.0).restitution, 0.7);
  EXPECT_DOUBLE_EQ(wallHit(world, 4.0).restitution, 0.4);
  EXPECT_DOUBLE_EQ(wallHit(world, 9.0).restitution, 0.3);
}

TEST(RestitutionPairTest, PerPairAndPerWallValuesApply) {
  // a -> b with e = 0.25, b -> c with the default 1, c -> wall with 0.5.
  WorldDef world;
  world.duration_s = 6.0;
  world.restitution = 1.0;
  world.pair_restitution = {{1, 0, 0.25}};  // order does not matter
  world.bodies = {block("a", 1.0, 0.5, 0.0, 2.0), block("b", 1.0, 0.5, 2.0, 0.0),
                  block("c", 1.0, 0.5, 4.0, 0.0)};
  world.walls = {wall("w", {6.0, 0.0}, {-1.0, 0.0}, 0.5)};
  const Timeline timeline = simulate(world);
  ASSERT_GE(timeline.collisionCount(), 3);
  const auto& events = timeline.collisions();
  EXPECT_EQ(events[0].restitution, 0.25);
  // Equal masses, e = 0.25: v_a' = (1 - e)/2 * 2, v_b' = (1 + e)/2 * 2.
  EXPECT_DOUBLE_EQ(events[0].velocity_a_after_mps.x(), 0.75);
  EXPECT_DOUBLE_EQ(events[0].velocity_b_after_mps.x(), 1.25);
  bool saw_wall = false;
  for (const CollisionEvent& event : events) {
    if (event.hitsWall()) {
      saw_wall = true;
      EXPECT_EQ(event.restitution, 0.5);
    } else if (std::min(event.body_a, event.body_b) == 0 &&
               std::max(event.body_a, event.body_b) == 1) {
      EXPECT_EQ(event.restitution, 0.25);
    } else {
      EXPECT_EQ(event.restitution, 1.0);
    }
  }
  EXPECT_TRUE(saw_wall);
}

}  // namespace
}  // namespace collide::physics
