// Simultaneous impacts: the outcome never depends on body numbering, mirror images give mirror
// results, and a touching row struck at one end is resolved pair by pair as the impulse travels.
// Expected values are computed here from Newton's law at each contact and conservation of momentum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace {

using testing::block;
using testing::wall;

bool collapseWarned(const Timeline& timeline) {
  for (const Warning& warning : timeline.warnings()) {
    if (warning.kind == WarningKind::kCollapseRule) return true;
  }
  return false;
}

// Masses 1, 2, 1 kg; the outer blocks reach the middle one at the same instant from both sides
// at 1 m/s, e = 0.5. Centred on `centre_m` (0 makes the mirror image exact in binary).
WorldDef threeBlocks(double centre_m) {
  WorldDef world;
  world.restitution = 0.5;
  world.duration_s = 2.0;
  world.bodies = {block("left", 1.0, 0.5, centre_m - 1.75, 1.0),
                  block("middle", 2.0, 1.0, centre_m, 0.0),
                  block("right", 1.0, 0.5, centre_m + 1.75, -1.0)};
  return world;
}

TEST(SimultaneousTest, ABlockStruckFromBothSidesAtOnceGivesTheSymmetricOutcome) {
  // Both contacts close at c = 1 m/s and share the middle block. Newton's law at each contact
  // after the impulses J1, J2 (v1' = 1 - J1, v2' = (J1 - J2) / 2, v3' = -1 + J2):
  //   v2' - v1' = e c  and  v3' - v2' = e c
  // i.e. [1.5 -0.5; -0.5 1.5] J = (1 + e) c (1, 1): solved by Cramer's rule.
  const double e = 0.5, c = 1.0;
  const double a11 = 1.5, a12 = -0.5, a21 = -0.5, a22 = 1.5, b = (1.0 + e) * c;
  const double det = a11 * a22 - a12 * a21;
  const double j1 = (b * a22 - a12 * b) / det, j2 = (a11 * b - b * a21) / det;
  const double v1 = 1.0 - j1, v2 = (j1 - j2) / 2.0, v3 = -1.0 + j2;
  for (double centre : {0.0, 5.3, -123.456}) {
    const Timeline timeline = simulate(threeBlocks(centre));
    ASSERT_EQ(timeline.collisionCount(), 2) << centre;
    const Snapshot end = timeline.sample(2.0);
    EXPECT_NEAR(end.bodies[0].velocity_mps.x(), v1, 1e-12) << centre;
    EXPECT_NEAR(end.bodies[1].velocity_mps.x(), v2, 1e-12) << centre;
    EXPECT_NEAR(end.bodies[2].velocity_mps.x(), v3, 1e-12) << centre;
    // Booked: the kinetic energy lost, 1/2 (1 + 0 + 1) - (1/2 v1^2 + v2^2 + 1/2 v3^2).
    const double lost = 1.0 - (0.5 * v1 * v1 + v2 * v2 + 0.5 * v3 * v3);
    EXPECT_NEAR(timeline.totalEnergyLost(), lost, 1e-12) << centre;
    for (const CollisionEvent& event : timeline.collisions()) {
      EXPECT_NEAR(event.impulse_Ns, j1, 1e-12);
      EXPECT_NEAR(event.energy_lost_J, 0.5 * j1 * (1.0 - e) * c, 1e-12);
    }
  }
}

TEST(SimultaneousTest, RenumberingTheBodiesChangesNothing) {
  const WorldDef world = threeBlocks(5.3);
  const Snapshot reference = simulate(world).sample(2.0);
  const int orders[][3] = {{0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& order : orders) {
    WorldDef renumbered = world;
    for (int k = 0; k < 3; ++k) renumbered.bodies[k] = world.bodies[order[k]];
    const Snapshot end = simulate(renumbered).sample(2.0);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(end.bodies[k].velocity_mps.x(), reference.bodies[order[k]].velocity_mps.x(),
                  1e-12);
      EXPECT_NEAR(end.bodies[k].position_m.x(), reference.bodies[order[k]].position_m.x(), 1e-12);
    }
  }
}

