// 1D analytic cases: expected values from conservation of momentum and the definition of e.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace {

using testing::block;
using testing::wall;

// Solves m1 v1' + m2 v2' = m1 v1 + m2 v2 and v2' - v1' = -e (v2 - v1) for (v1', v2').
void expectedAfter(double m1, double v1, double m2, double v2, double e, double& v1_after,
                   double& v2_after) {
  const double p = m1 * v1 + m2 * v2;
  const double separation = -e * (v2 - v1);  // v2' - v1'
  v1_after = (p - m2 * separation) / (m1 + m2);
  v2_after = v1_after + separation;
}

class TwoBodyTableTest : public ::testing::TestWithParam<double> {};

TEST_P(TwoBodyTableTest, VelocitiesTimeAndEnergyMatchConservation) {
  const double e = GetParam();
  const double m1 = 2.0, m2 = 3.0, v1 = 4.0, v2 = -1.0, w1 = 0.5, w2 = 1.0;
  WorldDef world;
  world.restitution = e;
  world.duration_s = 3.0;
  world.bodies = {block("a", m1, w1, -2.0, v1), block("b", m2, w2, 3.0, v2)};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const CollisionEvent& hit = timeline.collisions()[0];
  // Gap between faces: 3 - (-2) - (0.25 + 0.5) = 4.25 m, closing at 5 m/s.
  EXPECT_NEAR(hit.time_s, 4.25 / 5.0, 1e-15);
  double v1_after, v2_after;
  expectedAfter(m1, v1, m2, v2, e, v1_after, v2_after);
  EXPECT_NEAR(hit.velocity_a_after_mps.x(), v1_after, 1e-12);
  EXPECT_NEAR(hit.velocity_b_after_mps.x(), v2_after, 1e-12);
  EXPECT_EQ(hit.merged, e == 0.0);
  const double mu = m1 * m2 / (m1 + m2);
  EXPECT_NEAR(hit.energy_lost_analytic_J, 0.5 * mu * (1 - e * e) * 25.0, 1e-12);
  EXPECT_NEAR(hit.energy_lost_J, hit.energy_lost_analytic_J, 1e-12);
  // Sampled state after the impact moves on analytically.
  const Snapshot end = timeline.sample(3.0);
  EXPECT_NEAR(end.bodies[0].velocity_mps.x(), v1_after, 1e-12);
  EXPECT_NEAR(end.bodies[1].position_m.x(), 3.0 + v2 * hit.time_s + v2_after * (3.0 - hit.time_s),
              1e-12);
  EXPECT_NEAR(timeline.momentum(end).x(), m1 * v1 + m2 * v2, 1e-12);
  EXPECT_NEAR(timeline.kineticEnergy(end) + end.energy_lost_J, timeline.initialKineticEnergy(),
              1e-12);
}

INSTANTIATE_TEST_SUITE_P(Restitution, TwoBodyTableTest, ::testing::Values(1.0, 0.5, 0.0));

TEST(LineMergeTest, MergedCompositeHitsWallAsOneBody) {
  // e = 0 between the blocks: one composite of 3 kg at (1*3 + 2*0)/3 = 1 m/s, then an elastic wall.
  WorldDef world;
  world.restitution = 0.0;
  world.duration_s = 10.0;
  world.bodies = {block("a", 1.0, 1.0, 0.0, 3.0), block("b", 2.0, 1.0, 2.0, 0.0)};
  world.walls = {wall("right", {6.0, 0.0}, {-1.0, 0.0}, 1.0)};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 2);
  const CollisionEvent& merge = timeline.collisions()[0];
  EXPECT_TRUE(merge.merged);
  EXPECT_DOUBLE_EQ(merge.velocity_a_after_mps.x(), 1.0);
  EXPECT_DOUBLE_EQ(merge.velocity_b_after_mps.x(), 1.0);
  const CollisionEvent& bounce = timeline.collisions()[1];
  EXPECT_TRUE(bounce.hitsWall());
  EXPECT_EQ(bounce.wallIndex(), 0);
  EXPECT_EQ(bounce.body_a, 1);  // the face that touches the wall
  EXPECT_NEAR(bounce.velocity_a_after_mps.x(), -1.0, 1e-15);
  // Merge at t = 1/3 s (gap 1 m at 3 m/s); b's right face, still at 2.5 m, reaches the wall at
  // 6 m moving at 1 m/s.
  EXPECT_NEAR(bounce.time_s, 1.0 / 3.0 + (6.0 - 2.5) / 1.0, 1e-12);
  const Snapshot end = timeline.sample(10.0);
  EXPECT_DOUBLE_EQ(end.bodies[0].velocity_mps.x(), -1.0);
  EXPECT_NEAR(end.bodies[1].position_m.x() - end.bodies[0].position_m.x(), 1.0, 1e-12);
}

