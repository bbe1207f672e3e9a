// The presets with bodies on strings through scene -> physics: the swinging newtons-cradle with
// `moving` = 1..4 over more than ten full swings, and the ballistic-pendulum's rise. Expected
// values come from the pendulum's closed forms (std::comp_ellint_1), conservation of momentum and
// of energy, computed here from the preset's own geometry.
#include <gtest/gtest.h>

#include <cmath>

#include "app/world_from_scene.hpp"
#include "physics/simulate.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace string_presets_physics_test {

// Angle of a body on its string from straight down, counter-clockwise positive.
double angleOf(const physics::BodyDef& def, const core::Vec2& position_m) {
  const core::Vec2 r = position_m - def.pivot_m;
  return std::atan2(r.x(), -r.y());
}

// With e = 1 the cradle is periodic: every half period all balls are at rest at the top of a
// swing, the `moving` on one side at the release angle, the rest hanging straight down; the far
// side after odd half periods. Checked at each of 22 half periods (11 full swings).
TEST(StringPresetsPhysicsTest, CradleSendsOutAsManyBallsAsCameInForElevenSwings) {
  constexpr int kHalfSwings = 22;
  for (int moving = 1; moving <= 4; ++moving) {
    scene::SceneDesc scene =
        scene::makePreset("newtons-cradle", {{"moving", static_cast<double>(moving)}});
    physics::WorldDef world = app::worldFromScene(scene);
    ASSERT_EQ(world.bodies.size(), 5u);
    const physics::BodyDef& first = world.bodies[0];
    ASSERT_TRUE(first.on_string);
    const double length_m = (first.position_m - first.pivot_m).norm();
    const double release_rad = std::abs(angleOf(first, first.position_m));
    const double g = -world.gravity_mps2.y();
    const double period_s =
        4.0 * std::sqrt(length_m / g) * std::comp_ellint_1(std::sin(0.5 * release_rad));
    world.duration_s = (0.5 * kHalfSwings + 0.25) * period_s;
    const physics::Timeline timeline = physics::simulate(world);
    ASSERT_GE(timeline.collisions().size(), static_cast<std::size_t>(kHalfSwings));

    for (int half = 1; half <= kHalfSwings; ++half) {
      const physics::Snapshot s = timeline.sample(0.5 * half * period_s);
      const bool far_side = half % 2 == 1;
      int out = 0;
      for (int i = 0; i < 5; ++i) {
        const double angle = angleOf(world.bodies[i], s.bodies[i].position_m);
        const bool expected_out = far_side ? i >= 5 - moving : i < moving;
        const double expected = expected_out ? (far_side ? release_rad : -release_rad) : 0.0;
        EXPECT_NEAR(angle, expected, 1e-9)
            << "moving " << moving << " half " << half << " ball " << i + 1;
        EXPECT_NEAR(s.bodies[i].velocity_mps.norm(), 0.0, 1e-8)
            << "moving " << moving << " half " << half << " ball " << i + 1;
        if (std::abs(angle) > 0.5 * release_rad) ++out;
      }
      EXPECT_EQ(out, moving) << "half " << half;
    }
    EXPECT_NEAR(timeline.totalEnergyLost(), 0.0, 1e-12) << "moving " << moving;
  }
}

