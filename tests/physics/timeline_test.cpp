// Timeline: exact sampling through checkpoints, replay, and the event log.
#include <gtest/gtest.h>

#include "physics/pi_blocks.hpp"
#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace {

void expectSameSnapshot(const Snapshot& a, const Snapshot& b) {
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  EXPECT_EQ(a.collision_count, b.collision_count);
  EXPECT_EQ(a.energy_lost_J, b.energy_lost_J);
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    EXPECT_EQ(a.bodies[i].position_m, b.bodies[i].position_m) << i;
    EXPECT_EQ(a.bodies[i].velocity_mps, b.bodies[i].velocity_mps) << i;
  }
}

TEST(TimelineTest, SamplingThroughSparseCheckpointsIsBitIdentical) {
  // Same world, once with a checkpoint per collision and once with a tiny checkpoint budget that
  // forces re-simulation from sparse checkpoints.
  WorldDef dense = piBlocksWorld(4);
  WorldDef sparse = dense;
  sparse.max_keyframe_bytes = 1;  // the floor of 64 checkpoints applies
  const Timeline a = simulate(dense), b = simulate(sparse);
  ASSERT_EQ(a.collisionCount(), b.collisionCount());
  for (int k = 0; k <= 240; ++k) expectSameSnapshot(a.sample(0.05 * k), b.sample(0.05 * k));
}

TEST(TimelineTest, SampleAtACollisionTimeGivesTheStateAfterIt) {
  WorldDef world;
  world.duration_s = 2.0;
  world.bodies = {testing::block("a", 1.0, 1.0, -1.0, 1.0),
                  testing::block("b", 1.0, 1.0, 1.0, 0.0)};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const Snapshot at = timeline.sample(timeline.collisions()[0].time_s);
  EXPECT_EQ(at.collision_count, 1);
  EXPECT_EQ(at.bodies[1].velocity_mps.x(), 1.0);
}

TEST(TimelineTest, ReplayStreamsEveryCollisionBeyondTheStoredOnes) {
  WorldDef world = piBlocksWorld(4);
  world.max_recorded_collisions = 100;
  const Timeline timeline = simulate(world);
  EXPECT_EQ(timeline.collisions().size(), 100u);
  EXPECT_TRUE(timeline.collisionsTruncated());
  std::int64_t seen = 0;
  double lost = 0.0;
  timeline.replayCollisions([&](const CollisionEvent& event) {
    EXPECT_EQ(event.index, seen);
    if (seen < 100) {
      EXPECT_EQ(event.time_s, timeline.collisions()[seen].time_s);
      EXPECT_EQ(event.velocity_a_after_mps, timeline.collisions()[seen].velocity_a_after_mps);
    }
    lost += event.energy_lost_J;
    ++seen;
  });
  EXPECT_EQ(seen, timeline.collisionCount());
  EXPECT_EQ(lost, timeline.totalEnergyLost());
}

TEST(TimelineTest, WallPartnersAreNamedThroughTheWorld) {
  WorldDef world;
  world.duration_s = 1.0;
  world.bodies = {testing::block("a", 1.0, 0.2, 0.5, -1.0)};
  world.walls = {testing::wall("floor", {0.0, 0.0}, {1.0, 0.0}, 0.5)};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const CollisionEvent& hit = timeline.collisions()[0];
  ASSERT_TRUE(hit.hitsWall());
  EXPECT_EQ(timeline.world().walls[hit.wallIndex()].name, "floor");
  EXPECT_EQ(hit.normal, core::Vec2(-1.0, 0.0));  // from the block towards the wall
  EXPECT_EQ(hit.restitution, 0.5);
  EXPECT_EQ(hit.velocity_a_after_mps.x(), 0.5);
  EXPECT_NEAR(hit.energy_lost_J, 0.5 * 1.0 * (1 - 0.25) * 1.0, 1e-15);
}

// A block 1 m wide at x = 5 m moving at 10 m/s between walls at 0 and 10 m hits the right wall at
// t = 0.45 s, the left at 1.35 s and the right again at 2.25 s. The collision cap stops the run
// after those three; frames are still asked for up to the 10 s duration, and must show the state
// the simulation reached, not a block carried on through the left wall (at -68 m by t = 10 s).
TEST(TimelineTest, SamplesPastAnEarlyStopHoldTheLastSimulatedState) {
  WorldDef world;
  world.duration_s = 10.0;
  world.max_collisions = 3;
  world.bodies = {testing::block("a", 1.0, 1.0, 5.0, 10.0)};
  world.walls = {testing::wall("left", {0.0, 0.0}, {1.0, 0.0}),
                 testing::wall("right", {10.0, 0.0}, {-1.0, 0.0})};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.status(), SimulationStatus::kCollisionCapReached);
  ASSERT_EQ(timeline.collisionCount(), 3);
  EXPECT_NEAR(timeline.simulatedUntil_s(), 2.25, 1e-15);
  const Snapshot stop = timeline.sample(timeline.simulatedUntil_s());
  EXPECT_NEAR(stop.bodies[0].position_m.x(), 9.5, 1e-14);
  EXPECT_EQ(stop.bodies[0].velocity_mps.x(), -10.0);
  for (double t : {2.5, 5.0, 10.0, 20.0}) {
    const Snapshot held = timeline.sample(t);
    EXPECT_EQ(held.time_s, timeline.simulatedUntil_s()) << t;
    expectSameSnapshot(held, stop);
  }
}

TEST(TimelineTest, InitialStateIsBeforeAnImpactDueAtTimeZero) {
  // Touching and approaching at t = 0: 1 kg at 2 m/s against 1 kg at rest, e = 0.5. The impact
  // is at t = 0; sample(0) shows the state after it (0.5 and 1.5 m/s), initialState() the
  // conditions as given, with 1/2 1 2^2 = 2 J.
  WorldDef world;
  world.restitution = 0.5;
  world.duration_s = 1.0;
  world.bodies = {testing::block("a", 1.0, 0.5, 0.0, 2.0), testing::block("b", 1.0, 0.5, 0.5, 0.0)};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  EXPECT_EQ(timeline.collisions()[0].time_s, 0.0);
  const Snapshot initial = timeline.initialState();
  EXPECT_EQ(initial.time_s, 0.0);
  EXPECT_EQ(initial.collision_count, 0);
  EXPECT_EQ(initial.energy_lost_J, 0.0);
  EXPECT_EQ(initial.bodies[0].velocity_mps.x(), 2.0);
  EXPECT_EQ(initial.bodies[1].velocity_mps.x(), 0.0);
  EXPECT_EQ(timeline.initialKineticEnergy(), 2.0);
  const Snapshot after = timeline.sample(0.0);
  EXPECT_EQ(after.collision_count, 1);
  EXPECT_NEAR(after.bodies[0].velocity_mps.x(), 0.5, 1e-15);
  EXPECT_NEAR(after.bodies[1].velocity_mps.x(), 1.5, 1e-15);
  // Loss 1/2 mu (1 - e^2) u^2 = 0.5 * 0.5 * 0.75 * 4 = 0.75 J.
  EXPECT_NEAR(after.energy_lost_J, 0.75, 1e-15);
}

}  // namespace
}  // namespace collide::physics