TEST(LineCradleTest, FiveTouchingBallsOneInOneOut) {
  WorldDef world;
  world.duration_s = 2.0;
  world.bodies.push_back(block("in", 1.0, 1.0, -1.0, 1.0));  // 1 m from b1
  for (int k = 1; k < 5; ++k)
    world.bodies.push_back(block(testing::numbered("b", k), 1.0, 1.0, k, 0.0));
  const Timeline timeline = simulate(world);
  EXPECT_EQ(timeline.collisionCount(), 4);
  for (const CollisionEvent& event : timeline.collisions()) EXPECT_DOUBLE_EQ(event.time_s, 1.0);
  const Snapshot end = timeline.sample(2.0);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(end.bodies[k].velocity_mps.x(), 0.0) << k;
  EXPECT_EQ(end.bodies[4].velocity_mps.x(), 1.0);
  EXPECT_NEAR(end.bodies[4].position_m.x(), 4.0 + 1.0, 1e-15);
}

TEST(LineContactTest, BlockAtRestAgainstAnotherPassesTheHitOn) {
  // b rests touching c (2 kg); a (1 kg) hits b. Sequential impacts, all elastic: a and b (equal)
  // swap, so b takes 2 m/s and hits c at once; b bounces back with vb < 0 into a, which is still
  // touching it, and equal masses swap again: a ends with vb, b at rest, c with vc.
  WorldDef world;
  world.duration_s = 1.0;
  world.bodies = {block("a", 1.0, 1.0, -1.5, 2.0), block("b", 1.0, 1.0, 0.0, 0.0),
                  block("c", 2.0, 1.0, 1.0, 0.0)};
  const Timeline timeline = simulate(world);
  EXPECT_EQ(timeline.collisionCount(), 3);
  const Snapshot end = timeline.sample(1.0);
  double vb, vc;
  expectedAfter(1.0, 2.0, 2.0, 0.0, 1.0, vb, vc);
  EXPECT_NEAR(end.bodies[0].velocity_mps.x(), vb, 1e-15);
  EXPECT_NEAR(end.bodies[1].velocity_mps.x(), 0.0, 1e-15);
  EXPECT_NEAR(end.bodies[2].velocity_mps.x(), vc, 1e-15);
  EXPECT_NEAR(timeline.momentum(end).x(), 2.0, 1e-12);
  EXPECT_NEAR(timeline.kineticEnergy(end), 2.0, 1e-12);
}

TEST(LineContactTest, ThreeBodiesMeetingAtOneInstantComeOutSymmetric) {
  WorldDef world;
  world.duration_s = 2.0;
  world.bodies = {block("a", 1.0, 1.0, -2.0, 1.0), block("b", 1.0, 1.0, 0.0, 0.0),
                  block("c", 1.0, 1.0, 2.0, -1.0)};
  const Timeline timeline = simulate(world);
  for (const CollisionEvent& event : timeline.collisions()) EXPECT_DOUBLE_EQ(event.time_s, 1.0);
  const Snapshot end = timeline.sample(2.0);
  EXPECT_EQ(end.bodies[0].velocity_mps.x(), -1.0);
  EXPECT_EQ(end.bodies[1].velocity_mps.x(), 0.0);
  EXPECT_EQ(end.bodies[2].velocity_mps.x(), 1.0);
}

