// SPDX-License-Identifier: MIT
// Property tests over random table scenes with sliding friction (the random plane scenes of
// property_test.cpp on a level table, rigid contacts, each disk given a kinetic mu): the books
// add up at every sampled instant (kinetic + lost + to the surface = the start), the kinetic
// energy never rises, what went to the surface never falls, the disks' momentum plus the
// surface's is the start's as a vector (no walls), no disk overlaps another or a wall, and the
// mirror image renumbered is the same motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "plane_mirror.hpp"
#include "random_scenes.hpp"
#include "table_checks.hpp"

namespace collide::physics {
namespace plane_friction_property_test {

using testing::Dice;
using testing::SceneTraits;

constexpr int kTableBlocks = 2, kTableScenesPerBlock = 250;
constexpr std::uint64_t kTableSeed = 20261130;
constexpr int kTableSamples = 40;

// A level table: no gravity in the plane, rigid contacts; friction on most disks (mu_k up to
// 0.6), none on some.
void makeTable(Dice& dice, WorldDef& world, SceneTraits& traits) {
  world.gravity_mps2 = {0.0, 0.0};
  world.contact_model = ContactModel::kImpulse;
  traits.gravity = false;
  traits.soft = false;
  for (BodyDef& body : world.bodies) {
    if (dice.chance(0.2)) continue;
    body.friction = dice.uniform(0.0, 0.6);
    body.static_friction = body.friction;
  }
}

class RandomFrictionTables : public ::testing::TestWithParam<int> {};

TEST_P(RandomFrictionTables, BooksAddUpEnergyNeverRisesMomentumGoesToTheSurfaceMirrorAgrees) {
  const int block = GetParam();
  Dice dice(kTableSeed + block);
  int compared = 0, stopped = 0;
  for (int k = 0; k < kTableScenesPerBlock; ++k) {
    const int scene = block * kTableScenesPerBlock + k;
    SceneTraits traits;
    WorldDef world = testing::randomPlane(dice, traits);
    makeTable(dice, world, traits);
    const Timeline timeline = simulate(world);
    // A stuck cluster that would turn, or a disk pressed onto another by friction, stops the
    // run with a warning; what ran is checked.
    if (timeline.status() != SimulationStatus::kComplete) {
      ASSERT_EQ(timeline.status(), SimulationStatus::kStalled) << "scene " << scene;
      ++stopped;
    }
    const WorldDef& ran = timeline.world();
    double p_scale = 1e-12;
    for (const BodyDef& body : ran.bodies) p_scale += body.mass_kg * body.velocity_mps.norm();
    testing::checkTableBooks(timeline, kTableSamples, energyBooks(timeline, 0.0).total_J() + 1e-12,
                             scene);
    testing::checkTableMomentumAndOverlap(timeline, kTableSamples, p_scale, traits.walls, scene);
    compared += testing::checkPlaneMirror(timeline, scene) ? 1 : 0;
    if (HasFailure()) return;
  }
  EXPECT_GT(compared, kTableScenesPerBlock / 2);
  EXPECT_LT(stopped, kTableScenesPerBlock / 4);
  std::printf("%d of %d compared with their mirror image, %d stopped early\n", compared,
              kTableScenesPerBlock, stopped);
}

INSTANTIATE_TEST_SUITE_P(Block, RandomFrictionTables, ::testing::Range(0, kTableBlocks));

}  // namespace plane_friction_property_test
}  // namespace collide::physics
