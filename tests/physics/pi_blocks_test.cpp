// Galperin's blocks: the general 1D engine must count the digits of pi.
#include "physics/pi_blocks.hpp"

#include <gtest/gtest.h>

#include <cstdint>

#include "physics/simulate.hpp"

namespace collide::physics {
namespace {

// The first d digits of pi as an integer, from its decimal expansion 3.14159265...
std::int64_t piDigits(int d) {
  const char* digits = "314159265";
  std::int64_t value = 0;
  for (int k = 0; k < d; ++k) value = 10 * value + (digits[k] - '0');
  return value;
}

TEST(PiBlocksTest, CountsTheDigitsOfPiUpToSeven) {
  for (int d = 1; d <= 7; ++d) {
    const Timeline timeline = simulate(piBlocksWorld(d));
    EXPECT_EQ(timeline.collisionCount(), piDigits(d)) << "digits " << d;
    EXPECT_EQ(timeline.status(), SimulationStatus::kComplete);
  }
}

TEST(PiBlocksTest, EightDigits) {
  const Timeline timeline = simulate(piBlocksWorld(8));
  EXPECT_EQ(timeline.collisionCount(), 31415926);
  // The densest preset stays within the default caps (max_collisions_per_second: all 31.4
  // million collisions fall between t = 1.3 s and 5.03 s, so at most that many in one second).
  EXPECT_EQ(timeline.status(), SimulationStatus::kComplete);
  EXPECT_TRUE(timeline.warnings().empty());
  // Elastic throughout: no energy lost beyond rounding, relative to the big block's 5e13 J
  // (measured: 1.7e-10 of it; the bound is 60x that).
  EXPECT_LT(std::abs(timeline.totalEnergyLost()), 1e-8 * timeline.initialKineticEnergy());
}

TEST(PiBlocksTest, EveryCollisionHappensWithinTheDuration) {
  // A much longer run finds no further collision.
  for (int d = 1; d <= 5; ++d) {
    WorldDef world = piBlocksWorld(d);
    const std::int64_t count = simulate(world).collisionCount();
    world.duration_s = 1000.0;
    EXPECT_EQ(simulate(world).collisionCount(), count) << d;
  }
}

TEST(PiBlocksTest, FinalStateCannotCollideAgain) {
  const Timeline timeline = simulate(piBlocksWorld(4));
  const Snapshot end = timeline.sample(timeline.duration_s());
  const double v_small = end.bodies[0].velocity_mps.x(), v_big = end.bodies[1].velocity_mps.x();
  EXPECT_GE(v_small, 0.0);    // leaving the wall
  EXPECT_GE(v_big, v_small);  // and never catching the big block
  // Momentum is not conserved (the wall pushes) but energy is: 1/2 M 1^2 initially.
  EXPECT_NEAR(timeline.kineticEnergy(end), 0.5 * 1e6, 1e-6);
}

}  // namespace
}  // namespace collide::physics
