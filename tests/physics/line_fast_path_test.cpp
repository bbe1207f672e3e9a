// The 1D engine's fast path for two elastic bodies (line_two_bodies.cpp) must give the general
// loop's bits: it takes over once no event is recorded any more, so a run recorded in full (the
// general loop throughout) and a run recorded not at all (the fast path throughout) must end in
// the same state, collision for collision.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "physics/pi_blocks.hpp"
#include "physics/simulate.hpp"

namespace collide::physics {
namespace {

BodyDef block(const char* name, double mass_kg, double size_m, double x_m, double v_mps) {
  BodyDef body;
  body.name = name;
  body.mass_kg = mass_kg;
  body.size_m = size_m;
  body.position_m = {x_m, 0.0};
  body.velocity_mps = {v_mps, 0.0};
  return body;
}

WallDef wall(const char* name, double x_m, double normal_x) {
  return WallDef{name, {x_m, 0.0}, {normal_x, 0.0}, 1.0};
}

// Runs `world` twice, recording every event and none, and compares the ends bit for bit.
void expectSameBits(WorldDef world, const std::string& what) {
  world.max_recorded_collisions = 0;
  const Timeline fast = simulate(world);
  world.max_recorded_collisions = fast.collisionCount() + 1;
  const Timeline general = simulate(world);
  ASSERT_GT(fast.collisionCount(), 0) << what;
  EXPECT_EQ(fast.collisionCount(), general.collisionCount()) << what;
  const Snapshot a = fast.sample(world.duration_s), b = general.sample(world.duration_s);
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    EXPECT_EQ(a.bodies[i].position_m.x(), b.bodies[i].position_m.x()) << what << " body " << i;
    EXPECT_EQ(a.bodies[i].velocity_mps.x(), b.bodies[i].velocity_mps.x()) << what << " body " << i;
  }
}

TEST(LineFastPathTest, PiBlocksEndInTheGeneralLoopsState) {
  expectSameBits(piBlocksWorld(5), "pi-blocks, 5 digits");
}

TEST(LineFastPathTest, TwoWallsAndUnequalMasses) {
  WorldDef world;
  world.dimensions = 1;
  world.restitution = 1.0;
  world.duration_s = 40.0;
  world.walls = {wall("left", 0.0, 1.0), wall("right", 5.0, -1.0)};
  world.bodies = {block("a", 1.0, 0.3, 1.0, 0.7), block("b", 7.0, 0.5, 3.0, -0.45)};
  expectSameBits(world, "a box");
}

// A block struck by the wall and by its neighbour at one instant: the round that resolves them
// as one system. Every number is exact in binary, so both impacts fall at t = 1 exactly: the
// light block's left face reaches the wall (from 1.0 m at 1 m/s) as the heavy one closes the
// 1.0 m gap at 2 - 1 m/s.
TEST(LineFastPathTest, ABlockStruckFromBothSidesAtOnce) {
  WorldDef world;
  world.dimensions = 1;
  world.restitution = 1.0;
  world.duration_s = 30.0;
  world.walls = {wall("left", 0.0, 1.0)};
  world.bodies = {block("light", 1.0, 0.5, 1.25, -1.0), block("heavy", 3.0, 1.0, 3.0, -2.0)};
  expectSameBits(world, "left wall");
  // The mirror image, against a wall on the right.
  world.walls = {wall("right", 0.0, -1.0)};
  world.bodies = {block("heavy", 3.0, 1.0, -3.0, 2.0), block("light", 1.0, 0.5, -1.25, 1.0)};
  expectSameBits(world, "right wall");
}

}  // namespace
}  // namespace collide::physics
