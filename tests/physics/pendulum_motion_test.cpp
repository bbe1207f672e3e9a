// The exact pendulum against references computed here, independently of the elliptic functions
// under test: the arithmetic-geometric mean for K(k), a fine Runge-Kutta integration of
// theta'' = -(g/L) sin(theta), Simpson quadrature of dt = dtheta / omega(theta), and bisection
// on the flight's distance from the pivot.
#include "physics/pendulum_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace collide::physics {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kLength_m = 1.3;
constexpr double kGravity_m_s2 = 9.81;

// K(k) = pi / (2 AGM(1, sqrt(1 - k^2))).
double completeKByAgm(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 40 && std::fabs(a - b) > 1e-17 * a; ++i) {
    const double next_a = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next_a;
  }
  return kPi / (2.0 * a);
}

double omega0() {
  return std::sqrt(kGravity_m_s2 / kLength_m);
}

// Energy per unit mass, the pivot at zero height.
double energyPerMass(PendulumState s) {
  return 0.5 * kLength_m * kLength_m * s.angular_velocity_rad_s * s.angular_velocity_rad_s -
         kGravity_m_s2 * kLength_m * std::cos(s.angle_rad);
}

// Classic fourth-order Runge-Kutta on (theta, omega) with a fixed small step.
PendulumState integrate(PendulumState s, double t_s, double step_s = 2e-5) {
  const auto accel = [](double theta) { return -kGravity_m_s2 / kLength_m * std::sin(theta); };
  const int steps = static_cast<int>(std::ceil(t_s / step_s));
  const double dt = t_s / steps;
  for (int i = 0; i < steps; ++i) {
    const double th = s.angle_rad, w = s.angular_velocity_rad_s;
    const double k1t = w, k1w = accel(th);
    const double k2t = w + 0.5 * dt * k1w, k2w = accel(th + 0.5 * dt * k1t);
    const double k3t = w + 0.5 * dt * k2w, k3w = accel(th + 0.5 * dt * k2t);
    const double k4t = w + dt * k3w, k4w = accel(th + dt * k3t);
    s.angle_rad += dt / 6.0 * (k1t + 2.0 * k2t + 2.0 * k3t + k4t);
    s.angular_velocity_rad_s += dt / 6.0 * (k1w + 2.0 * k2w + 2.0 * k3w + k4w);
  }
  return s;
}

// Time to swing from theta = 0 to theta_end (either sign) on a taut string of energy parameter
// h: the integral of dtheta / |omega|, |omega| = 2 omega0 sqrt(h - sin^2(theta/2)), by Simpson.
double swingTime(double h, double theta_end) {
  const int panels = 20000;
  const double step = std::fabs(theta_end) / panels;
  const auto inverse_speed = [&](double theta) {
    const double s = std::sin(0.5 * theta);
    return 1.0 / (2.0 * omega0() * std::sqrt(h - s * s));
  };
  double sum = inverse_speed(0.0) + inverse_speed(std::fabs(theta_end));
  for (int i = 1; i < panels; ++i) sum += (i % 2 ? 4.0 : 2.0) * inverse_speed(i * step);
  return sum * step / 3.0;
}

TEST(PendulumMotionTest, SmallSwingPeriodIsTwoPiRootLOverG) {
  const double amplitude = 1e-4;
  const PendulumArc arc(kLength_m, kGravity_m_s2, {amplitude, 0.0});
  EXPECT_EQ(arc.kind(), PendulumKind::kLibration);
  // The exact period exceeds 2 pi sqrt(L/g) by a factor 1 + k^2/4 + ..., k = sin(1e-4 / 2):
  // about 6e-10, inside the 1e-9 the small-angle formula is held to here.
  const double small_angle_period = 2.0 * kPi * std::sqrt(kLength_m / kGravity_m_s2);
  EXPECT_NEAR(arc.period_s() / small_angle_period, 1.0, 1e-9);
  EXPECT_NEAR(arc.at(arc.period_s()).angle_rad, amplitude, 1e-9 * amplitude);
  EXPECT_NEAR(arc.at(0.5 * arc.period_s()).angle_rad, -amplitude, 1e-9 * amplitude);
}

TEST(PendulumMotionTest, LargeSwingPeriodIsFourRootLOverGTimesK) {
  const double amplitude = 170.0 * kPi / 180.0;
  const PendulumArc arc(kLength_m, kGravity_m_s2, {amplitude, 0.0});
  const double k = std::sin(0.5 * amplitude);
  const double expected = 4.0 * std::sqrt(kLength_m / kGravity_m_s2) * completeKByAgm(k);
  EXPECT_NEAR(arc.period_s() / expected, 1.0, 1e-9);
  EXPECT_NEAR(arc.amplitude_rad(), amplitude, 1e-12);
  // Released at rest from +170 degrees: a quarter period later it passes the bottom moving in
  // the negative sense at the speed energy conservation gives, half a period later it is at -170.
  const PendulumState quarter = arc.at(0.25 * expected);
  EXPECT_NEAR(quarter.angle_rad, 0.0, 1e-9);
  EXPECT_NEAR(quarter.angular_velocity_rad_s, -2.0 * omega0() * k, 1e-9);
  EXPECT_NEAR(arc.at(0.5 * expected).angle_rad, -amplitude, 1e-9);
  EXPECT_NEAR(arc.at(expected).angle_rad, amplitude, 1e-9);
}