// With e < 1 the first impact is a cascade along the row (strings vertical at the bottom, so each
// impact is a 1D impact of equal masses): each pair loses 1/2 (m / 2)(1 - e^2) u^2. The books
// just after the first impact hold exactly that sum, worked out here.
TEST(StringPresetsPhysicsTest, InelasticCradleBooksItsImpactLosses) {
  scene::SceneDesc scene = scene::makePreset("newtons-cradle", {{"moving", 2.0}});
  scene.restitution = 0.7;
  physics::WorldDef world = app::worldFromScene(scene);
  const physics::BodyDef& first = world.bodies[0];
  const double length_m = (first.position_m - first.pivot_m).norm();
  const double release_rad = std::abs(angleOf(first, first.position_m));
  const double g = -world.gravity_mps2.y();
  const double m = first.mass_kg, e = world.restitution;
  const double quarter_s =
      std::sqrt(length_m / g) * std::comp_ellint_1(std::sin(0.5 * release_rad));
  world.duration_s = quarter_s + 0.01;
  const physics::Timeline timeline = physics::simulate(world);

  std::vector<double> v(5, 0.0);
  v[0] = v[1] = std::sqrt(2.0 * g * length_m * (1.0 - std::cos(release_rad)));
  double expected_loss_J = 0.0;
  for (;;) {  // the hardest closing pair first, until none closes
    int hardest = -1;
    for (int i = 0; i + 1 < 5; ++i) {
      const double u = v[i] - v[i + 1];
      if (u > 1e-12 && (hardest < 0 || u > v[hardest] - v[hardest + 1])) hardest = i;
    }
    if (hardest < 0) break;
    const int i = hardest;
    const double u = v[i] - v[i + 1];
    expected_loss_J += 0.5 * (0.5 * m) * (1.0 - e * e) * u * u;
    const double a = 0.5 * ((1.0 - e) * v[i] + (1.0 + e) * v[i + 1]);
    const double b = 0.5 * ((1.0 + e) * v[i] + (1.0 - e) * v[i + 1]);
    v[i] = a;
    v[i + 1] = b;
  }
  ASSERT_GT(expected_loss_J, 0.0);
  EXPECT_NEAR(timeline.totalEnergyLost(), expected_loss_J, 1e-9 * expected_loss_J);
  EXPECT_NEAR(timeline.energyLostMeasured(), expected_loss_J, 1e-9 * expected_loss_J);
  double logged_J = 0.0;
  for (const physics::CollisionEvent& event : timeline.collisions())
    logged_J += event.energy_lost_J;
  EXPECT_NEAR(logged_J, expected_loss_J, 1e-9 * expected_loss_J);
}

// The ballistic pendulum: momentum along the swing is shared by bullet and block, the pair then
// rises until that kinetic energy is potential, h = v_after^2 / (2 g), and (m + M) / m sqrt(2 g h)
// gives back the bullet's speed.
TEST(StringPresetsPhysicsTest, BallisticPendulumRiseGivesBackTheBulletsSpeed) {
  physics::WorldDef world = app::worldFromScene(scene::loadPreset("ballistic-pendulum"));
  ASSERT_EQ(world.bodies.size(), 2u);
  const int block = world.bodies[0].on_string ? 0 : 1, bullet = 1 - block;
  const double M = world.bodies[block].mass_kg, m = world.bodies[bullet].mass_kg;
  const double g = -world.gravity_mps2.y();
  const double v_bullet = world.bodies[bullet].velocity_mps.norm();
  const physics::Timeline timeline = physics::simulate(world);
  ASSERT_FALSE(timeline.collisions().empty());
  const physics::CollisionEvent& hit = timeline.collisions().front();
  EXPECT_TRUE(hit.merged);
  // The bullet flies level into the block at the bottom of its string: the string takes none of
  // the horizontal momentum.
  const double v_after = m * v_bullet / (m + M);
  const core::Vec2 after =
      block == hit.body_a ? hit.velocity_a_after_mps : hit.velocity_b_after_mps;
  EXPECT_NEAR(after.norm(), v_after, 1e-9 * v_after);
  const double h_m = v_after * v_after / (2.0 * g);
  // The highest point of the block after the hit: sampled finely, then bisected on vy.
  const double hit_y = timeline.sample(hit.time_s).bodies[block].position_m.y();
  double lo = hit.time_s, hi = timeline.simulatedUntil_s();
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (timeline.sample(mid).bodies[block].velocity_mps.y() > 0.0 ? lo : hi) = mid;
  }
  const double rise_m = timeline.sample(lo).bodies[block].position_m.y() - hit_y;
  EXPECT_NEAR(rise_m, h_m, 1e-9 * h_m);
  EXPECT_NEAR((m + M) / m * std::sqrt(2.0 * g * rise_m), v_bullet, 1e-9 * v_bullet);
}

}  // namespace string_presets_physics_test
}  // namespace collide
