// SPDX-License-Identifier: MIT
// The presets where stored energy comes in, through scene -> physics: spring-carts' speeds from
// Sum p = 0 and 1/2 m1 v1^2 + 1/2 m2 v2^2 = Q, recoil's rifle speed likewise, and the books
// (parts = at the start + released) at every instant of both, computed here from each preset's
// own masses and Q.
#include <gtest/gtest.h>

#include <cmath>

#include "app/world_from_scene.hpp"
#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace release_presets_physics_test {

// Speeds of two bodies at rest pushed apart by q: v_b = sqrt(2 q m_a / (m_b (m_a + m_b))), and
// v_a = -m_b v_b / m_a.
struct Speeds {
  double a_mps, b_mps;
};
Speeds fromRest(double m_a, double m_b, double q_J) {
  const double v_b = std::sqrt(2.0 * q_J * m_a / (m_b * (m_a + m_b)));
  return {-m_b * v_b / m_a, v_b};
}

TEST(ReleasePresetsPhysicsTest, SpringCartsLeaveWithEqualAndOppositeMomenta) {
  const scene::SceneDesc scene = scene::loadPreset("spring-carts");
  const physics::WorldDef world = app::worldFromScene(scene);
  ASSERT_EQ(world.releases.size(), 1u);
  const physics::ReleaseDef& release = world.releases[0];
  const double m1 = world.bodies[0].mass_kg, m2 = world.bodies[1].mass_kg;
  const Speeds expected = fromRest(m1, m2, release.energy_J);
  const physics::Timeline timeline = physics::simulate(world);
  const physics::Snapshot after = timeline.sample(release.time_s + 0.5);
  EXPECT_NEAR(after.bodies[0].velocity_mps.x(), expected.a_mps, 1e-14);
  EXPECT_NEAR(after.bodies[1].velocity_mps.x(), expected.b_mps, 1e-14);
  // Speeds in the inverse ratio of the masses; the kinetic energies add up to Q.
  EXPECT_NEAR(-after.bodies[0].velocity_mps.x() / after.bodies[1].velocity_mps.x(), m2 / m1, 1e-14);
  EXPECT_NEAR(timeline.kineticEnergy(after), release.energy_J, 1e-13);
}

TEST(ReleasePresetsPhysicsTest, RecoilSpeedOfTheRifle) {
  const scene::SceneDesc scene = scene::loadPreset("recoil");
  const physics::WorldDef world = app::worldFromScene(scene);
  ASSERT_EQ(world.releases.size(), 1u);
  const physics::ReleaseDef& release = world.releases[0];
  const double m_rifle = world.bodies[0].mass_kg, m_bullet = world.bodies[1].mass_kg;
  const Speeds expected = fromRest(m_rifle, m_bullet, release.energy_J);
  const physics::Timeline timeline = physics::simulate(world);
  const physics::Snapshot end = timeline.sample(world.duration_s);
  EXPECT_NEAR(end.bodies[0].velocity_mps.x(), expected.a_mps, 1e-13);
  // The bullet stops in the wall (e = 0): its kinetic energy is lost, the rifle keeps its own.
  EXPECT_EQ(end.bodies[1].velocity_mps.x(), 0.0);
  EXPECT_NEAR(timeline.totalEnergyLost(), 0.5 * m_bullet * expected.b_mps * expected.b_mps,
              1e-9 * release.energy_J);
}

// parts (kinetic + lost) = at the start + released, within 1e-9 of the largest total, at 1000
// instants and just before and after each event.
TEST(ReleasePresetsPhysicsTest, BooksAddUpAtEveryInstantOfEveryReleasePreset) {
  for (const char* name : {"spring-carts", "recoil"}) {
    const physics::WorldDef world = app::worldFromScene(scene::loadPreset(name));
    const physics::Timeline timeline = physics::simulate(world);
    const double initial_J = timeline.initialKineticEnergy();
    const double largest_J = initial_J + timeline.totalEnergyReleased();
    ASSERT_GT(timeline.totalEnergyReleased(), 0.0) << name;
    std::vector<double> times;
    for (int k = 0; k <= 1000; ++k) times.push_back(world.duration_s * k / 1000.0);
    for (const physics::CollisionEvent& event : timeline.collisions()) {
      times.push_back(std::nextafter(event.time_s, 0.0));
      times.push_back(event.time_s);
    }
    for (double t : times) {
      const physics::EnergyBooks books = physics::energyBooks(timeline, t);
      EXPECT_NEAR(books.total_J(), initial_J + books.released_J, 1e-9 * largest_J)
          << name << " t = " << t;
      EXPECT_LE(books.released_J, largest_J) << name;
    }
  }
}

}  // namespace release_presets_physics_test
}  // namespace collide