TEST(SimultaneousTest, TheMirrorImageOfAWalledSceneGivesTheMirrorResult) {
  // Four blocks between two walls, two of them meeting a resting block from both sides at once:
  // the scene reflected about x = 0 gives the reflected motion at every instant.
  WorldDef world;
  world.restitution = 0.8;
  world.duration_s = 5.0;
  world.bodies = {block("a", 1.0, 0.4, -2.0, 2.0), block("b", 3.0, 0.6, 0.0, 0.0),
                  block("c", 1.0, 0.4, 2.0, -2.0), block("d", 2.0, 0.4, 3.0, 0.5)};
  world.walls = {wall("left", {-4.0, 0.0}, {1.0, 0.0}, 0.9),
                 wall("right", {4.0, 0.0}, {-1.0, 0.0}, 0.9)};
  WorldDef mirrored = world;
  for (BodyDef& body : mirrored.bodies) {
    body.position_m.x() = -body.position_m.x();
    body.velocity_mps.x() = -body.velocity_mps.x();
  }
  for (WallDef& w : mirrored.walls) {
    w.point_m.x() = -w.point_m.x();
    w.normal.x() = -w.normal.x();
  }
  const Timeline original = simulate(world), image = simulate(mirrored);
  ASSERT_EQ(original.collisionCount(), image.collisionCount());
  for (double t : {0.5, 1.0, 2.5, 5.0}) {
    const Snapshot s = original.sample(t), m = image.sample(t);
    for (std::size_t k = 0; k < s.bodies.size(); ++k) {
      EXPECT_NEAR(s.bodies[k].position_m.x(), -m.bodies[k].position_m.x(), 1e-12) << t;
      EXPECT_NEAR(s.bodies[k].velocity_mps.x(), -m.bodies[k].velocity_mps.x(), 1e-12) << t;
    }
  }
}

// Pair-by-pair resolution of a row of equal blocks, computed here: each round, every contact
// closing (v_k > v_k+1) gets the two-body impulse (1 + e) mu (v_k - v_k+1); rounds repeat until
// no contact closes. (In a row struck at one end two closing contacts are never adjacent, which
// the function checks, so each round is a set of independent two-body impacts.)
std::vector<double> pairByPair(std::vector<double> v, double e, int& impacts) {
  impacts = 0;
  for (;;) {
    std::vector<int> closing;
    for (std::size_t k = 0; k + 1 < v.size(); ++k) {
      if (v[k] > v[k + 1]) closing.push_back(static_cast<int>(k));
    }
    if (closing.empty()) return v;
    for (std::size_t i = 0; i + 1 < closing.size(); ++i) {
      EXPECT_NE(closing[i] + 1, closing[i + 1]) << "adjacent closing contacts";
    }
    for (int k : closing) {
      const double impulse = (1.0 + e) * 0.5 * (v[k] - v[k + 1]);  // mu = 1/2 kg
      v[k] -= impulse;
      v[k + 1] += impulse;
      ++impacts;
    }
  }
}

TEST(SimultaneousTest, TouchingRowStruckAtOneEndKeepsDistinctVelocities) {
  // A striker at 1 m/s meets a row of four touching 1 kg blocks (a Newton's cradle on a line).
  for (double e : {0.9, 0.7, 0.5}) {
    WorldDef world;
    world.restitution = e;
    world.duration_s = 1.0;
    world.bodies.push_back(block("striker", 1.0, 0.2, -0.5, 1.0));
    for (int k = 0; k < 4; ++k) {
      world.bodies.push_back(block(testing::numbered("ball", k), 1.0, 0.2, 0.2 * k, 0.0));
    }
    int impacts = 0;
    const std::vector<double> expected = pairByPair({1.0, 0.0, 0.0, 0.0, 0.0}, e, impacts);
    const Timeline timeline = simulate(world);
    EXPECT_FALSE(collapseWarned(timeline)) << e;
    EXPECT_EQ(timeline.collisionCount(), impacts) << e;
    const Snapshot end = timeline.sample(1.0);
    for (std::size_t k = 0; k < expected.size(); ++k) {
      EXPECT_NEAR(end.bodies[k].velocity_mps.x(), expected[k], 1e-12) << "e " << e << " body " << k;
    }
    // Distinct velocities, increasing along the row: nothing glued together.
    for (std::size_t k = 0; k + 1 < expected.size(); ++k) {
      EXPECT_GT(end.bodies[k + 1].velocity_mps.x() - end.bodies[k].velocity_mps.x(), 1e-3)
          << "e " << e << " body " << k;
    }
  }
}

