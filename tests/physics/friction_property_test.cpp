// SPDX-License-Identifier: MIT
// Property tests over random line scenes with sliding friction (the random scenes of
// property_test.cpp, each body given a kinetic and a static mu): the books add up at every
// sampled instant (kinetic + gravity + lost + to the surface = the start + released), the
// mechanical energy never rises, the bodies' momentum plus the surface's is the start's (no
// walls, no gravity), every impact obeys the definition of e, no body overlaps another, and the
// mirror image renumbered is the same motion (line_properties.hpp, shared with the drag's).
#include <gtest/gtest.h>

#include <cstdio>

#include "line_properties.hpp"

namespace collide::physics {
namespace {

using testing::Dice;
using testing::SceneTraits;

constexpr int kFrictionBlocks = 2, kFrictionScenesPerBlock = 400;
constexpr std::uint64_t kFrictionSeed = 20261129;
constexpr int kFrictionSamples = 40;
constexpr int kFrictionMirrorMaxEvents = 20;
constexpr double kMomentumRelative = 1e-12;

// Friction on most bodies (mu_k up to 0.8, mu_s up to 0.3 above it), none on some.
void addFriction(Dice& dice, WorldDef& world) {
  for (BodyDef& body : world.bodies) {
    if (dice.chance(0.2)) continue;
    body.friction = dice.uniform(0.0, 0.8);
    const double extra = dice.uniform(0.0, 0.3);
    body.static_friction = body.friction + extra;
  }
}

// Without walls and gravity the bodies' momentum plus the surface's is the start's.
void checkMomentumWithTheSurface(const Timeline& timeline, const SceneTraits& traits, int scene) {
  if (traits.walls || traits.gravity) return;
  const core::Vec2 p0 = timeline.momentum(timeline.initialState());
  double p_scale = 1e-12;
  for (const BodyDef& body : timeline.world().bodies) {
    p_scale += body.mass_kg * body.velocity_mps.norm();
  }
  const double until = timeline.simulatedUntil_s();
  for (int k = 0; k <= kFrictionSamples; ++k) {
    const double t = until * k / kFrictionSamples;
    const Snapshot s = timeline.sample(t);
    ASSERT_NEAR(timeline.momentum(s).x() + s.surface_momentum_kgmps.x(), p0.x(),
                kMomentumRelative * p_scale)
        << "scene " << scene << " t " << t;
  }
}

class RandomFrictionLineScenes : public ::testing::TestWithParam<int> {};

TEST_P(RandomFrictionLineScenes, BooksAddUpEnergyNeverRisesAndTheMirrorImageAgrees) {
  const int block = GetParam();
  Dice dice(kFrictionSeed + block);
  int compared = 0, capped = 0;
  for (int k = 0; k < kFrictionScenesPerBlock; ++k) {
    const int scene = block * kFrictionScenesPerBlock + k;
    SceneTraits traits;
    WorldDef world = testing::randomLine(dice, traits);
    addFriction(dice, world);
    world.max_collisions = 200'000;
    const Timeline timeline = simulate(world);
    if (timeline.status() != SimulationStatus::kComplete) {
      // A frictionless body bouncing elastically for ever on a block held at a wall, under
      // gravity (a limit the frictionless scenes share): checked up to the cap, counted below.
      ASSERT_EQ(timeline.status(), SimulationStatus::kCollisionCapReached) << "scene " << scene;
      ++capped;
    }
    testing::checkLineImpacts(timeline, scene);
    testing::checkLineBooks(timeline, kFrictionSamples, scene);
    checkMomentumWithTheSurface(timeline, traits, scene);
    testing::checkLineOverlap(timeline, kFrictionSamples, scene);
    compared += testing::checkLineMirror(timeline, kFrictionMirrorMaxEvents, scene) ? 1 : 0;
    if (HasFailure()) return;
  }
  EXPECT_GT(compared, kFrictionScenesPerBlock / 2);
  EXPECT_LE(capped, kFrictionScenesPerBlock / 100) << capped << " scenes stopped at the cap";
  std::printf("%d of %d compared with their mirror image, %d stopped at the cap\n", compared,
              kFrictionScenesPerBlock, capped);
}

INSTANTIATE_TEST_SUITE_P(Block, RandomFrictionLineScenes, ::testing::Range(0, kFrictionBlocks));

}  // namespace
}  // namespace collide::physics
