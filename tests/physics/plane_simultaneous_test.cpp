// Simultaneous impacts in 2D: disks that strike one disk at the same instant are resolved as one
// system (docs/physics.md), so a mirror-symmetric scene stays mirror-symmetric and renumbering the
// disks changes nothing. Expected numbers come from momentum and the definition of e along each
// contact normal, solved by hand below.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace {

using testing::disk;

constexpr double kTolerance = 1e-12;

// Disks of 1, 2 and 1 kg (radius 0.5 m) on the x axis, the outer ones meeting the middle one at
// the same instant at 1 m/s, e = 0.5. Both contacts share the middle disk: with n = +x for both,
// the Delassus matrix is [[1/1 + 1/2, -1/2], [-1/2, 1/2 + 1/1]] and by symmetry J_left = J_right
// = J with (1.5 - 0.5) J = (1 + e) 1 m/s, so J = 1.5 N s: the outer disks leave at -0.5 and
// +0.5 m/s, the middle one stays at rest; each contact separates at 0.5 = e times 1 m/s, and the
// loss is 2 * 1/2 J (1 - e) u = 0.75 J.
TEST(PlaneSimultaneousTest, SymmetricMeetingOnALineIsSymmetric) {
  WorldDef world;
  world.dimensions = 2;
  world.restitution = 0.5;
  world.duration_s = 2.0;
  world.bodies = {disk("left", 1.0, 0.5, {-2.0, 0.0}, {1.0, 0.0}),
                  disk("middle", 2.0, 0.5, {0.0, 0.0}, {0.0, 0.0}),
                  disk("right", 1.0, 0.5, {2.0, 0.0}, {-1.0, 0.0})};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 2);
  const Snapshot end = timeline.sample(2.0);
  EXPECT_NEAR(end.bodies[0].velocity_mps.x(), -0.5, kTolerance);
  EXPECT_NEAR(end.bodies[1].velocity_mps.x(), 0.0, kTolerance);
  EXPECT_NEAR(end.bodies[2].velocity_mps.x(), 0.5, kTolerance);
  for (const BodyState& body : end.bodies) EXPECT_NEAR(body.velocity_mps.y(), 0.0, kTolerance);
  EXPECT_NEAR(timeline.totalEnergyLost(), 0.75, kTolerance);
  for (const CollisionEvent& event : timeline.collisions()) {
    EXPECT_NEAR(event.impulse_Ns, 1.5, kTolerance);
    EXPECT_NEAR(event.energy_lost_J, 0.375, kTolerance);
  }
}

// Disk C (2 kg) at rest at the origin; A and B (1 kg) at (-2, +0.8) and (-2, -0.8) moving at
// (1, 0) m/s, all of radius 0.5 m, e = 0.5. A touches C when its centre is at (-0.6, 0.8), so
// its normal is n_A = (0.6, -0.8) (B's is its mirror image) and its closing speed is
// (1, 0).n_A = 0.6 m/s. By the mirror symmetry J_A = J_B = J, C takes 2 J 0.6 along x, so
// C's normal speed along n_A is 2 J 0.6 / 2 * 0.6 = 0.36 J and A's is 0.6 - J / 1 kg. Newton's
// law, 0.36 J - (0.6 - J) = e 0.6, gives J = 0.6 (1 + e) / 1.36.
WorldDef glancingPair() {
  WorldDef world;
  world.dimensions = 2;
  world.restitution = 0.5;
  world.duration_s = 3.0;
  world.bodies = {disk("A", 1.0, 0.5, {-2.0, 0.8}, {1.0, 0.0}),
                  disk("B", 1.0, 0.5, {-2.0, -0.8}, {1.0, 0.0}),
                  disk("C", 2.0, 0.5, {0.0, 0.0}, {0.0, 0.0})};
  return world;
}

TEST(PlaneSimultaneousTest, TwoDisksStrikingOneAtOnceLeaveItOnTheAxis) {
  const Timeline timeline = simulate(glancingPair());
  ASSERT_EQ(timeline.collisionCount(), 2);
  const double e = 0.5, j = 0.6 * (1.0 + e) / 1.36;
  const core::Vec2 n_a(0.6, -0.8), n_b(0.6, 0.8);
  const core::Vec2 va = core::Vec2(1.0, 0.0) - j * n_a, vb = core::Vec2(1.0, 0.0) - j * n_b;
  const Snapshot end = timeline.sample(3.0);
  EXPECT_NEAR(end.bodies[0].velocity_mps.x(), va.x(), kTolerance);
  EXPECT_NEAR(end.bodies[0].velocity_mps.y(), va.y(), kTolerance);
  EXPECT_NEAR(end.bodies[1].velocity_mps.x(), vb.x(), kTolerance);
  EXPECT_NEAR(end.bodies[1].velocity_mps.y(), vb.y(), kTolerance);
  EXPECT_NEAR(end.bodies[2].velocity_mps.x(), 0.6 * j, kTolerance);
  EXPECT_NEAR(end.bodies[2].velocity_mps.y(), 0.0, kTolerance);
  // Each contact loses 1/2 J (1 - e) u; together they are the drop in kinetic energy.
  EXPECT_NEAR(timeline.totalEnergyLost(), 2.0 * 0.5 * j * (1.0 - e) * 0.6, kTolerance);
  EXPECT_NEAR(timeline.kineticEnergy(timeline.sample(0.0)) - timeline.kineticEnergy(end),
              timeline.totalEnergyLost(), kTolerance);
}

TEST(PlaneSimultaneousTest, RenumberingTheDisksChangesNothing) {
  const WorldDef world = glancingPair();
  const Snapshot reference = simulate(world).sample(3.0);
  // Every order of the three disks.
  const int orders[][3] = {{0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& order : orders) {
    WorldDef renumbered = world;
    for (int k = 0; k < 3; ++k) renumbered.bodies[k] = world.bodies[order[k]];
    const Snapshot end = simulate(renumbered).sample(3.0);
    for (int k = 0; k < 3; ++k) {
      const BodyState& expected = reference.bodies[order[k]];
      EXPECT_NEAR(end.bodies[k].position_m.x(), expected.position_m.x(), kTolerance);
      EXPECT_NEAR(end.bodies[k].position_m.y(), expected.position_m.y(), kTolerance);
      EXPECT_NEAR(end.bodies[k].velocity_mps.x(), expected.velocity_mps.x(), kTolerance);
      EXPECT_NEAR(end.bodies[k].velocity_mps.y(), expected.velocity_mps.y(), kTolerance);
    }
  }
}

}  // namespace
}  // namespace collide::physics
