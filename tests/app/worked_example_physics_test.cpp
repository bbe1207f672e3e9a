// The default preset through scene -> physics, checked against numbers derived here from momentum
// conservation and the definition of e (never from the reference page, whose table has slips).
#include <gtest/gtest.h>

#include <cmath>

#include "app/world_from_scene.hpp"
#include "physics/simulate.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

struct TwoBodyExpectation {
  double impact_time_s, v1_after_mps, v2_after_mps, energy_lost_J;
};

// Solves the 2x2 system  m1 v1' + m2 v2' = m1 v1 + m2 v2  and  v2' - v1' = e (v1 - v2)  by
// substitution, and places the impact where the facing edges meet.
TwoBodyExpectation expectFor(const physics::WorldDef& world) {
  const physics::BodyDef& a = world.bodies[0];
  const physics::BodyDef& b = world.bodies[1];
  const double m1 = a.mass_kg, m2 = b.mass_kg, v1 = a.velocity_mps.x(), v2 = b.velocity_mps.x();
  const double e = world.restitution;
  const double p = m1 * v1 + m2 * v2;
  const double separation = e * (v1 - v2);  // v2' - v1'
  const double v1_after = (p - m2 * separation) / (m1 + m2);
  const double v2_after = v1_after + separation;
  const double gap = (b.position_m.x() - 0.5 * b.size_m) - (a.position_m.x() + 0.5 * a.size_m);
  const double ke_before = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2;
  const double ke_after = 0.5 * m1 * v1_after * v1_after + 0.5 * m2 * v2_after * v2_after;
  return {gap / (v1 - v2), v1_after, v2_after, ke_before - ke_after};
}

TEST(WorkedExamplePhysicsTest, OneCollisionWithMomentumAndRestitutionObeyed) {
  const physics::WorldDef world = app::worldFromScene(scene::loadPreset("worked-example"));
  const TwoBodyExpectation expected = expectFor(world);
  const physics::Timeline timeline = physics::simulate(world);

  ASSERT_EQ(timeline.collisions().size(), 1u);
  const physics::CollisionEvent& hit = timeline.collisions().front();
  EXPECT_NEAR(hit.time_s, expected.impact_time_s, 1e-12);
  EXPECT_NEAR(hit.velocity_a_after_mps.x(), expected.v1_after_mps, 1e-12);
  EXPECT_NEAR(hit.velocity_b_after_mps.x(), expected.v2_after_mps, 1e-12);
  EXPECT_NEAR(hit.energy_lost_J, expected.energy_lost_J, 1e-12);

  // Energy lost equals 1/2 mu (1 - e^2) u^2 with u the closing speed.
  const double m1 = world.bodies[0].mass_kg, m2 = world.bodies[1].mass_kg;
  const double u = world.bodies[0].velocity_mps.x() - world.bodies[1].velocity_mps.x();
  const double mu = m1 * m2 / (m1 + m2);
  const double e = world.restitution;
  EXPECT_NEAR(hit.energy_lost_analytic_J, 0.5 * mu * (1 - e * e) * u * u, 1e-12);
  EXPECT_NEAR(hit.energy_lost_J, hit.energy_lost_analytic_J, 1e-12);
}

TEST(WorkedExamplePhysicsTest, SampledStateIsExactBeforeAndAfterTheImpact) {
  const physics::WorldDef world = app::worldFromScene(scene::loadPreset("worked-example"));
  const TwoBodyExpectation expected = expectFor(world);
  const physics::Timeline timeline = physics::simulate(world);
  const double x1 = world.bodies[0].position_m.x(), v1 = world.bodies[0].velocity_mps.x();
  const double x2 = world.bodies[1].position_m.x(), v2 = world.bodies[1].velocity_mps.x();
  const double tc = expected.impact_time_s;

  const physics::Snapshot before = timeline.sample(0.5 * tc);
  EXPECT_NEAR(before.bodies[0].position_m.x(), x1 + v1 * 0.5 * tc, 1e-12);
  EXPECT_NEAR(before.bodies[1].position_m.x(), x2 + v2 * 0.5 * tc, 1e-12);
  EXPECT_EQ(before.collision_count, 0);
  EXPECT_EQ(before.energy_lost_J, 0.0);

  const double t = 2.5;
  const physics::Snapshot after = timeline.sample(t);
  EXPECT_NEAR(after.bodies[0].position_m.x(), x1 + v1 * tc + expected.v1_after_mps * (t - tc),
              1e-12);
  EXPECT_NEAR(after.bodies[1].position_m.x(), x2 + v2 * tc + expected.v2_after_mps * (t - tc),
              1e-12);
  EXPECT_EQ(after.collision_count, 1);
  EXPECT_NEAR(after.energy_lost_J, expected.energy_lost_J, 1e-12);

  // Momentum is the same before and after; kinetic energy fell by exactly the energy lost.
  EXPECT_NEAR(timeline.momentum(after).x(), timeline.momentum(before).x(), 1e-12);
  EXPECT_NEAR(timeline.kineticEnergy(after) + after.energy_lost_J, timeline.initialKineticEnergy(),
              1e-12);
}

TEST(WorkedExamplePhysicsTest, ZeroRestitutionMergesTheBlocks) {
  physics::WorldDef world = app::worldFromScene(scene::loadPreset("worked-example"));
  world.restitution = 0.0;
  const physics::Timeline timeline = physics::simulate(world);
  ASSERT_EQ(timeline.collisions().size(), 1u);
  const physics::Snapshot end = timeline.sample(world.duration_s);
  const double m1 = world.bodies[0].mass_kg, m2 = world.bodies[1].mass_kg;
  const double common =
      (m1 * world.bodies[0].velocity_mps.x() + m2 * world.bodies[1].velocity_mps.x()) / (m1 + m2);
  EXPECT_NEAR(end.bodies[0].velocity_mps.x(), common, 1e-12);
  EXPECT_NEAR(end.bodies[1].velocity_mps.x(), common, 1e-12);
  // Still touching: centre distance equals the sum of half widths.
  const double touching = 0.5 * (world.bodies[0].size_m + world.bodies[1].size_m);
  EXPECT_NEAR(end.bodies[1].position_m.x() - end.bodies[0].position_m.x(), touching, 1e-12);
}

}  // namespace
}  // namespace collide
