// SPDX-License-Identifier: MIT
// Property tests over random line scenes with sliding friction (the random scenes of
// property_test.cpp, each body given a kinetic and a static mu): the books add up at every
// sampled instant (kinetic + gravity + lost + to the surface = the start + released), the
// mechanical energy never rises, the bodies' momentum plus the surface's is the start's (no
// walls, no gravity), every impact obeys the definition of e, no body overlaps another, and the
// mirror image renumbered is the same motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "random_scenes.hpp"

namespace collide::physics {
namespace {

using testing::Dice;
using testing::SceneTraits;

constexpr int kFrictionBlocks = 2, kFrictionScenesPerBlock = 400;
constexpr std::uint64_t kFrictionSeed = 20261129;
constexpr int kFrictionSamples = 40;
constexpr int kFrictionMirrorMaxEvents = 20;
// Tolerances relative to the scene's energy, momentum and extent; the books are sums of a few
// hundred rounded terms at most.
constexpr double kBooksRelative = 1e-11, kMomentumRelative = 1e-12, kFrictionOverlap_m = 1e-10;

// Friction on most bodies (mu_k up to 0.8, mu_s up to 0.3 above it), none on some.
void addFriction(Dice& dice, WorldDef& world) {
  for (BodyDef& body : world.bodies) {
    if (dice.chance(0.2)) continue;
    body.friction = dice.uniform(0.0, 0.8);
    const double extra = dice.uniform(0.0, 0.3);
    body.static_friction = body.friction + extra;
  }
}

double frictionEnergyScale(const Timeline& timeline) {
  const Snapshot first = timeline.sample(0.0);
  double scale = 1e-12;
  for (std::size_t i = 0; i < first.bodies.size(); ++i) {
    const BodyDef& body = timeline.world().bodies[i];
    scale += 0.5 * body.mass_kg * body.velocity_mps.squaredNorm();
    // Gravity along the line can give a body its weight times the scene's extent (a few m).
    scale += body.mass_kg * std::abs(timeline.world().gravity_mps2.x()) * 10.0;
  }
  return scale;
}

void checkBooksAndMomentum(const Timeline& timeline, const SceneTraits& traits, int scene) {
  const double start_J = energyBooks(timeline, 0.0).total_J();
  const double scale_J = frictionEnergyScale(timeline);
  const core::Vec2 p0 = timeline.momentum(timeline.initialState());
  double p_scale = 1e-12;
  for (const BodyDef& body : timeline.world().bodies) {
    p_scale += body.mass_kg * body.velocity_mps.norm();
  }
  double previous = timeline.mechanicalEnergy(timeline.sample(0.0));
  const double until = timeline.simulatedUntil_s();
  for (int k = 0; k <= kFrictionSamples; ++k) {
    const double t = until * k / kFrictionSamples;
    const EnergyBooks books = energyBooks(timeline, t);
    ASSERT_NEAR(books.total_J(), start_J + books.released_J, kBooksRelative * scale_J)
        << "scene " << scene << " t " << t;
    ASSERT_GE(books.surface_J, -kBooksRelative * scale_J) << "scene " << scene;
    const Snapshot s = timeline.sample(t);
    const double mechanical = timeline.mechanicalEnergy(s);
    ASSERT_LE(mechanical, previous + kBooksRelative * scale_J) << "scene " << scene << " t " << t;
    previous = mechanical;
    if (!traits.walls && !traits.gravity) {
      ASSERT_NEAR(timeline.momentum(s).x() + s.surface_momentum_kgmps.x(), p0.x(),
                  kMomentumRelative * p_scale)
          << "scene " << scene << " t " << t;
    }
  }
}

void checkFrictionOverlap(const Timeline& timeline, int scene) {
  const WorldDef& world = timeline.world();
  std::vector<int> order(world.bodies.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return world.bodies[a].position_m.x() < world.bodies[b].position_m.x();
  });
  for (int k = 0; k <= kFrictionSamples; ++k) {
    const Snapshot s = timeline.sample(timeline.simulatedUntil_s() * k / kFrictionSamples);
    for (std::size_t j = 0; j + 1 < order.size(); ++j) {
      const int a = order[j], b = order[j + 1];
      const double gap = s.bodies[b].position_m.x() - s.bodies[a].position_m.x() -
                         0.5 * (world.bodies[a].size_m + world.bodies[b].size_m);
      ASSERT_GE(gap, -kFrictionOverlap_m) << "scene " << scene << " sample " << k;
    }
  }
}

void checkFrictionEvents(const Timeline& timeline, int scene) {
  for (const CollisionEvent& event : timeline.collisions()) {
    const double scale =
        event.velocity_a_before_mps.norm() + event.velocity_b_before_mps.norm() + 1.0;
    const double before =
        (event.velocity_a_before_mps - event.velocity_b_before_mps).dot(event.normal);
    const double after =
        (event.velocity_a_after_mps - event.velocity_b_after_mps).dot(event.normal);
    ASSERT_NEAR(after, -event.restitution * before, 1e-12 * scale) << "scene " << scene;
    ASSERT_GE(event.energy_lost_J, -1e-13 * scale * scale) << "scene " << scene;
  }
  for (const Warning& warning : timeline.warnings()) {
    ASSERT_NE(warning.kind, WarningKind::kEnergyLedger) << "scene " << scene << warning.message;
  }
}

// Short runs only: beyond a few impacts rounding-level differences between a scene and its image
// grow (docs/physics.md, simultaneous impacts). Runs where the resting rule ended a bounce series
// are left out too: the gaps at the end of such a series are rounding noise, and the next impact
// of a partner comes due at a time that noise sets (1e-11 apart in the image of one scene).
bool checkFrictionMirror(const Timeline& timeline, int scene) {
  if (timeline.collisionCount() > kFrictionMirrorMaxEvents) return false;
  for (const CollisionEvent& event : timeline.collisions()) {
    if (event.collapse_rule) return false;
  }
  const WorldDef& world = timeline.world();
  const Timeline image = simulate(testing::mirroredAndRenumbered(world));
  EXPECT_EQ(image.collisionCount(), timeline.collisionCount()) << "scene " << scene;
  double speed = 1.0, extent = 1.0;
  for (const BodyDef& body : world.bodies) {
    speed = std::max(speed, body.velocity_mps.norm());
    extent = std::max(extent, body.position_m.norm());
  }
  const int n = static_cast<int>(world.bodies.size());
  for (double t : {0.5 * timeline.simulatedUntil_s(), timeline.simulatedUntil_s()}) {
    const Snapshot s = timeline.sample(t), m = image.sample(t);
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(s.bodies[i].position_m.x(), -m.bodies[n - 1 - i].position_m.x(), 1e-12 * extent)
          << "scene " << scene << " t " << t;
      EXPECT_NEAR(s.bodies[i].velocity_mps.x(), -m.bodies[n - 1 - i].velocity_mps.x(),
                  1e-12 * speed)
          << "scene " << scene << " t " << t;
    }
    EXPECT_NEAR(s.energy_to_surface_J, m.energy_to_surface_J,
                1e-12 * frictionEnergyScale(timeline));
  }
  return true;
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
    checkFrictionEvents(timeline, scene);
    checkBooksAndMomentum(timeline, traits, scene);
    checkFrictionOverlap(timeline, scene);
    compared += checkFrictionMirror(timeline, scene) ? 1 : 0;
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
