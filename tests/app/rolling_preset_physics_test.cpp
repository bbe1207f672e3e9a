// SPDX-License-Identifier: MIT
// billiards-follow and billiards-draw through scene -> physics: every number from the presets'
// own speeds, places and coefficients by the closed forms of the sliding and rolling phases. The
// follow shot: the rolling cue ball arrives at v = sqrt(v0^2 - 2 mu_r g s), stops, and rolls on
// at 2/7 v; the object ball settles to 5/7 v. The draw shot comes back. The break on a cloth comes
// to rest. The books (kinetic with the spins + lost + to the cloth = the start) at every instant.
#include <gtest/gtest.h>

#include <cmath>

#include "app/world_from_scene.hpp"
#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace rolling_preset_physics_test {

void expectBooksAddUp(const physics::Timeline& timeline, double duration_s) {
  const double start_J = physics::energyBooks(timeline, 0.0).total_J();
  for (int k = 0; k <= 200; ++k) {
    const double t = duration_s * k / 200;
    const physics::EnergyBooks books = physics::energyBooks(timeline, t);
    EXPECT_NEAR(books.total_J(), start_J, 1e-12 * start_J) << "t " << t;
  }
}

TEST(RollingPresetPhysicsTest,
     TheFollowShotStopsThenFollowsAtTwoSeventhsWhileTheObjectBallGetsFive) {
  const physics::WorldDef world = app::worldFromScene(scene::loadPreset("billiards-follow"));
  ASSERT_TRUE(world.rolling);
  ASSERT_EQ(world.bodies.size(), 2u);
  const physics::BodyDef &cue = world.bodies[0], &object = world.bodies[1];
  const double g = world.surface_gravity_mps2, mu = cue.friction, mu_r = cue.rolling_friction;
  const double r = cue.size_m, v0 = cue.velocity_mps.x();
  // Rolling from the start: its spin is that of rolling.
  EXPECT_NEAR(cue.spin_radps.y(), v0 / r, 1e-12 * v0 / r);
  const physics::Timeline timeline = physics::simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const double s = object.position_m.x() - cue.position_m.x() - 2.0 * r;
  const double v = std::sqrt(v0 * v0 - 2.0 * mu_r * g * s);
  const physics::CollisionEvent& hit = timeline.collisions().front();
  EXPECT_NEAR(hit.velocity_a_before_mps.x(), v, 1e-12);
  EXPECT_NEAR(hit.velocity_a_after_mps.norm(), 0.0, 1e-12);
  // Both slide for 2 v / (7 mu g); then the cue ball rolls at 2/7 v, the object ball at 5/7 v.
  const double t_roll = hit.time_s + 2.0 * v / (7.0 * mu * g);
  const physics::Snapshot rolled = timeline.sample(t_roll * (1.0 + 1e-9));
  EXPECT_NEAR(rolled.bodies[0].velocity_mps.x(), 2.0 / 7.0 * v, 1e-9);
  EXPECT_NEAR(rolled.bodies[1].velocity_mps.x(), 5.0 / 7.0 * v, 1e-9);
  expectBooksAddUp(timeline, world.duration_s);
}

TEST(RollingPresetPhysicsTest, TheDrawShotComesBack) {
  const physics::WorldDef world = app::worldFromScene(scene::loadPreset("billiards-draw"));
  ASSERT_TRUE(world.rolling);
  const physics::BodyDef& cue = world.bodies[0];
  EXPECT_NEAR(cue.spin_radps.y(), -cue.velocity_mps.x() / cue.size_m, 1e-9);
  const physics::Timeline timeline = physics::simulate(world);
  ASSERT_GE(timeline.collisionCount(), 1);
  const physics::Snapshot end = timeline.sample(world.duration_s);
  EXPECT_LT(end.bodies[0].velocity_mps.x(), 0.0);
  // Back behind where it stopped at the impact.
  const double t_hit = timeline.collisions().front().time_s;
  EXPECT_LT(end.bodies[0].position_m.x(), timeline.sample(t_hit).bodies[0].position_m.x());
  expectBooksAddUp(timeline, world.duration_s);
}

// The break, struck at the centre: the cue ball sets off sliding without spin, and by the end
// the cloth has stopped every ball and every spin, so what the impacts did not take, the cloth
// did. A rolling ball stops from v after v / (mu_r g): the end leaves time for that.
TEST(RollingPresetPhysicsTest, TheBreakComesToRestAndTheClothTookWhatTheImpactsLeft) {
  const physics::WorldDef world = app::worldFromScene(scene::loadPreset("billiards-break"));
  ASSERT_TRUE(world.rolling);
  const physics::BodyDef& cue = world.bodies.front();
  EXPECT_EQ(cue.spin_radps.norm(), 0.0);
  const physics::Timeline timeline = physics::simulate(world);
  EXPECT_TRUE(timeline.warnings().empty());
  const physics::Snapshot end = timeline.sample(world.duration_s);
  for (std::size_t i = 0; i < end.bodies.size(); ++i) {
    EXPECT_EQ(end.bodies[i].velocity_mps.norm(), 0.0) << "ball " << i;
    EXPECT_EQ(end.bodies[i].spin_radps.norm(), 0.0) << "ball " << i;
  }
  const double start_J = 0.5 * cue.mass_kg * cue.velocity_mps.squaredNorm();
  const physics::EnergyBooks books = physics::energyBooks(timeline, world.duration_s);
  EXPECT_NEAR(books.surface_J + books.lost_J, start_J, 1e-12 * start_J);
  EXPECT_GT(books.surface_J, 0.0);
  EXPECT_GT(books.lost_J, 0.0);
  expectBooksAddUp(timeline, world.duration_s);
}

}  // namespace rolling_preset_physics_test
}  // namespace collide
