// Bodies on strings run through the whole engine (physics::simulate and the Timeline): every
// expected number comes from a closed form or an independent calculation here (std::comp_ellint_1
// for the periods, quadrature for the slack time, the parabola and conservation laws).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace string_engine_test {

using testing::disk;

constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.81;
constexpr double kLength_m = 0.8;

BodyDef hanging(const std::string& name, double mass_kg, double radius_m, core::Vec2 pivot_m,
                double length_m, double angle_rad, double angular_velocity_rad_s = 0.0) {
  const core::Vec2 out{std::sin(angle_rad), -std::cos(angle_rad)};
  const core::Vec2 along{std::cos(angle_rad), std::sin(angle_rad)};
  BodyDef body = disk(name, mass_kg, radius_m, pivot_m + length_m * out,
                      length_m * angular_velocity_rad_s * along);
  body.on_string = true;
  body.pivot_m = pivot_m;
  return body;
}

WorldDef stringWorld(double duration_s) {
  WorldDef world;
  world.dimensions = 2;
  world.gravity_mps2 = {0.0, -kG};
  world.duration_s = duration_s;
  return world;
}

// The exact period of a swing released at rest `amplitude_rad` from straight down on a string of
// kLength_m: 4 sqrt(L / g) K(sin(amplitude / 2)), K the complete elliptic integral of the first
// kind.
double swingPeriod_s(double amplitude_rad) {
  return 4.0 * std::sqrt(kLength_m / kG) * std::comp_ellint_1(std::sin(amplitude_rad / 2));
}

// The angle from straight down of a body at `position` hanging from `pivot`.
double angleOf(core::Vec2 position, core::Vec2 pivot) {
  return std::atan2(position.x() - pivot.x(), pivot.y() - position.y());
}

TEST(StringEngineTest, SmallSwingPeriodIsTwoPiRootLOverG) {
  const double amplitude = 1e-5;
  const double period = 2.0 * kPi * std::sqrt(kLength_m / kG);
  WorldDef world = stringWorld(3.0 * period);
  world.bodies.push_back(hanging("bob", 1.0, 0.05, {0.0, 1.0}, kLength_m, amplitude));
  const Timeline timeline = simulate(world);
  // The small-angle period is exact to 1 + amplitude^2 / 16: far below 1e-9. Back at the start
  // after one period, at the opposite turning point after half of one.
  for (int k = 1; k <= 3; ++k) {
    const double angle = angleOf(timeline.sample(k * period).bodies[0].position_m, {0.0, 1.0});
    EXPECT_NEAR(angle / amplitude, 1.0, 1e-9) << k;
    const double half = angleOf(timeline.sample((k - 0.5) * period).bodies[0].position_m, {0, 1});
    EXPECT_NEAR(half / amplitude, -1.0, 1e-9) << k;
  }
}

TEST(StringEngineTest, LargeSwingPeriodIsFourRootLOverGTimesK) {
  for (double degrees : {5.0, 30.0, 60.0, 89.0, 90.0}) {
    const double amplitude = degrees * kPi / 180.0;
    const double period = swingPeriod_s(amplitude);
    WorldDef world = stringWorld(2.5 * period);
    world.bodies.push_back(hanging("bob", 1.0, 0.05, {0.0, 0.0}, kLength_m, amplitude));
    const Timeline timeline = simulate(world);
    // Released at rest no higher than the pivot (higher, the string could not pull: it would
    // start slack), back at the start after each period, through the bottom a quarter later.
    for (int k = 1; k <= 2; ++k) {
      const BodyState top = timeline.sample(k * period).bodies[0];
      EXPECT_NEAR(angleOf(top.position_m, {0, 0}), amplitude, 1e-9) << degrees;
      const BodyState bottom = timeline.sample((k + 0.25) * period).bodies[0];
      EXPECT_NEAR(angleOf(bottom.position_m, {0, 0}), 0.0, 1e-9) << degrees;
      // Energy: the speed at the bottom is sqrt(2 g L (1 - cos(amplitude))).
      const double speed = std::sqrt(2.0 * kG * kLength_m * (1.0 - std::cos(amplitude)));
      EXPECT_NEAR(bottom.velocity_mps.norm() / speed, 1.0, 1e-9) << degrees;
    }
  }
}

TEST(StringEngineTest, FreeSwingKeepsItsEnergyOverAHundredPeriods) {
  for (double degrees : {10.0, 60.0, 90.0}) {
    const double amplitude = degrees * kPi / 180.0;
    const double period = swingPeriod_s(amplitude);
    WorldDef world = stringWorld(100.0 * period);
    world.bodies.push_back(hanging("bob", 2.0, 0.05, {0.0, 0.0}, kLength_m, amplitude));
    const Timeline timeline = simulate(world);
    const double e0 = timeline.mechanicalEnergy(timeline.sample(0.0));
    const double scale = 2.0 * kG * kLength_m;  // m g L: the energies involved
    for (double t = 0.0; t <= 100.0 * period; t += period / 7.3) {
      EXPECT_NEAR(timeline.mechanicalEnergy(timeline.sample(t)), e0, 1e-12 * scale) << t;
    }
    EXPECT_EQ(timeline.totalEnergyLost(), 0.0);
  }
}

