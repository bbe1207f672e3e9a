// Impacts of bodies on strings: the Newton's cradle and the ballistic pendulum run through the
// whole engine. Expected numbers come from conservation laws, the definition of e and the
// complete elliptic integral (std::comp_ellint_1), computed here.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "physics/simulate.hpp"
#include "physics/string_impact.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace string_impacts_test {

using testing::disk;
using testing::numbered;

constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.81;

struct Cradle {
  int balls = 5;
  int moving = 1;  // pulled aside on the left, released together
  double restitution = 1.0;
  double radius_m = 0.05;
  double length_m = 0.6;
  double mass_kg = 0.2;
  double release_rad = 0.5;  // angle of the pulled balls from straight down
};

WorldDef cradleWorld(const Cradle& c, double duration_s) {
  WorldDef world;
  world.dimensions = 2;
  world.gravity_mps2 = {0.0, -kG};
  world.duration_s = duration_s;
  world.restitution = c.restitution;
  for (int i = 0; i < c.balls; ++i) {
    const core::Vec2 pivot{2.0 * c.radius_m * i, 0.0};
    const double angle = i < c.moving ? -c.release_rad : 0.0;
    BodyDef ball =
        disk(numbered("b", i + 1), c.mass_kg, c.radius_m,
             pivot + c.length_m * core::Vec2(std::sin(angle), -std::cos(angle)), {0.0, 0.0});
    ball.on_string = true;
    ball.pivot_m = pivot;
    world.bodies.push_back(ball);
  }
  return world;
}

double periodOf(const Cradle& c) {
  return 4.0 * std::sqrt(c.length_m / kG) * std::comp_ellint_1(std::sin(c.release_rad / 2));
}

double angleOf(const Cradle& c, const Snapshot& s, int ball) {
  const core::Vec2 pivot{2.0 * c.radius_m * ball, 0.0};
  const core::Vec2 r = s.bodies[ball].position_m - pivot;
  return std::atan2(r.x(), -r.y());
}

TEST(StringImpactsTest, CradleSendsOutAsManyBallsAsCameIn) {
  for (int moving = 1; moving <= 4; ++moving) {
    Cradle c;
    c.moving = moving;
    const double period = periodOf(c);
    const Timeline timeline = simulate(cradleWorld(c, 6.5 * period));
    // Every half period the balls are at the top of a swing: `moving` of them at the release
    // angle on one side, the others hanging at rest. The right side after odd half periods.
    for (int half = 1; half <= 12; ++half) {
      const Snapshot s = timeline.sample(0.5 * half * period);
      const bool right = half % 2 == 1;
      int out = 0;
      for (int i = 0; i < c.balls; ++i) {
        const double angle = angleOf(c, s, i);
        const bool expected_out = right ? i >= c.balls - moving : i < moving;
        if (expected_out) {
          EXPECT_NEAR(angle, right ? c.release_rad : -c.release_rad, 1e-9)
              << "moving " << moving << " half-swing " << half << " ball " << i;
          ++out;
        } else {
          EXPECT_NEAR(angle, 0.0, 1e-9) << "moving " << moving << " half " << half << " " << i;
        }
        EXPECT_NEAR(s.bodies[i].velocity_mps.norm(), 0.0, 1e-8) << moving << " " << half;
      }
      EXPECT_EQ(out, moving);
    }
    EXPECT_NEAR(timeline.totalEnergyLost(), 0.0, 1e-12);
  }
}