TEST(LineContactTest, NoTunnellingAtAnySpeed) {
  // A block at 1e6 m/s between walls 1 m apart: 1e6 bounces per second, none missed.
  WorldDef world;
  world.duration_s = 1e-3;
  world.bodies = {block("fast", 1.0, 0.1, 0.5, 1e6)};
  world.walls = {wall("left", {0.0, 0.0}, {1.0, 0.0}), wall("right", {1.0, 0.0}, {-1.0, 0.0})};
  const Timeline timeline = simulate(world);
  // Free travel 0.9 m per bounce: 1e6 * 1e-3 = 1000 m of travel. The first wall is 0.45 m away.
  EXPECT_EQ(timeline.collisionCount(), static_cast<std::int64_t>((1000.0 - 0.45) / 0.9) + 1);
  for (int k = 0; k <= 1000; ++k) {
    const Snapshot s = timeline.sample(k * 1e-6);
    EXPECT_GE(s.bodies[0].position_m.x(), 0.05 - 1e-9);
    EXPECT_LE(s.bodies[0].position_m.x(), 0.95 + 1e-9);
  }
}

TEST(LineGravityTest, BouncingBlockReboundsByESquaredWithExactFlightTimes) {
  // A block dropped from rest, its lower face h above a floor, g = 9.81 along -x.
  const double g = 9.81, h = 2.0, e = 0.8, half = 0.05;
  WorldDef world;
  world.gravity_mps2 = {-g, 0.0};
  world.duration_s = 4.0;
  world.bodies = {block("ball", 1.0, 2 * half, h + half, 0.0)};
  world.walls = {wall("floor", {0.0, 0.0}, {1.0, 0.0}, e)};
  const Timeline timeline = simulate(world);
  ASSERT_GE(timeline.collisionCount(), 4);
  double t = std::sqrt(2.0 * h / g), u = g * t, height = h;
  for (int k = 0; k < 4; ++k) {
    const CollisionEvent& hit = timeline.collisions()[k];
    EXPECT_NEAR(hit.time_s, t, 1e-12 * (k + 1)) << k;
    EXPECT_NEAR(hit.closing_speed_mps, u, 1e-11) << k;
    EXPECT_NEAR(hit.velocity_a_after_mps.x(), e * u, 1e-11) << k;
    // Apex of the next flight: (e u)^2 / 2g = e^2 * previous height.
    const double apex_t = t + e * u / g;
    const Snapshot apex = timeline.sample(apex_t);
    EXPECT_NEAR(apex.bodies[0].position_m.x() - half, e * e * height, 1e-10) << k;
    EXPECT_NEAR(apex.bodies[0].velocity_mps.x(), 0.0, 1e-10) << k;
    height *= e * e;
    t += 2.0 * e * u / g;
    u *= e;
  }
  // Mechanical energy plus the losses stays the initial one.
  const Snapshot mid = timeline.sample(1.234);
  EXPECT_NEAR(timeline.mechanicalEnergy(mid) + mid.energy_lost_J,
              timeline.mechanicalEnergy(timeline.sample(0.0)), 1e-10);
}

TEST(LineGravityTest, InelasticBounceSeriesEndsAtRestInFiniteTime) {
  // With e < 1 the bounces form a geometric series (Zeno): total time t0 (1 + e) / (1 - e).
  const double g = 9.81, h = 1.0, e = 0.5, half = 0.05;
  WorldDef world;
  world.gravity_mps2 = {-g, 0.0};
  world.duration_s = 10.0;
  world.bodies = {block("ball", 1.0, 2 * half, h + half, 0.0)};
  world.walls = {wall("floor", {0.0, 0.0}, {1.0, 0.0}, e)};
  const Timeline timeline = simulate(world);
  EXPECT_EQ(timeline.status(), SimulationStatus::kComplete);
  EXPECT_LT(timeline.collisionCount(), 100);
  const double t0 = std::sqrt(2.0 * h / g);
  const CollisionEvent& last = timeline.collisions().back();
  EXPECT_TRUE(last.merged);  // came to rest on the floor
  // The run lets the body rest once a rebound would rise less than 1e-10 m; the flights left out
  // of the series from there sum to at most 2 sqrt(2 h / g) / (1 - e).
  const double cut = 2.0 * std::sqrt(2.0 * 1e-10 / g) / (1 - e);
  EXPECT_NEAR(last.time_s, t0 * (1 + e) / (1 - e), cut);
  const Snapshot end = timeline.sample(10.0);
  EXPECT_NEAR(end.bodies[0].position_m.x(), half, 1e-12);
  EXPECT_EQ(end.bodies[0].velocity_mps.x(), 0.0);
  EXPECT_NEAR(end.energy_lost_J, 1.0 * g * h, 1e-9);
}

