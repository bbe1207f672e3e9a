// Timeline::sample gives the same state at a time whatever was sampled before it. Frames sample
// in order, and the timeline carries on the re-simulation an earlier sample left behind where
// that costs less than a new one from the checkpoint (physics/sample_cursors.hpp); a time asked
// for after a later one always starts from its checkpoint. So the reference here is sampling
// from the end backwards: every state is then re-simulated from its own checkpoint, as every
// sample was before the engines were kept. Each world keeps few checkpoints (the floor of 64),
// so that most samples have events to re-simulate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

#include "physics/pi_blocks.hpp"
#include "physics/simulate.hpp"
#include "random_scenes.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace {

using testing::disk;
using testing::numbered;

// 64 disks in a box, e = 1: enough for the 2D engine's grid of cells (from 32 disks).
WorldDef gas() {
  WorldDef world;
  world.dimensions = 2;
  world.duration_s = 2.0;
  world.walls = testing::boxWalls(1.0);
  testing::Dice dice(5);
  for (int k = 0; k < 64; ++k) {
    const core::Vec2 centre(-0.875 + 0.25 * (k % 8), -0.875 + 0.25 * (k / 8));
    world.bodies.push_back(disk(numbered("d", k), 0.01, 0.05, centre,
                                {dice.uniform(-2.0, 2.0), dice.uniform(-2.0, 2.0)}));
  }
  return world;
}

// Five touching balls on strings, two pulled aside, e = 0.9, for 30 s: impacts, and strings
// going slack.
WorldDef cradle() {
  WorldDef world;
  world.dimensions = 2;
  world.gravity_mps2 = {0.0, -9.81};
  world.duration_s = 30.0;
  world.restitution = 0.9;  // the balls fall out of step: impacts spread over each swing
  for (int k = 0; k < 5; ++k) {
    const core::Vec2 pivot(0.1 * k, 1.0);
    const double angle = k < 2 ? -0.6 : 0.0;
    BodyDef body = disk(numbered("b", k), 1.0, 0.05,
                        pivot + 0.8 * core::Vec2(std::sin(angle), -std::cos(angle)), {0.0, 0.0});
    body.on_string = true;
    body.pivot_m = pivot;
    world.bodies.push_back(body);
  }
  return world;
}

// Three disks in a small box for 12 s, soft contacts (a spring and damper, 10 ms each).
WorldDef softBox() {
  WorldDef world;
  world.dimensions = 2;
  world.duration_s = 12.0;
  world.restitution = 0.9;
  world.contact_model = ContactModel::kSpringDamper;
  world.walls = testing::boxWalls(0.5);
  world.bodies = {disk("s0", 1.0, 0.1, {-0.2, -0.1}, {2.0, 1.0}),
                  disk("s1", 2.0, 0.15, {0.2, 0.1}, {-1.0, 1.5}),
                  disk("s2", 0.5, 0.08, {0.0, 0.3}, {1.5, -2.0})};
  return world;
}

// Worlds of every engine (1D, 2D with and without its grid, strings, soft contacts) with enough
// collisions that most samples re-simulate some.
std::vector<WorldDef> worlds() {
  std::vector<WorldDef> out = {gas(), cradle(), softBox(), piBlocksWorld(4)};
  // Random lines and planes with at least 100 collisions: merges, walls, gravity, stuck
  // clusters.
  testing::Dice dice(23);
  int lines = 0, planes = 0;
  while (lines < 4 || planes < 4) {
    testing::SceneTraits traits;
    const bool line = lines < 4;
    WorldDef world = line ? testing::randomLine(dice, traits) : testing::randomPlane(dice, traits);
    if (simulate(world).collisionCount() < 100) continue;
    ++(line ? lines : planes);
    out.push_back(std::move(world));
  }
  for (WorldDef& world : out) world.max_keyframe_bytes = 1;
  return out;
}

void expectSameSnapshot(const Snapshot& a, const Snapshot& b, const char* order, double t_s) {
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  EXPECT_EQ(a.time_s, b.time_s) << order << " t " << t_s;
  EXPECT_EQ(a.collision_count, b.collision_count) << order << " t " << t_s;
  EXPECT_EQ(a.energy_lost_J, b.energy_lost_J) << order << " t " << t_s;
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    EXPECT_EQ(a.bodies[i].position_m, b.bodies[i].position_m) << order << " t " << t_s << " " << i;
    EXPECT_EQ(a.bodies[i].velocity_mps, b.bodies[i].velocity_mps) << order << " t " << t_s;
    EXPECT_EQ(a.bodies[i].angle_rad, b.bodies[i].angle_rad) << order << " t " << t_s;
    EXPECT_EQ(a.bodies[i].angular_velocity_radps, b.bodies[i].angular_velocity_radps)
        << order << " t " << t_s;
  }
}

constexpr int kSamples = 240;

double timeOf(const Timeline& timeline, int k) {
  return timeline.duration_s() * k / kSamples;
}

// Each state re-simulated from its own checkpoint: sampled from the end backwards.
std::vector<Snapshot> backwards(const Timeline& timeline) {
  std::vector<Snapshot> states(kSamples + 1);
  for (int k = kSamples; k >= 0; --k) states[k] = timeline.sample(timeOf(timeline, k));
  return states;
}

TEST(SampleOrderTest, SamplingForwardsGivesTheStatesOfSamplingBackwards) {
  for (const WorldDef& world : worlds()) {
    const Timeline timeline = simulate(world);
    SCOPED_TRACE(world.bodies.front().name + ", " + std::to_string(world.bodies.size()) +
                 " bodies, " + std::to_string(timeline.collisionCount()) + " collisions");
    const std::vector<Snapshot> reference = backwards(timeline);
    for (int k = 0; k <= kSamples; ++k) {
      expectSameSnapshot(timeline.sample(timeOf(timeline, k)), reference[k], "forwards",
                         timeOf(timeline, k));
    }
    // A frame that asks for the start and for now, then a trail of earlier times up to now.
    for (int k = 0; k <= kSamples; k += 3) {
      expectSameSnapshot(timeline.sample(0.0), reference[0], "start", 0.0);
      for (int j = std::max(k - 4, 0); j <= k; ++j) {
        expectSameSnapshot(timeline.sample(timeOf(timeline, j)), reference[j], "trail",
                           timeOf(timeline, j));
      }
    }
  }
}

TEST(SampleOrderTest, TwoThreadsSamplingAtOnceGetTheSameStates) {
  const Timeline timeline = simulate(worlds().front());
  const std::vector<Snapshot> reference = backwards(timeline);
  std::vector<Snapshot> got[2];
  auto sweep = [&](int which) {
    for (int k = 0; k <= kSamples; ++k) got[which].push_back(timeline.sample(timeOf(timeline, k)));
  };
  std::thread other(sweep, 1);
  sweep(0);
  other.join();
  for (int which : {0, 1}) {
    for (int k = 0; k <= kSamples; ++k) {
      expectSameSnapshot(got[which][k], reference[k], "thread", timeOf(timeline, k));
    }
  }
}

}  // namespace
}  // namespace collide::physics
