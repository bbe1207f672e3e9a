// SPDX-License-Identifier: MIT
// Property tests over random line scenes with air drag (the random scenes of property_test.cpp,
// most bodies given linear drag, quadratic drag or both; quadratic only without gravity along
// the line): the books add up at every sampled instant (kinetic + gravity + lost + to the air =
// the start + released), the mechanical energy never rises (energy is never created), every
// impact obeys the definition of e, no body overlaps another, and the mirror image renumbered is
// the same motion (line_properties.hpp, shared with friction's).
#include <gtest/gtest.h>

#include <cstdio>

#include "line_properties.hpp"

namespace collide::physics {
namespace {

using testing::Dice;
using testing::SceneTraits;

constexpr int kDragBlocks = 2, kDragScenesPerBlock = 150;
constexpr std::uint64_t kDragSeed = 20261130;
constexpr int kDragSamples = 40;
constexpr int kDragMirrorMaxEvents = 20;

// Drag on most bodies, with a rate k/m or c/m (per metre) up to 2: enough to slow a body
// noticeably over the 4 s of a scene.
void addDrag(Dice& dice, WorldDef& world, bool gravity) {
  for (BodyDef& body : world.bodies) {
    if (dice.chance(0.2)) continue;
    const int kind = gravity ? 0 : dice.integer(0, 2);  // linear, quadratic, both
    const double linear_per_s = dice.uniform(0.0, 2.0);
    const double quadratic_per_m = dice.uniform(0.0, 2.0);
    if (kind != 1) body.drag_linear_kgps = linear_per_s * body.mass_kg;
    if (kind != 0) body.drag_quadratic_kgpm = quadratic_per_m * body.mass_kg;
  }
}

class RandomDragLineScenes : public ::testing::TestWithParam<int> {};

TEST_P(RandomDragLineScenes, BooksAddUpEnergyNeverRisesAndTheMirrorImageAgrees) {
  const int block = GetParam();
  Dice dice(kDragSeed + block);
  int compared = 0, capped = 0;
  for (int k = 0; k < kDragScenesPerBlock; ++k) {
    const int scene = block * kDragScenesPerBlock + k;
    SceneTraits traits;
    WorldDef world = testing::randomLine(dice, traits);
    addDrag(dice, world, traits.gravity);
    world.max_collisions = 200'000;
    const Timeline timeline = simulate(world);
    if (timeline.status() != SimulationStatus::kComplete) {
      // A body without drag bouncing elastically for ever on a block held at a wall, under
      // gravity (a limit the scenes without drag share): checked up to the cap, counted below.
      ASSERT_EQ(timeline.status(), SimulationStatus::kCollisionCapReached) << "scene " << scene;
      ++capped;
    }
    testing::checkLineImpacts(timeline, scene);
    testing::checkLineBooks(timeline, kDragSamples, scene);
    testing::checkLineOverlap(timeline, kDragSamples, scene);
    compared += testing::checkLineMirror(timeline, kDragMirrorMaxEvents, scene) ? 1 : 0;
    if (HasFailure()) return;
  }
  EXPECT_GT(compared, kDragScenesPerBlock / 2);
  EXPECT_LE(capped, kDragScenesPerBlock / 50) << capped << " scenes stopped at the cap";
  std::printf("%d of %d compared with their mirror image, %d stopped at the cap\n", compared,
              kDragScenesPerBlock, capped);
}

INSTANTIATE_TEST_SUITE_P(Block, RandomDragLineScenes, ::testing::Range(0, kDragBlocks));

}  // namespace
}  // namespace collide::physics