TEST(StringImpactsTest, InelasticCradleLosesTheSumOfItsImpactLosses) {
  Cradle c;
  c.moving = 1;
  c.restitution = 0.8;
  const double period = periodOf(c);
  const Timeline timeline = simulate(cradleWorld(c, 3.0 * period));
  ASSERT_GT(timeline.collisions().size(), 4u);
  // The first cascade, worked out here: ball 1 arrives at the speed energy gives; each impact
  // is a 1D impact of equal masses along the row (strings vertical at the bottom),
  // v' = ((1 - e) v1 + (1 + e) v2) / 2 and back, losing 1/2 (m / 2) (1 - e^2) u^2. Touching
  // balls that close hit at once, the hardest impact first, until no pair closes.
  const double e = c.restitution;
  std::vector<double> v(c.balls, 0.0);
  v[0] = std::sqrt(2.0 * kG * c.length_m * (1.0 - std::cos(c.release_rad)));
  double first_cascade_loss = 0.0;
  for (;;) {
    int hardest = -1;
    for (int i = 0; i + 1 < c.balls; ++i) {
      const double u = v[i] - v[i + 1];
      if (u > 1e-12 && (hardest < 0 || u > v[hardest] - v[hardest + 1])) hardest = i;
    }
    if (hardest < 0) break;
    const int i = hardest;
    const double u = v[i] - v[i + 1];
    first_cascade_loss += 0.5 * (0.5 * c.mass_kg) * (1.0 - e * e) * u * u;
    const double a = 0.5 * ((1.0 - e) * v[i] + (1.0 + e) * v[i + 1]);
    const double b = 0.5 * ((1.0 + e) * v[i] + (1.0 - e) * v[i + 1]);
    v[i] = a;
    v[i + 1] = b;
  }
  // Just after the first impact (a quarter period in) the books hold that cascade's losses
  const Snapshot after = timeline.sample(0.25 * period + 1e-6);
  EXPECT_NEAR(after.energy_lost_J, first_cascade_loss, 1e-9 * first_cascade_loss);
  for (int i = 0; i < c.balls; ++i) {
    EXPECT_NEAR(after.bodies[i].velocity_mps.x(), v[i], 1e-5) << i;  // 1e-6 s of swing
  }
  // Every impact: 1/2 m_eff (1 - e^2) u^2 with the closing speed from the log and m_eff the mass
  // the contact feels through the strings (docs/physics.md): 1/m_eff = sum over the two balls
  // of (1 - (n . r)^2) / m where the string holds (r along it; its ball keeps no radial
  // velocity) and 1 / m where it let go (the impact pushed the ball towards its pivot). It is
  // also the kinetic energy the two balls lost, by the logged velocities.
  double sum = 0.0;
  for (const CollisionEvent& event : timeline.collisions()) {
    const Snapshot at = timeline.sample(event.time_s);
    double inverse = 0.0;
    for (int ball : {event.body_a, event.body_b}) {
      const core::Vec2 pivot{2.0 * c.radius_m * ball, 0.0};
      const core::Vec2 r = (at.bodies[ball].position_m - pivot).normalized();
      const core::Vec2 after =
          ball == event.body_a ? event.velocity_a_after_mps : event.velocity_b_after_mps;
      const bool holds = std::abs(r.dot(after)) <= 1e-9 * event.closing_speed_mps;
      inverse += (holds ? 1.0 - event.normal.dot(r) * event.normal.dot(r) : 1.0) / c.mass_kg;
    }
    const double u = event.closing_speed_mps;
    const double loss = 0.5 / inverse * (1.0 - e * e) * u * u;
    const double kinetic_drop =
        0.5 * c.mass_kg *
        (event.velocity_a_before_mps.squaredNorm() + event.velocity_b_before_mps.squaredNorm() -
         event.velocity_a_after_mps.squaredNorm() - event.velocity_b_after_mps.squaredNorm());
    EXPECT_NEAR(event.energy_lost_J, loss, 1e-9 * loss) << event.index;
    // (A difference of kinetic energies: good to rounding of the energies themselves.)
    const double kinetic_before =
        0.5 * c.mass_kg *
        (event.velocity_a_before_mps.squaredNorm() + event.velocity_b_before_mps.squaredNorm());
    EXPECT_NEAR(kinetic_drop, loss, 1e-9 * loss + 1e-13 * kinetic_before) << event.index;
    sum += loss;
  }
  // The books hold those and the jerks of strings snapping taut again after letting go (each
  // 1/2 m v_r^2, tiny here: the radial speeds are those of off-centre impacts); the mechanical
  // energy fell by exactly what was booked.
  EXPECT_GE(timeline.totalEnergyLost(), sum * (1.0 - 1e-12));
  EXPECT_NEAR(timeline.totalEnergyLost(), sum, 1e-5 * sum);
  EXPECT_NEAR(timeline.energyLostMeasured(), timeline.totalEnergyLost(), 1e-12);
}