TEST(PendulumMotionTest, MotionMatchesARungeKuttaIntegration) {
  // A swing, a swing started moving backwards, a swing near the top, and two full rotations.
  const PendulumState starts[] = {{1.0, 0.7},
                                  {-0.4, -2.5},
                                  {0.0, 2.0 * omega0() * std::sqrt(0.999)},
                                  {0.3, 2.0 * omega0() * std::sqrt(2.0)},
                                  {-2.0, -9.0}};
  for (const PendulumState& start : starts) {
    const PendulumArc arc(kLength_m, kGravity_m_s2, start);
    PendulumState reference = start;
    for (int i = 1; i <= 6; ++i) {
      reference = integrate(reference, 0.5);
      const PendulumState exact = arc.at(0.5 * i);
      EXPECT_NEAR(exact.angle_rad, reference.angle_rad, 1e-8) << "start " << start.angle_rad;
      EXPECT_NEAR(exact.angular_velocity_rad_s, reference.angular_velocity_rad_s, 1e-8);
    }
  }
}

TEST(PendulumMotionTest, EnergyOfAFreeSwingIsConservedOverAHundredPeriods) {
  const PendulumState starts[] = {{2.5, 0.0}, {0.2, 6.0}, {0.0, 2.0 * omega0() * 1.5}};
  for (const PendulumState& start : starts) {
    const PendulumArc arc(kLength_m, kGravity_m_s2, start);
    const double energy0 = energyPerMass(start);
    const double scale = kGravity_m_s2 * kLength_m + std::fabs(energy0);
    int samples = 0;
    for (double t = 0.0; t <= 100.0 * arc.period_s(); t += arc.period_s() / 9.7, ++samples) {
      EXPECT_NEAR(energyPerMass(arc.at(t)), energy0, 1e-12 * scale) << "t = " << t;
    }
    EXPECT_GT(samples, 900);
  }
}

TEST(PendulumMotionTest, ARotationTurnsOnceInTwoKOverRootHOmega0) {
  const double h = 2.0;
  const PendulumState start{0.3, 2.0 * omega0() * std::sqrt(h - std::pow(std::sin(0.15), 2))};
  const PendulumArc arc(kLength_m, kGravity_m_s2, start);
  EXPECT_EQ(arc.kind(), PendulumKind::kRotation);
  EXPECT_NEAR(arc.energyParameter(), h, 1e-14);
  const double turn = 2.0 * completeKByAgm(1.0 / std::sqrt(h)) / (std::sqrt(h) * omega0());
  EXPECT_NEAR(arc.period_s() / turn, 1.0, 1e-12);
  EXPECT_NEAR(arc.at(turn).angle_rad, start.angle_rad + 2.0 * kPi, 1e-9);
  EXPECT_NEAR(arc.at(3.0 * turn).angle_rad, start.angle_rad + 6.0 * kPi, 1e-9);
  EXPECT_FALSE(arc.slackTime_s().has_value()) << "a fast loop keeps its string taut";
}

TEST(PendulumMotionTest, TheStringGoesSlackWhereTheTensionVanishes) {
  // From the bottom with energy parameter h: the tension g (4 h + 1 - 6 sin^2(theta/2)) is zero
  // at sin^2(theta/2) = (4 h + 1) / 6. h = 0.9 swings above the pivot's height; h = 1.1 would go
  // over the top but slackens first; both directions of travel.
  for (const double h : {0.9, 1.1}) {
    for (const double direction : {1.0, -1.0}) {
      const PendulumArc arc(kLength_m, kGravity_m_s2,
                            {0.0, direction * 2.0 * omega0() * std::sqrt(h)});
      const double slack_angle = 2.0 * std::asin(std::sqrt((4.0 * h + 1.0) / 6.0));
      const std::optional<double> slack = arc.slackTime_s();
      ASSERT_TRUE(slack.has_value()) << "h = " << h;
      EXPECT_NEAR(*slack, swingTime(h, slack_angle), 1e-10) << "h = " << h;
      const PendulumState at_slack = arc.at(*slack);
      EXPECT_NEAR(at_slack.angle_rad, direction * slack_angle, 1e-10);
      EXPECT_NEAR(arc.tensionPerMass_m_s2(at_slack), 0.0, 1e-9 * kGravity_m_s2);
      EXPECT_GT(arc.tensionPerMass_m_s2(arc.at(0.999 * *slack)), 0.0);
    }
  }
  // Swings that stay below the pivot's height (h <= 1/2) never slacken.
  EXPECT_FALSE(PendulumArc(kLength_m, kGravity_m_s2, {kPi / 2.0, 0.0}).slackTime_s().has_value());
}

