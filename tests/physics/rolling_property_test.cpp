// SPDX-License-Identifier: MIT
// Property tests over random rolling tables (the random plane scenes of property_test.cpp made
// level, rigid and sliding on: balls with a cloth mu, a rolling resistance and a random spin):
// the books add up at every sampled instant (kinetic with the spins + lost + to the cloth = the
// start), the kinetic energy never rises, what went to the cloth never falls, the balls'
// momentum plus the cloth's is the start's (no walls), no ball overlaps another or a wall, and the
// mirror image renumbered (spins reflected as the pseudovectors they are) is the same motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "random_scenes.hpp"
#include "table_checks.hpp"

namespace collide::physics {
namespace rolling_property_test {

using testing::Dice;
using testing::SceneTraits;

constexpr int kRollingScenes = 300;
constexpr std::uint64_t kRollingSeed = 20261131;
constexpr int kRollingSamples = 40;
constexpr int kRollingMirrorMaxCollisions = 20;

void makeRollingTable(Dice& dice, WorldDef& world, SceneTraits& traits) {
  world.rolling = true;
  world.gravity_mps2 = {0.0, 0.0};
  world.contact_model = ContactModel::kImpulse;
  world.inelastic_mode = InelasticMode::kSlip;
  traits.gravity = false;
  traits.soft = false;
  // Billiard-like restitution: lower, the balls' spins press them onto cushions and each other
  // in lasting contacts, which stop a run (checked up to there, but then little runs).
  world.restitution = dice.uniform(0.7, 1.0);
  for (PairRestitution& pair : world.pair_restitution) pair.restitution = dice.uniform(0.7, 1.0);
  for (WallDef& wall : world.walls) wall.restitution = dice.uniform(0.6, 1.0);
  for (BodyDef& body : world.bodies) {
    body.friction = dice.uniform(0.0, 0.4);
    body.rolling_friction = dice.uniform(0.0, 0.05);
    const double spin_x = dice.uniform(-3.0, 3.0);  // one statement each: a fixed order
    const double spin_y = dice.uniform(-3.0, 3.0);
    body.spin_radps = core::Vec2(spin_x, spin_y) / body.size_m;
  }
}

// Reflected about x = 0: v_x and x flip, and the spin, a pseudovector, keeps omega_x and flips
// omega_y (a ball rolling at v has omega = (-v_y, v_x) / R).
WorldDef mirrored(const WorldDef& world) {
  WorldDef image = testing::mirroredAndRenumbered(world);
  const int n = static_cast<int>(world.bodies.size());
  for (int i = 0; i < n; ++i) {
    image.bodies[i].spin_radps = world.bodies[n - 1 - i].spin_radps;
    image.bodies[i].spin_radps.y() = -image.bodies[i].spin_radps.y();
  }
  return image;
}

bool checkMirror(const Timeline& timeline, int scene) {
  if (timeline.collisionCount() > kRollingMirrorMaxCollisions) return false;
  const WorldDef& world = timeline.world();
  const Timeline image = simulate(mirrored(world));
  EXPECT_EQ(image.collisionCount(), timeline.collisionCount()) << "scene " << scene;
  double speed = 1.0, extent = 1.0;
  for (const BodyDef& body : world.bodies) {
    speed = std::max(speed, body.velocity_mps.norm() + body.size_m * body.spin_radps.norm());
    extent = std::max(extent, body.position_m.norm());
  }
  const int n = static_cast<int>(world.bodies.size());
  const double t = timeline.simulatedUntil_s();
  const Snapshot s = timeline.sample(t), m = image.sample(t);
  for (int i = 0; i < n; ++i) {
    const BodyState &a = s.bodies[i], &b = m.bodies[n - 1 - i];
    EXPECT_NEAR(a.position_m.x(), -b.position_m.x(), 1e-12 * extent) << "scene " << scene;
    EXPECT_NEAR(a.position_m.y(), b.position_m.y(), 1e-12 * extent) << "scene " << scene;
    EXPECT_NEAR(a.velocity_mps.x(), -b.velocity_mps.x(), 1e-12 * speed) << "scene " << scene;
    EXPECT_NEAR(a.velocity_mps.y(), b.velocity_mps.y(), 1e-12 * speed) << "scene " << scene;
  }
  return true;
}

TEST(RandomRollingTables, BooksAddUpEnergyNeverRisesMomentumGoesToTheClothMirrorAgrees) {
  Dice dice(kRollingSeed);
  int compared = 0, stopped = 0;
  for (int scene = 0; scene < kRollingScenes; ++scene) {
    SceneTraits traits;
    WorldDef world = testing::randomPlane(dice, traits);
    makeRollingTable(dice, world, traits);
    const Timeline timeline = simulate(world);
    if (timeline.status() != SimulationStatus::kComplete) {
      ASSERT_EQ(timeline.status(), SimulationStatus::kStalled) << "scene " << scene;
      ++stopped;
    }
    double p_scale = 1e-12;  // the spins' share of the speeds counted too
    for (const BodyDef& body : world.bodies) {
      p_scale += body.mass_kg * (body.velocity_mps.norm() + body.size_m * body.spin_radps.norm());
    }
    testing::checkTableBooks(timeline, kRollingSamples,
                             energyBooks(timeline, 0.0).total_J() + 1e-12, scene);
    testing::checkTableMomentumAndOverlap(timeline, kRollingSamples, p_scale, traits.walls, scene);
    compared += checkMirror(timeline, scene) ? 1 : 0;
    if (HasFailure()) return;
  }
  EXPECT_GT(compared, kRollingScenes / 2);
  EXPECT_LT(stopped, kRollingScenes / 20);
  std::printf("%d of %d compared with their mirror image, %d stopped early\n", compared,
              kRollingScenes, stopped);
}

}  // namespace rolling_property_test
}  // namespace collide::physics