TEST(StringImpactsTest, PerfectlyInelasticCradleSwingsAsOne) {
  Cradle c;
  c.moving = 1;
  c.restitution = 0.0;
  const double period = periodOf(c);
  const Timeline timeline = simulate(cradleWorld(c, period));
  // Momentum m v shared by all five: v / 5 at the bottom; the loss 1/2 m v^2 (1 - 1/5).
  const double v = std::sqrt(2.0 * kG * c.length_m * (1.0 - std::cos(c.release_rad)));
  const Snapshot after = timeline.sample(0.25 * period + 1e-9);
  for (int i = 0; i < c.balls; ++i) {
    EXPECT_NEAR(after.bodies[i].velocity_mps.x(), v / c.balls, 1e-6) << i;
  }
  EXPECT_NEAR(after.energy_lost_J, 0.5 * c.mass_kg * v * v * (1.0 - 1.0 / c.balls), 1e-12);
  // The five rise together to h = (v / 5)^2 / (2 g).
  const double h = (v / c.balls) * (v / c.balls) / (2.0 * kG);
  const double amplitude = std::acos(1.0 - h / c.length_m);
  const double swing =
      4.0 * std::sqrt(c.length_m / kG) * std::comp_ellint_1(std::sin(amplitude / 2));
  const Snapshot top = timeline.sample(0.25 * period + 0.25 * swing);
  for (int i = 0; i < c.balls; ++i) {
    EXPECT_NEAR(top.bodies[i].position_m.y(), -c.length_m + h, 1e-9) << i;
  }
}

TEST(StringImpactsTest, BallisticPendulumRisesToTheHeightThatGivesTheBulletsSpeed) {
  const double m = 0.01, M = 2.0, v = 300.0, L = 1.2;
  const double r_block = 0.1, r_bullet = 0.01;
  WorldDef world;
  world.dimensions = 2;
  world.gravity_mps2 = {0.0, -kG};
  world.duration_s = 3.0;
  world.restitution = 0.0;
  BodyDef block = disk("block", M, r_block, {0.0, -L}, {0.0, 0.0});
  block.on_string = true;
  block.pivot_m = {0.0, 0.0};
  world.bodies.push_back(block);
  // Fired level with the block's centre from 2 cm before contact (it drops g t^2 / 2 ~ 2e-8 m
  // on the way: the impact is all but horizontal).
  world.bodies.push_back(disk("bullet", m, r_bullet, {-(r_block + r_bullet + 0.02), -L}, {v, 0.0}));
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisions().size(), 1u);
  const CollisionEvent& hit = timeline.collisions()[0];
  EXPECT_TRUE(hit.merged);
  // The block's string takes the momentum's part along it (here all but nothing); the rest,
  // along the swing, is shared: v_after = m v_t / (m + M).
  const core::Vec2 momentum = m * hit.velocity_b_before_mps + M * hit.velocity_a_before_mps;
  const Snapshot just_after = timeline.sample(hit.time_s);
  const core::Vec2 out = just_after.bodies[0].position_m.normalized();  // pivot at the origin
  const core::Vec2 tangent{-out.y(), out.x()};
  const double v_after = momentum.dot(tangent) / (M + m);
  EXPECT_NEAR(just_after.bodies[0].velocity_mps.norm(), v_after, 1e-12 * v_after);
  EXPECT_NEAR(just_after.bodies[1].velocity_mps.norm(), v_after, 1e-12 * v_after);
  // The bullet is inside the block.
  EXPECT_LT((just_after.bodies[1].position_m - just_after.bodies[0].position_m).norm(),
            r_block - r_bullet + 1e-12);
  // The block swings on its string of length L (carrying the bullet) from the bottom; the top
  // of the swing comes a quarter period of that swing after the hit, at the height energy
  // conservation gives: h = v_after^2 / (2 g).
  const double h = v_after * v_after / (2.0 * kG);
  const double top_angle = std::acos(1.0 - h / L);
  const double quarter = std::sqrt(L / kG) * std::comp_ellint_1(std::sin(top_angle / 2));
  const Snapshot top = timeline.sample(hit.time_s + quarter);
  const auto centre = [&](const Snapshot& s) {
    return (M * s.bodies[0].position_m + m * s.bodies[1].position_m) / (M + m);
  };
  const double rise = centre(top).y() - centre(just_after).y();
  EXPECT_NEAR(rise / h, 1.0, 1e-9);
  EXPECT_NEAR(top.bodies[0].position_m.y() - just_after.bodies[0].position_m.y(), rise, 1e-12);
  EXPECT_NEAR(top.bodies[0].velocity_mps.norm(), 0.0, 1e-6);
  // The method of the demonstration: v = (m + M) / m sqrt(2 g h) recovers the bullet's speed.
  const double recovered = (m + M) / m * std::sqrt(2.0 * kG * rise);
  EXPECT_NEAR(recovered / hit.velocity_b_before_mps.norm(), 1.0, 1e-9);
  // Energy: the impact took 1/2 m v^2 less 1/2 (m + M) v_after^2, and the mechanical energy
  // fell by what was booked.
  const double bullet_energy = 0.5 * m * hit.velocity_b_before_mps.squaredNorm();
  EXPECT_NEAR(timeline.totalEnergyLost(), bullet_energy - 0.5 * (m + M) * v_after * v_after,
              1e-9 * bullet_energy);
  EXPECT_NEAR(timeline.energyLostMeasured(), timeline.totalEnergyLost(), 1e-12 * bullet_energy);
}

