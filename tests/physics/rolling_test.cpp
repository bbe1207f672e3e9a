// SPDX-License-Identifier: MIT
// Rolling balls on a cloth: every expected number from the closed forms of the sliding and
// rolling phases (Leckie and Greenspan 2006). A solid ball's slip u = v + omega x (-R z) shrinks
// at 7/2 mu g along its own direction, so the slip ends at t = 2|u0| / (7 mu g) with
// v = v0 - (2/7) u0, the path a parabola; rolling, the ball slows at mu_r g to a stop after
// v / (mu_r g), v^2 / (2 mu_r g) on. The books count the spin's energy, 1/2 (2/5 m R^2) |omega|^2:
// kinetic + lost + to the cloth = the start at every instant.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace rolling_test {

using testing::disk;

constexpr double kG = 9.81;
constexpr double kR = 0.028575, kM = 0.17;  // a pool ball

BodyDef ball(const char* name, core::Vec2 x, core::Vec2 v, core::Vec2 spin, double mu,
             double mu_roll) {
  BodyDef body = disk(name, kM, kR, x, v);
  body.friction = mu;
  body.static_friction = mu;
  body.rolling_friction = mu_roll;
  body.spin_radps = spin;
  return body;
}

// The spin of a ball rolling at v.
core::Vec2 rollingSpin(core::Vec2 v) {
  return {-v.y() / kR, v.x() / kR};
}

WorldDef cloth(double duration_s) {
  WorldDef world;
  world.dimensions = 2;
  world.rolling = true;
  world.duration_s = duration_s;
  world.surface_gravity_mps2 = kG;
  return world;
}

void expectBooksAddUp(const Timeline& timeline, int samples) {
  const double start_J = energyBooks(timeline, 0.0).total_J();
  for (int k = 0; k <= samples; ++k) {
    const double t = timeline.duration_s() * k / samples;
    const EnergyBooks books = energyBooks(timeline, t);
    EXPECT_NEAR(books.total_J(), start_J, 1e-12 * start_J) << "t " << t;
  }
}

