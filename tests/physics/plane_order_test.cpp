// Simultaneous impacts in 2D that go pair by pair (a perfectly inelastic contact, a stuck
// cluster, a soft contact, more contacts than the simultaneous solver takes) must not depend on
// body numbering either: they go in the order of their contact points (docs/physics.md), so every
// renumbering of the bodies ends in the same states, renumbered.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace {

using testing::disk;

constexpr double kRenumberedTolerance = 1e-12;

// Two 1 kg disks striking a 2 kg disk at one instant from either side of the x axis (the
// glancing pair of plane_simultaneous_test.cpp), with restitution e.
WorldDef twoStrikeOne(double e) {
  WorldDef world;
  world.dimensions = 2;
  world.restitution = e;
  world.duration_s = 3.0;
  world.bodies = {disk("A", 1.0, 0.5, {-2.0, 0.8}, {1.0, 0.0}),
                  disk("B", 1.0, 0.5, {-2.0, -0.8}, {1.0, 0.0}),
                  disk("C", 2.0, 0.5, {0.0, 0.0}, {0.0, 0.0})};
  return world;
}

// Twelve disks on the x axis whose eleven gaps of 1 m all close at t = 1 s (disk k at 2k m
// moving at -k m/s): one group of eleven contacts, beyond the simultaneous solver's ten.
WorldDef rowClosingAtOnce() {
  WorldDef world;
  world.dimensions = 2;
  world.restitution = 0.5;
  world.duration_s = 2.0;
  for (int k = 0; k < 12; ++k) {
    char name[8];
    std::snprintf(name, sizeof name, "d%d", k);  // (GCC 12 warns falsely on "d" + to_string)
    world.bodies.push_back(disk(name, 1.0 + 0.25 * (k % 3), 0.5, {2.0 * k, 0.0}, {-1.0 * k, 0.0}));
  }
  return world;
}

// Simulates `world` and its renumberings and compares each body's end state.
void expectRenumberingChangesNothing(const WorldDef& world, const std::string& what) {
  const Timeline reference_run = simulate(world);
  ASSERT_GT(reference_run.collisionCount(), 0) << what;
  const Snapshot reference = reference_run.sample(world.duration_s);
  const int n = static_cast<int>(world.bodies.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::mt19937 dice(15);
  for (int trial = 0; trial < 6; ++trial) {
    if (trial == 0) {
      std::reverse(order.begin(), order.end());
    } else {
      std::shuffle(order.begin(), order.end(), dice);
    }
    WorldDef renumbered = world;
    for (int k = 0; k < n; ++k) renumbered.bodies[k] = world.bodies[order[k]];
    const Snapshot end = simulate(renumbered).sample(world.duration_s);
    for (int k = 0; k < n; ++k) {
      SCOPED_TRACE(what + ", body " + world.bodies[order[k]].name);
      const BodyState& expected = reference.bodies[order[k]];
      EXPECT_NEAR(end.bodies[k].position_m.x(), expected.position_m.x(), kRenumberedTolerance);
      EXPECT_NEAR(end.bodies[k].position_m.y(), expected.position_m.y(), kRenumberedTolerance);
      EXPECT_NEAR(end.bodies[k].velocity_mps.x(), expected.velocity_mps.x(), kRenumberedTolerance);
      EXPECT_NEAR(end.bodies[k].velocity_mps.y(), expected.velocity_mps.y(), kRenumberedTolerance);
      EXPECT_NEAR(end.bodies[k].angular_velocity_radps, expected.angular_velocity_radps,
                  kRenumberedTolerance);
    }
  }
}

TEST(PlaneOrderTest, PerfectlyInelasticContactsAtOnce) {
  expectRenumberingChangesNothing(twoStrikeOne(0.0), "e = 0, slip");
}

TEST(PlaneOrderTest, StuckClustersFormingAtOnce) {
  WorldDef world = twoStrikeOne(0.0);
  world.inelastic_mode = InelasticMode::kStick;
  expectRenumberingChangesNothing(world, "e = 0, stick");
}

TEST(PlaneOrderTest, SoftContactsAtOnce) {
  WorldDef world = twoStrikeOne(0.5);
  world.contact_model = ContactModel::kSpringDamper;
  world.contact_duration_s = 0.05;
  expectRenumberingChangesNothing(world, "soft contacts");
}

TEST(PlaneOrderTest, MoreContactsThanTheSolverTakes) {
  expectRenumberingChangesNothing(rowClosingAtOnce(), "eleven contacts");
}

}  // namespace
}  // namespace collide::physics