TEST(StringImpactsTest, StringsTakeOnlyWhatTheyCanPull) {
  using detail::ImpactPartner;
  // A body hanging at rest (pivot above it), struck from below straight up its string by an
  // equal body at speed 2: the contact pushes it towards the pivot, the string goes slack and
  // takes nothing, so the impact is the free one: e = 1 swaps the velocities.
  ImpactPartner striker{1.0, {0.0, 2.0}, false, {}};
  ImpactPartner hanging{1.0, {0.0, 0.0}, true, {0.0, -1.0}};
  detail::StringImpact up = resolveStringImpact(striker, hanging, {0.0, 1.0}, 1.0);
  EXPECT_FALSE(up.string_b_holds);
  EXPECT_NEAR((up.velocity_b_mps - core::Vec2(0.0, 2.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(up.energy_lost_J, 0.0, 1e-15);
  // Struck from above, straight down its string: the string pulls and holds the body still; the
  // striker bounces off as off a wall (its mass meets the pivot's), with e = 0.5: -1 m/s.
  ImpactPartner from_above{1.0, {0.0, -2.0}, false, {}};
  detail::StringImpact down = resolveStringImpact(from_above, hanging, {0.0, -1.0}, 0.5);
  EXPECT_TRUE(down.string_b_holds);
  EXPECT_NEAR(down.velocity_b_mps.norm(), 0.0, 1e-15);
  EXPECT_NEAR((down.velocity_a_mps - core::Vec2(0.0, 1.0)).norm(), 0.0, 1e-15);
  // Loss 1/2 m_eff (1 - e^2) u^2 with m_eff = 1 kg (the striker alone): 1/2 * 0.75 * 4.
  EXPECT_NEAR(down.energy_lost_J, 1.5, 1e-15);
  // Struck at 45 degrees to its string (string along -y, normal (1, -1)/sqrt 2): only the
  // tangential direction x is free. With m_eff from 1/m_eff = n.(W_a + W_b).n = 1 + 1/2 and
  // e = 1, J = 2 m_eff u; the hanging body moves along x only.
  const core::Vec2 n = core::Vec2(1.0, -1.0).normalized();
  ImpactPartner oblique{1.0, 2.0 * n, false, {}};
  detail::StringImpact side = resolveStringImpact(oblique, hanging, n, 1.0);
  EXPECT_TRUE(side.string_b_holds);
  const double m_eff = 1.0 / 1.5;
  EXPECT_NEAR(side.contact_impulse_Ns, 2.0 * m_eff * 2.0, 1e-14);
  EXPECT_NEAR(side.velocity_b_mps.y(), 0.0, 1e-15);
  EXPECT_NEAR(side.velocity_b_mps.x(), side.contact_impulse_Ns * n.x(), 1e-14);
  // Elastic: kinetic energy kept.
  EXPECT_NEAR(0.5 * side.velocity_a_mps.squaredNorm() + 0.5 * side.velocity_b_mps.squaredNorm(),
              0.5 * 4.0, 1e-14);
}

}  // namespace string_impacts_test
}  // namespace collide::physics
