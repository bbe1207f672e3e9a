// SPDX-License-Identifier: MIT
// accident-reconstruction through scene -> physics, as a reconstruction works: the locked pair's
// skid d gives its speed after the impact, sqrt(2 mu g d); momentum gives car 1's speed before it,
// (m1 + m2) / m1 times that; the closed form of car 1's own skid to the impact,
// sqrt(v0^2 - 2 mu g s), must agree. And the books (kinetic + lost + to the surface = the start)
// at every instant. Every number from the preset's own masses, coefficients and places.
#include <gtest/gtest.h>

#include <cmath>

#include "app/world_from_scene.hpp"
#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace friction_preset_physics_test {

TEST(FrictionPresetPhysicsTest, TheSkidLengthGivesTheSpeedsBeforeTheImpact) {
  const physics::WorldDef world = app::worldFromScene(scene::loadPreset("accident-reconstruction"));
  ASSERT_EQ(world.bodies.size(), 2u);
  const physics::BodyDef &car1 = world.bodies[0], &car2 = world.bodies[1];
  ASSERT_EQ(car1.friction, car2.friction);
  const double mu = car1.friction, g = world.surface_gravity_mps2;
  const double m1 = car1.mass_kg, m2 = car2.mass_kg, v0 = car1.velocity_mps.x();
  const physics::Timeline timeline = physics::simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const physics::CollisionEvent& impact = timeline.collisions().front();
  EXPECT_TRUE(impact.merged);
  // The reconstruction: from the skid after the impact back to the speed before it.
  const physics::Snapshot end = timeline.sample(world.duration_s);
  const double skid = end.bodies[1].position_m.x() - car2.position_m.x();
  EXPECT_EQ(end.bodies[0].velocity_mps.x(), 0.0);
  const double v_after = std::sqrt(2.0 * mu * g * skid);
  const double v_before = (m1 + m2) / m1 * v_after;
  EXPECT_NEAR(impact.velocity_a_after_mps.x(), v_after, 1e-12);
  EXPECT_NEAR(impact.velocity_a_before_mps.x(), v_before, 1e-12);
  // Car 1 skidded the gap between them first.
  const double gap =
      (car2.position_m.x() - 0.5 * car2.size_m) - (car1.position_m.x() + 0.5 * car1.size_m);
  EXPECT_NEAR(v_before, std::sqrt(v0 * v0 - 2.0 * mu * g * gap), 1e-12);
  // The books at 300 instants: nothing created, nothing lost track of.
  const double start_J = 0.5 * m1 * v0 * v0;
  for (int k = 0; k <= 300; ++k) {
    const double t = world.duration_s * k / 300;
    const physics::EnergyBooks books = physics::energyBooks(timeline, t);
    EXPECT_NEAR(books.total_J(), start_J, 1e-12 * start_J) << "t " << t;
  }
  // Of the start's energy, the impact took 1/2 mu_red v_before^2, the surface all the rest.
  const double lost = 0.5 * (m1 * m2 / (m1 + m2)) * v_before * v_before;
  EXPECT_NEAR(timeline.totalEnergyLost(), lost, 1e-9 * start_J);
  EXPECT_NEAR(timeline.totalEnergyToSurface(), start_J - lost, 1e-9 * start_J);
}

}  // namespace friction_preset_physics_test
}  // namespace collide