TEST(LineCollapseTest, CollapseProneChainFinishes) {
  // Blocks with e = 0.05 driven into a wall: without the collapse rule the rattling would never
  // end; with it the run finishes, momentum is exchanged only with the wall and KE never grows.
  WorldDef world;
  world.restitution = 0.05;
  world.duration_s = 20.0;
  for (int k = 0; k < 6; ++k)
    world.bodies.push_back(
        block(testing::numbered("b", k), 1.0 + k % 2, 0.5, 1.0 + k, -1.0 - 0.1 * k));
  world.walls = {wall("wall", {0.0, 0.0}, {1.0, 0.0}, 0.05)};
  const Timeline timeline = simulate(world);
  EXPECT_EQ(timeline.status(), SimulationStatus::kComplete);
  double previous = timeline.initialKineticEnergy();
  for (int k = 0; k <= 200; ++k) {
    const Snapshot s = timeline.sample(0.1 * k);
    const double ke = timeline.kineticEnergy(s);
    EXPECT_LE(ke, previous * (1 + 1e-12) + 1e-15) << k;
    previous = ke;
  }
}

TEST(LineMergeTest, ExtremeMassRatioMergeKeepsMomentum) {
  // 1e-6 kg at 1e4 m/s sticks to 1e9 kg at -1e-6 m/s (mass ratio 1e15). The common velocity is
  // total momentum over total mass; rounding of that quotient is a few ulps of it, so momentum
  // holds to a few ulps of the larger momentum (1e3 kg m/s): 1e-14 of it is about 45 ulps.
  const double m1 = 1e-6, v1 = 1e4, m2 = 1e9, v2 = -1e-6;
  WorldDef world;
  world.restitution = 0.0;
  world.duration_s = 1.0;
  world.bodies = {block("light", m1, 1.0, 0.0, v1), block("heavy", m2, 1.0, 2.0, v2)};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const double p = m1 * v1 + m2 * v2;
  const double v = p / (m1 + m2);
  const Snapshot end = timeline.sample(1.0);
  EXPECT_NEAR(end.bodies[0].velocity_mps.x(), v, 4e-16 * std::abs(v));
  EXPECT_NEAR(end.bodies[1].velocity_mps.x(), v, 4e-16 * std::abs(v));
  EXPECT_NEAR(timeline.momentum(end).x(), p, 1e-14 * (m1 * std::abs(v1) + m2 * std::abs(v2)));
}

TEST(LineCapTest, CollisionCapStopsTheRunWithAWarning) {
  WorldDef world = WorldDef{};
  world.duration_s = 1.0;
  world.max_collisions = 50;
  world.bodies = {block("fast", 1.0, 0.1, 0.5, 1000.0)};
  world.walls = {wall("left", {0.0, 0.0}, {1.0, 0.0}), wall("right", {1.0, 0.0}, {-1.0, 0.0})};
  const Timeline timeline = simulate(world);
  EXPECT_EQ(timeline.collisionCount(), 50);
  EXPECT_EQ(timeline.status(), SimulationStatus::kCollisionCapReached);
  ASSERT_FALSE(timeline.warnings().empty());
  EXPECT_EQ(timeline.warnings().back().kind, WarningKind::kCollisionCap);
  EXPECT_LT(timeline.simulatedUntil_s(), 1.0);
}

}  // namespace
}  // namespace collide::physics