TEST(PendulumMotionTest, AfterSlackTheBodyFliesInsideTheCircleUntilTheStringIsTaut) {
  const double h = 0.9;
  const PendulumArc arc(kLength_m, kGravity_m_s2, {0.0, 2.0 * omega0() * std::sqrt(h)});
  const PendulumState slack = arc.at(*arc.slackTime_s());
  const core::Vec2 r0 = pendulumPosition_m(kLength_m, slack.angle_rad);
  const core::Vec2 v0 = pendulumVelocity_m_s(kLength_m, slack);
  const std::optional<double> taut = tautTime_s(kLength_m, kGravity_m_s2, r0, v0);
  ASSERT_TRUE(taut.has_value());
  const auto position = [&](double t) {
    return core::Vec2(r0.x() + v0.x() * t, r0.y() + v0.y() * t - 0.5 * kGravity_m_s2 * t * t);
  };
  // Reference: the first time on a fine grid that the parabola is outside the circle, refined
  // by bisection.
  double lo = 0.0, hi = 0.0;
  for (int i = 1; i <= 100000; ++i) {
    const double t = 1e-5 * i;
    if (position(t).norm() > kLength_m) {
      hi = t;
      lo = t - 1e-5;
      break;
    }
  }
  ASSERT_GT(hi, 0.0);
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (lo + hi);
    (position(mid).norm() > kLength_m ? hi : lo) = mid;
  }
  EXPECT_NEAR(*taut, lo, 1e-9);
  EXPECT_NEAR(position(*taut).norm(), kLength_m, 1e-9 * kLength_m);
  for (int i = 1; i < 100; ++i) EXPECT_LT(position(*taut * i / 100.0).norm(), kLength_m);
}

TEST(PendulumMotionTest, ABodyDroppedInsideTheCircleFallsUntilTheStringCatchesIt) {
  // At rest 0.3 m right of the pivot with a 1 m string: it falls straight down and the string
  // is taut at y = -sqrt(1 - 0.09), after sqrt(2 sqrt(0.91) / g).
  const std::optional<double> taut = tautTime_s(1.0, kGravity_m_s2, {0.3, 0.0}, {0.0, 0.0});
  ASSERT_TRUE(taut.has_value());
  EXPECT_NEAR(*taut, std::sqrt(2.0 * std::sqrt(0.91) / kGravity_m_s2), 1e-12);
  // On the circle moving inwards (after an impact pushed it towards the pivot).
  const std::optional<double> inward = tautTime_s(1.0, kGravity_m_s2, {0.0, -1.0}, {0.0, 2.0});
  ASSERT_TRUE(inward.has_value());
  // Straight up and back down: it is at y = -1 again after 2 v / g.
  EXPECT_NEAR(*inward, 2.0 * 2.0 / kGravity_m_s2, 1e-12);
}

TEST(PendulumMotionTest, TheJerkTakesTheRadialVelocityAndBooksItsEnergy) {
  const core::Vec2 r{0.6, -0.8};  // unit length: outward = r
  const core::Vec2 v{1.0, -2.0};  // radial 0.6 + 1.6 = 2.2 outwards, tangential part kept
  const double radial = 2.2;
  const core::Vec2 tangential = v - radial * r;
  for (const double e : {0.0, 0.5, 1.0}) {
    const StringJerk jerk = stringJerk(r, v, e);
    EXPECT_NEAR((jerk.velocity_m_s - (tangential - e * radial * r)).norm(), 0.0, 1e-15);
    EXPECT_NEAR(jerk.energy_lost_per_mass_J_kg, 0.5 * (1.0 - e * e) * radial * radial, 1e-15);
    EXPECT_NEAR(0.5 * v.squaredNorm(),
                0.5 * jerk.velocity_m_s.squaredNorm() + jerk.energy_lost_per_mass_J_kg, 1e-14);
  }
  // Moving inwards the string is slack: nothing changes.
  const StringJerk none = stringJerk(r, -v, 0.0);
  EXPECT_EQ(none.velocity_m_s, -v);
  EXPECT_EQ(none.energy_lost_per_mass_J_kg, 0.0);
}

TEST(PendulumMotionTest, StateFromOffsetAndVelocityRoundTrips) {
  const PendulumState state{2.2, -1.7};
  const PendulumState back = pendulumStateOf(pendulumPosition_m(kLength_m, state.angle_rad),
                                             pendulumVelocity_m_s(kLength_m, state));
  EXPECT_NEAR(back.angle_rad, state.angle_rad, 1e-14);
  EXPECT_NEAR(back.angular_velocity_rad_s, state.angular_velocity_rad_s, 1e-14);
}

}  // namespace
}  // namespace collide::physics