TEST(StringEngineTest, LoopTheLoopGoesRoundWithItsOwnPeriod) {
  // Launched from the bottom with v^2 = 6 g L > 5 g L: the string stays taut over the top.
  const double omega = std::sqrt(6.0 * kG / kLength_m);
  WorldDef world = stringWorld(3.0);
  world.bodies.push_back(hanging("bob", 1.0, 0.05, {0.0, 0.0}, kLength_m, 0.0, omega));
  const Timeline timeline = simulate(world);
  // One turn takes the integral of dtheta / omega(theta), omega^2 = omega_0^2 - 2 g / L (1 - cos):
  // Simpson's rule on 20,000 intervals (the integrand is smooth and periodic).
  const int n = 20000;
  double turn = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double theta = 2.0 * kPi * i / n;
    const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    turn += weight / std::sqrt(omega * omega - 2.0 * kG / kLength_m * (1.0 - std::cos(theta)));
  }
  turn *= 2.0 * kPi / n / 3.0;
  for (int k = 1; k <= 2; ++k) {
    const BodyState s = timeline.sample(k * turn).bodies[0];
    EXPECT_NEAR((s.position_m - core::Vec2(0.0, -kLength_m)).norm(), 0.0, 1e-9) << k;
    EXPECT_NEAR(s.velocity_mps.x() / (kLength_m * omega), 1.0, 1e-9) << k;
  }
  EXPECT_EQ(timeline.totalEnergyLost(), 0.0);
}

TEST(StringEngineTest, StringGoesSlackFliesItsParabolaAndSnapsTaut) {
  // From the bottom with v0^2 = 3.5 g L: not enough for the loop (5 g L), more than for a
  // swing below the pivot (2 g L). The tension m (v^2 / L + g cos) vanishes where, by energy,
  // cos(theta_s) = (2 g L - v0^2) / (3 g L) = -0.5: at 120 degrees.
  const double v0 = std::sqrt(3.5 * kG * kLength_m);
  const double mass = 1.5;
  WorldDef world = stringWorld(2.0);
  world.bodies.push_back(hanging("bob", mass, 0.05, {0.0, 0.0}, kLength_m, 0.0, v0 / kLength_m));
  const Timeline timeline = simulate(world);
  const double theta_s = std::acos(-0.5);
  // Slack time: Simpson's rule on dt = dtheta / omega(theta) from 0 to theta_s.
  const auto omega = [&](double theta) {
    return std::sqrt(v0 * v0 / (kLength_m * kLength_m) -
                     2.0 * kG / kLength_m * (1 - std::cos(theta)));
  };
  const int n = 20000;
  double t_slack = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double weight = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    t_slack += weight / omega(theta_s * i / n);
  }
  t_slack *= theta_s / n / 3.0;
  // At the slack point the speed is sqrt(-g L cos(theta_s)), along the tangent (cos, sin).
  const double v_s = std::sqrt(-kG * kLength_m * std::cos(theta_s));
  const core::Vec2 r_s{kLength_m * std::sin(theta_s), -kLength_m * std::cos(theta_s)};
  const core::Vec2 u_s{v_s * std::cos(theta_s), v_s * std::sin(theta_s)};
  const auto flight = [&](double tau) {
    return core::Vec2(r_s.x() + u_s.x() * tau, r_s.y() + u_s.y() * tau - 0.5 * kG * tau * tau);
  };
  // Back on the circle: |r_s + u tau - g tau^2 / 2 y|^2 = L^2 with r_s . u = 0 and zero tension
  // (u^2 = -g r_s.y... = g L cos): the quartic factors to tau^3 (g^2 tau / 4 - g u_y) = 0.
  const double t_taut = t_slack + 4.0 * u_s.y() / kG;
  // Just before the slack point the body is on the circle at the angle given by the quadrature.
  const BodyState before = timeline.sample(t_slack - 1e-3).bodies[0];
  EXPECT_NEAR(before.position_m.norm(), kLength_m, 1e-12);
  // Taylor to second order: theta'' = -(g / L) sin(theta).
  const double back = theta_s - 1e-3 * omega(theta_s) - 0.5e-6 * kG / kLength_m * std::sin(theta_s);
  EXPECT_NEAR(angleOf(before.position_m, {0, 0}), back, 1e-8);
  // In flight: on the parabola, inside the circle.
  for (double f : {0.1, 0.25, 0.5, 0.75, 0.9}) {
    const double tau = f * (t_taut - t_slack);
    const BodyState s = timeline.sample(t_slack + tau).bodies[0];
    EXPECT_NEAR((s.position_m - flight(tau)).norm(), 0.0, 1e-9) << f;
    EXPECT_LT(s.position_m.norm(), kLength_m) << f;
  }
  // The jerk at t_taut takes the radial velocity; its energy is booked as lost.
  const double tau = t_taut - t_slack;
  const core::Vec2 r_t = flight(tau);
  EXPECT_NEAR(r_t.norm(), kLength_m, 1e-12);
  const core::Vec2 v_t{u_s.x(), u_s.y() - kG * tau};
  const double radial = v_t.dot(r_t) / r_t.norm();
  const double jerk_loss = 0.5 * mass * radial * radial;
  EXPECT_NEAR(timeline.sample(t_taut - 1e-6).energy_lost_J, 0.0, 0.0);
  EXPECT_NEAR(timeline.sample(t_taut + 1e-6).energy_lost_J, jerk_loss, 1e-9 * jerk_loss);
  // After it the body swings on the string with the tangential velocity only.
  const BodyState after = timeline.sample(t_taut + 1e-9).bodies[0];
  EXPECT_NEAR(after.position_m.norm(), kLength_m, 1e-9);
  EXPECT_NEAR(after.velocity_mps.dot(after.position_m) / kLength_m, 0.0, 1e-6);
  // The ledger: mechanical energy fell by what was booked.
  EXPECT_NEAR(timeline.energyLostMeasured(), timeline.totalEnergyLost(), 1e-9 * jerk_loss);
}

}  // namespace string_engine_test
}  // namespace collide::physics
