// SPDX-License-Identifier: MIT
// The 1D engine's loop for two elastic bodies and one wall (line_wall_pair.cpp), which runs
// pi-blocks, against the general loop on the same scenes. A third block far beyond the big one,
// leaving faster than anything in the scene can follow, puts the general loop in charge of the
// same two bodies and the same wall. Both update velocities with the same arithmetic, so the
// impacts, their order, the counts and every velocity must agree bit for bit; times and positions
// come from the same physics computed in a different order, so they must agree to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "physics/pi_blocks.hpp"
#include "physics/simulate.hpp"

namespace collide::physics {
namespace {

constexpr double kRoundingUnit = std::numeric_limits<double>::epsilon();

// The first d digits of pi as an integer, from its decimal expansion 3.14159265...
std::int64_t piCount(int d) {
  const char* digits = "314159265";
  std::int64_t value = 0;
  for (int k = 0; k < d; ++k) value = 10 * value + (digits[k] - '0');
  return value;
}

// pi-blocks with a spectator 50 m from the wall leaving at 10 m/s. The big block never moves
// faster than its starting 1 m/s (it never has more than the scene's kinetic energy), so the
// spectator is never reached and takes no part.
WorldDef withSpectator(WorldDef world) {
  BodyDef spectator;
  spectator.name = "spectator";
  spectator.mass_kg = 1.0;
  spectator.size_m = 0.5;
  spectator.position_m = {50.0, 0.0};
  spectator.velocity_mps = {10.0, 0.0};
  world.bodies.push_back(spectator);
  return world;
}

// The same scene reflected in x = 0: the wall on the right.
WorldDef reflected(WorldDef world) {
  for (WallDef& wall : world.walls) {
    wall.point_m.x() = -wall.point_m.x();
    wall.normal.x() = -wall.normal.x();
  }
  for (BodyDef& body : world.bodies) {
    body.position_m.x() = -body.position_m.x();
    body.velocity_mps.x() = -body.velocity_mps.x();
  }
  return world;
}

// Round-off allowance after n impacts, in units of `scale`: each impact's time and positions are
// a handful of roundings (relative eps each) of quantities no larger than the scale, and the
// errors of successive impacts add at most linearly.
double roundOff(std::int64_t impacts, double scale) {
  return 16.0 * kRoundingUnit * static_cast<double>(impacts + 1) * scale;
}

// pi-blocks with d digits (reflected: the wall on the right), run by both loops.
void expectSameRun(int digits, bool reflect, bool events) {
  const std::string what = "digits " + std::to_string(digits) + (reflect ? ", reflected" : "");
  const WorldDef world = piBlocksWorld(digits);
  WorldDef fast_world = reflect ? reflected(world) : world;
  WorldDef general_world = reflect ? reflected(withSpectator(world)) : withSpectator(world);
  fast_world.max_recorded_collisions = general_world.max_recorded_collisions =
      events ? piCount(digits) : 0;
  const Timeline fast = simulate(fast_world), general = simulate(general_world);
  const std::int64_t n = piCount(digits);
  ASSERT_EQ(fast.collisionCount(), n) << what;
  ASSERT_EQ(general.collisionCount(), n) << what;
  const double duration_s = world.duration_s;
  // The blocks stay within 2 * duration * 1 m/s of the start: the largest speed of the big block
  // is 1 m/s, and the small one moves only between the wall and the big one.
  const double extent_m = 2.0 * duration_s;
  if (events) {
    ASSERT_EQ(fast.collisions().size(), general.collisions().size()) << what;
    for (std::size_t k = 0; k < fast.collisions().size(); ++k) {
      const CollisionEvent &a = fast.collisions()[k], &b = general.collisions()[k];
      ASSERT_EQ(a.body_a, b.body_a) << what << " impact " << k;
      ASSERT_EQ(a.body_b, b.body_b) << what << " impact " << k;
      ASSERT_EQ(a.velocity_a_after_mps, b.velocity_a_after_mps) << what << " impact " << k;
      ASSERT_EQ(a.velocity_b_after_mps, b.velocity_b_after_mps) << what << " impact " << k;
      ASSERT_NEAR(a.time_s, b.time_s, roundOff(k, duration_s)) << what << " impact " << k;
    }
  }
  const Snapshot a = fast.sample(duration_s), b = general.sample(duration_s);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(a.bodies[i].velocity_mps, b.bodies[i].velocity_mps) << what << " body " << i;
    EXPECT_NEAR(a.bodies[i].position_m.x(), b.bodies[i].position_m.x(), roundOff(n, extent_m))
        << what << " body " << i;
  }
}

TEST(LineWallPairTest, CountsVelocitiesAndTimesMatchTheGeneralLoop) {
  for (int d = 1; d <= 5; ++d) expectSameRun(d, false, true);
  expectSameRun(6, false, false);
}

TEST(LineWallPairTest, AWallOnTheRightMatchesTheGeneralLoop) {
  for (int d = 1; d <= 4; ++d) expectSameRun(d, true, true);
}

// Body `body`'s velocity after `event` (0 where it took no part). A pair's body_a is the one
// on the left, which reflection swaps.
double velocityAfter(const CollisionEvent& event, int body) {
  if (event.body_a == body) return event.velocity_a_after_mps.x();
  if (event.body_b == body) return event.velocity_b_after_mps.x();
  return 0.0;
}

// Reflection changes nothing but signs: negation is exact, so the reflected run is the same bits.
TEST(LineWallPairTest, TheMirrorImageIsTheSameRunReflected) {
  WorldDef world = piBlocksWorld(5);
  world.max_recorded_collisions = piCount(5);
  const Timeline left = simulate(world), right = simulate(reflected(world));
  ASSERT_EQ(left.collisionCount(), right.collisionCount());
  ASSERT_EQ(left.collisions().size(), right.collisions().size());
  for (std::size_t k = 0; k < left.collisions().size(); ++k) {
    const CollisionEvent &a = left.collisions()[k], &b = right.collisions()[k];
    ASSERT_EQ(a.time_s, b.time_s) << k;
    for (int body = 0; body < 2; ++body) {
      ASSERT_EQ(velocityAfter(a, body), -velocityAfter(b, body)) << k << " body " << body;
    }
  }
  for (double t_s : {1.0, 4.0, 12.0}) {
    const Snapshot a = left.sample(t_s), b = right.sample(t_s);
    for (int i = 0; i < 2; ++i) {
      EXPECT_EQ(a.bodies[i].position_m.x(), -b.bodies[i].position_m.x()) << t_s << " " << i;
      EXPECT_EQ(a.bodies[i].velocity_mps.x(), -b.bodies[i].velocity_mps.x()) << t_s << " " << i;
    }
  }
}

}  // namespace
}  // namespace collide::physics