TEST(RollingTest, ASlidingBallRollsAtTwoSeventhsOfItsSlipAfterTwoUOverSevenMuG) {
  // Struck with side spin off its line: the slip is not along v, so the path is a parabola.
  const double mu = 0.2, mu_roll = 0.01;
  const core::Vec2 v0(1.0, 0.4), spin0(-20.0, 10.0);
  WorldDef world = cloth(2.0);
  world.bodies = {ball("cue", {0.0, 0.0}, v0, spin0, mu, mu_roll)};
  const Timeline timeline = simulate(world);
  const core::Vec2 u0(v0.x() - kR * spin0.y(), v0.y() + kR * spin0.x());
  const double t_roll = 2.0 * u0.norm() / (7.0 * mu * kG);
  const core::Vec2 v_roll = v0 - (2.0 / 7.0) * u0;
  // Sliding: x = v0 t + a t^2 / 2 with a = -mu g u0 / |u0|.
  const core::Vec2 a = -mu * kG / u0.norm() * u0;
  for (double f : {0.25, 0.5, 0.999}) {
    const double t = f * t_roll;
    const Snapshot s = timeline.sample(t);
    EXPECT_NEAR((s.bodies[0].position_m - (v0 * t + 0.5 * a * t * t)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((s.bodies[0].velocity_mps - (v0 + a * t)).norm(), 0.0, 1e-15);
  }
  // Rolling from t_roll on at v0 - (2/7) u0, its contact point at rest, slowing at mu_r g.
  const double rolled_s = 1e-6;
  const core::Vec2 v_after = v_roll - mu_roll * kG * rolled_s / v_roll.norm() * v_roll;
  const Snapshot s = timeline.sample(t_roll + rolled_s);
  EXPECT_NEAR((s.bodies[0].velocity_mps - v_after).norm(), 0.0, 1e-12);
  EXPECT_NEAR((s.bodies[0].spin_radps - rollingSpin(v_after)).norm(), 0.0, 1e-9);
  const double later = t_roll + 0.5;
  const Snapshot r = timeline.sample(later);
  const double speed = v_roll.norm() - mu_roll * kG * 0.5;
  EXPECT_NEAR((r.bodies[0].velocity_mps - speed / v_roll.norm() * v_roll).norm(), 0.0, 1e-14);
  EXPECT_NEAR((r.bodies[0].spin_radps - rollingSpin(r.bodies[0].velocity_mps)).norm(), 0.0, 1e-9);
  EXPECT_TRUE(timeline.warnings().empty());
  expectBooksAddUp(timeline, 50);
}

TEST(RollingTest, ARollingBallStopsAfterVOverMuRGHavingRolledVSquaredOverTwoMuRG) {
  const double mu_roll = 0.02, v = 0.8;
  WorldDef world = cloth(5.0);
  world.bodies = {ball("ball", {0.0, 0.0}, {0.0, -v}, rollingSpin({0.0, -v}), 0.2, mu_roll)};
  const Timeline timeline = simulate(world);
  const double t_stop = v / (mu_roll * kG), d = v * v / (2.0 * mu_roll * kG);
  const Snapshot end = timeline.sample(5.0);
  EXPECT_GT(5.0, t_stop);
  EXPECT_NEAR(end.bodies[0].position_m.y(), -d, 1e-14);
  EXPECT_EQ(end.bodies[0].velocity_mps.norm(), 0.0);
  EXPECT_EQ(end.bodies[0].spin_radps.norm(), 0.0);
  // The cloth took the rolling ball's energy, 7/10 m v^2 (its spin's share included), and its
  // momentum.
  EXPECT_NEAR(end.energy_to_surface_J, 0.7 * kM * v * v, 1e-15);
  EXPECT_NEAR(end.surface_momentum_kgmps.y(), -kM * v, 1e-15);
  expectBooksAddUp(timeline, 50);
}

TEST(RollingTest, TheFollowShotStopsThenFollowsAtTwoSeventhsAndTheObjectBallSettlesToFiveSevenths) {
  // Head-on, elastic, a rolling cue ball: the impact hands all its velocity to the object ball
  // and keeps its spin. The cue ball's slip is then -v, the object ball's +v: they roll at
  // 2/7 v and 5/7 v after 2 v / (7 mu g). No rolling resistance, so v at the impact is v0.
  const double mu = 0.2, v0 = 1.2;
  WorldDef world = cloth(1.0);
  world.bodies = {ball("cue", {-0.4, 0.0}, {v0, 0.0}, rollingSpin({v0, 0.0}), mu, 0.0),
                  ball("object", {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}, mu, 0.0)};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisions().size(), 1u);
  const double t_hit = (0.4 - 2.0 * kR) / v0;
  EXPECT_NEAR(timeline.collisions()[0].time_s, t_hit, 1e-15);
  const double t_roll = t_hit + 2.0 * v0 / (7.0 * mu * kG);
  const Snapshot s = timeline.sample(t_roll + 0.1);
  EXPECT_NEAR(s.bodies[0].velocity_mps.x(), 2.0 / 7.0 * v0, 1e-14);
  EXPECT_NEAR(s.bodies[1].velocity_mps.x(), 5.0 / 7.0 * v0, 1e-14);
  // Just after the impact the cue ball is at rest, spinning.
  const Snapshot after = timeline.sample(t_hit * (1.0 + 1e-12));
  EXPECT_NEAR(after.bodies[0].velocity_mps.norm(), 0.0, 1e-10);
  EXPECT_NEAR(after.bodies[0].spin_radps.y(), v0 / kR, 1e-9);
  // The cloth took m v^2 / 7 from each ball's slip: 2/7 of the cue ball's starting energy
  // (7/10 m v^2) and none was lost at the elastic impact.
  const Snapshot end = timeline.sample(1.0);
  EXPECT_NEAR(end.energy_to_surface_J, 2.0 * kM * v0 * v0 / 7.0, 1e-15);
  EXPECT_NEAR(end.energy_lost_J, 0.0, 1e-15);
  expectBooksAddUp(timeline, 50);
}

TEST(RollingTest, ADrawShotComesBackAtTwoSeventhsOfTheBackspinLeftAtTheImpact) {
  // Backspin -v0 / R at the start: the slip 2 v0 shrinks as the ball slides on; at the impact
  // the ball stops and its slip is the backspin's R omega_y alone, which pulls it back.
  const double mu = 0.2, v0 = 2.0, x0 = -0.3;
  WorldDef world = cloth(1.5);
  world.bodies = {ball("cue", {x0, 0.0}, {v0, 0.0}, {0.0, -v0 / kR}, mu, 0.0),
                  ball("object", {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}, mu, 0.0)};
  const Timeline timeline = simulate(world);
  ASSERT_GE(timeline.collisions().size(), 1u);
  // Sliding: x = x0 + v0 t - mu g t^2 / 2 reaches -2R.
  const double g = mu * kG, gap = -2.0 * kR - x0;
  const double t_hit = 2.0 * gap / (v0 + std::sqrt(v0 * v0 - 2.0 * g * gap));
  EXPECT_NEAR(timeline.collisions()[0].time_s, t_hit, 1e-15);
  // omega_y grows at 5/(2R) mu g from -v0/R; the slip at the impact is -R omega_y (v = 0).
  const double slip = -kR * (-v0 / kR + 2.5 / kR * g * t_hit);
  ASSERT_GT(slip, 0.0);
  const Snapshot s = timeline.sample(t_hit + 2.0 * slip / (7.0 * g) + 0.05);
  EXPECT_NEAR(s.bodies[0].velocity_mps.x(), -2.0 / 7.0 * slip, 1e-13);
  expectBooksAddUp(timeline, 50);
}

}  // namespace rolling_test
}  // namespace collide::physics
