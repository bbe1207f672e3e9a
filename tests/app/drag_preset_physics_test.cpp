// SPDX-License-Identifier: MIT
// air-drag through scene -> physics: the glider with the sail (quadratic drag c, mass m) slows as
// v = v0 / (1 + c v0 t / m), so it covers the gap d at t* = (m / (c v0))(e^(c d / m) - 1) and
// arrives at v0 e^(-c d / m); e = 1 between equal masses hands all of that to the glider at
// rest, which coasts on without drag. The air took 1/2 m (v0^2 - v*^2), the impact nothing, and
// the books add up at every instant. Every number from the preset's own masses, drag and places.
#include <gtest/gtest.h>

#include <cmath>

#include "app/world_from_scene.hpp"
#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace drag_preset_physics_test {

TEST(DragPresetPhysicsTest, TheSailedGliderArrivesWhenAndAsFastAsTheClosedFormSays) {
  const physics::WorldDef world = app::worldFromScene(scene::loadPreset("air-drag"));
  ASSERT_EQ(world.bodies.size(), 2u);
  const physics::BodyDef &sail = world.bodies[0], &glider = world.bodies[1];
  ASSERT_EQ(sail.mass_kg, glider.mass_kg);
  ASSERT_EQ(world.restitution, 1.0);
  const double m = sail.mass_kg, c = sail.drag_quadratic_kgpm, v0 = sail.velocity_mps.x();
  ASSERT_GT(c, 0.0);
  ASSERT_EQ(glider.drag_quadratic_kgpm + glider.drag_linear_kgps, 0.0);
  const double d =
      (glider.position_m.x() - 0.5 * glider.size_m) - (sail.position_m.x() + 0.5 * sail.size_m);
  const double t_hit = (m / (c * v0)) * std::expm1(c * d / m);
  const double v_hit = v0 * std::exp(-c * d / m);
  const physics::Timeline timeline = physics::simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const physics::CollisionEvent& impact = timeline.collisions().front();
  EXPECT_NEAR(impact.time_s, t_hit, 1e-14 * t_hit);
  EXPECT_NEAR(impact.velocity_a_before_mps.x(), v_hit, 1e-14 * v0);
  const physics::Snapshot end = timeline.sample(world.duration_s);
  EXPECT_NEAR(end.bodies[0].velocity_mps.x(), 0.0, 1e-14 * v0);
  EXPECT_NEAR(end.bodies[1].velocity_mps.x(), v_hit, 1e-14 * v0);
  EXPECT_NEAR(end.bodies[1].position_m.x(),
              glider.position_m.x() + v_hit * (world.duration_s - t_hit), 1e-12);
  // The air took what the sail's glider lost on its way; the elastic impact nothing.
  const double start_J = 0.5 * m * v0 * v0;
  EXPECT_NEAR(timeline.totalEnergyToAir(), 0.5 * m * (v0 * v0 - v_hit * v_hit), 1e-13 * start_J);
  EXPECT_NEAR(timeline.totalEnergyLost(), 0.0, 1e-15 * start_J);
  for (int k = 0; k <= 300; ++k) {
    const double t = world.duration_s * k / 300;
    const physics::EnergyBooks books = physics::energyBooks(timeline, t);
    EXPECT_NEAR(books.total_J(), start_J, 1e-12 * start_J) << "t " << t;
  }
}

}  // namespace drag_preset_physics_test
}  // namespace collide