// A light block squeezed between a wall and a heavy block closing at 1 m/s, e = 0.1 everywhere:
// it bounces between them ever faster as the gap closes, impacts without end in a finite time
// (an inelastic collapse). Each cycle takes a fixed share of the heavy block's speed, so the
// velocities fall geometrically; the limit is both blocks at rest against the wall.
WorldDef squeeze(double heavy_kg) {
  WorldDef world;
  world.restitution = 0.1;
  world.duration_s = 4.0;
  world.bodies = {block("light", 1.0, 0.2, 0.5, 0.0), block("heavy", heavy_kg, 0.5, 2.0, -1.0)};
  world.walls = {wall("wall", {0.0, 0.0}, {1.0, 0.0}, 0.1)};
  return world;
}

TEST(SimultaneousTest, ACollapseThatConvergesEndsAtItsLimitWithoutTheGuard) {
  // At 100 kg the velocities reach the round-off of the scene's speed (1 m/s) in a few thousand
  // impacts: the sequence has reached its limit, which is where it ends, without the guard.
  const Timeline timeline = simulate(squeeze(100.0));
  EXPECT_EQ(timeline.status(), SimulationStatus::kComplete);
  EXPECT_FALSE(collapseWarned(timeline)) << timeline.collisionCount();
  const Snapshot end = timeline.sample(4.0);
  const double round_off_mps = 16.0 * std::numeric_limits<double>::epsilon() * 1.0;
  EXPECT_NEAR(end.bodies[0].velocity_mps.x(), 0.0, round_off_mps);
  EXPECT_NEAR(end.bodies[1].velocity_mps.x(), 0.0, round_off_mps);
  // The whole initial kinetic energy, 1/2 100 kg (1 m/s)^2, went into the impacts.
  EXPECT_NEAR(timeline.totalEnergyLost(), 50.0, 1e-12 * 50.0);
  EXPECT_LE(std::abs(timeline.energyLostMeasured() - timeline.totalEnergyLost()),
            timeline.energyLedgerTolerance());
}

TEST(SimultaneousTest, InelasticCollapseTripsTheGuardWithAWarning) {
  // At 1000 kg each cycle takes ten times less of the heavy block's speed: the burst runs past
  // the guard's count long before it converges. The guard must end it, name the partners and
  // the time, and leave the run complete, with the heavy block turned back (or stopped) and the
  // books balanced.
  const Timeline timeline = simulate(squeeze(1000.0));
  EXPECT_EQ(timeline.status(), SimulationStatus::kComplete);
  ASSERT_TRUE(collapseWarned(timeline)) << timeline.collisionCount();
  for (const Warning& warning : timeline.warnings()) {
    if (warning.kind != WarningKind::kCollapseRule) continue;
    EXPECT_NE(warning.message.find("t = "), std::string::npos) << warning.message;
    EXPECT_NE(warning.message.find("\"light\""), std::string::npos) << warning.message;
  }
  const Snapshot end = timeline.sample(4.0);
  EXPECT_GE(end.bodies[1].velocity_mps.x(), 0.0);
  EXPECT_LE(std::abs(timeline.energyLostMeasured() - timeline.totalEnergyLost()),
            timeline.energyLedgerTolerance());
}

}  // namespace
}  // namespace collide::physics
