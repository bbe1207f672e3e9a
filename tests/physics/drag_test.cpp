// SPDX-License-Identifier: MIT
// Air drag on a line: every expected number from the closed forms of motion under drag, written
// out here from the equations of motion (m dv/dt = -k v, or -c |v| v):
//   linear:    v = v0 e^(-kt/m), x = x0 + (m v0 / k)(1 - e^(-kt/m)), so v = v0 - (k/m)(x - x0);
//   quadratic: v = v0 / (1 + c v0 t / m), x = x0 + (m/c) ln(1 + c v0 t / m), v = v0 e^(-c
//   (x-x0)/m);
// impacts at the times these give, momentum conserved in them, and the books (kinetic + gravity
// + lost + to the air = the start) at every sampled instant.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace {

using testing::block;
using testing::wall;

BodyDef draggedBlock(const char* name, double mass_kg, double x_m, double v_mps, double k_kgps,
                     double c_kgpm = 0.0) {
  BodyDef body = block(name, mass_kg, 0.2, x_m, v_mps);
  body.drag_linear_kgps = k_kgps;
  body.drag_quadratic_kgpm = c_kgpm;
  return body;
}

WorldDef lineWorld(double duration_s) {
  WorldDef world;
  world.dimensions = 1;
  world.duration_s = duration_s;
  return world;
}

// Kinetic + gravity + lost + to the air against the start (and what was released) at `samples`
// instants, to 1e-12 of the start's energy; the air's share never negative nor falling.
void expectAirBooksAddUp(const Timeline& timeline, int samples) {
  const double start_J = energyBooks(timeline, 0.0).total_J();
  double previous_air_J = 0.0;
  for (int k = 0; k <= samples; ++k) {
    const double t = timeline.duration_s() * k / samples;
    const EnergyBooks books = energyBooks(timeline, t);
    EXPECT_NEAR(books.total_J(), start_J + books.released_J, 1e-12 * start_J) << "t " << t;
    EXPECT_GE(books.air_J, previous_air_J - 1e-14 * start_J) << "t " << t;
    previous_air_J = books.air_J;
  }
  for (const Warning& warning : timeline.warnings()) {
    EXPECT_NE(warning.kind, WarningKind::kEnergyLedger) << warning.message;
  }
}

TEST(DragTest, LinearDragDecaysExponentiallyAndCoastsMV0OverK) {
  const double m = 2.0, v0 = 3.0, k = 0.5, x0 = 1.0;
  WorldDef world = lineWorld(20.0);
  world.bodies = {draggedBlock("glider", m, x0, v0, k)};
  const Timeline timeline = simulate(world);
  for (double t : {1e-9, 1e-3, 0.5, 2.0, 7.5, 20.0}) {
    const Snapshot s = timeline.sample(t);
    const double decay = std::exp(-k * t / m);
    EXPECT_NEAR(s.bodies[0].velocity_mps.x(), v0 * decay, 1e-15 * v0) << "t " << t;
    // 1 - e^(-kt/m) as -expm1(-kt/m), which keeps its digits at small kt/m.
    const double coasted = -(m * v0 / k) * std::expm1(-k * t / m);
    EXPECT_NEAR(s.bodies[0].position_m.x(), x0 + coasted, 1e-14 * coasted + 4e-16 * x0)
        << "t " << t;
    // All the kinetic energy it lost went to the air.
    EXPECT_NEAR(s.energy_to_air_J, 0.5 * m * v0 * v0 * (1.0 - decay * decay),
                1e-14 * 0.5 * m * v0 * v0)
        << "t " << t;
  }
  expectAirBooksAddUp(timeline, 100);
}

TEST(DragTest, QuadraticDragSlowsAsOneOverTime) {
  const double m = 0.5, v0 = -4.0, c = 0.2;
  WorldDef world = lineWorld(30.0);
  world.bodies = {draggedBlock("puck", m, 0.0, v0, 0.0, c)};
  const Timeline timeline = simulate(world);
  for (double t : {1e-6, 0.25, 3.0, 30.0}) {
    const Snapshot s = timeline.sample(t);
    const double growth = 1.0 + c * std::abs(v0) * t / m;
    EXPECT_NEAR(s.bodies[0].velocity_mps.x(), v0 / growth, 1e-15 * std::abs(v0)) << "t " << t;
    // ln(1 + c |v0| t / m) as log1p, which keeps its digits at small t.
    const double gone = (m / c) * std::log1p(c * std::abs(v0) * t / m);
    EXPECT_NEAR(s.bodies[0].position_m.x(), -gone, 1e-14 * gone) << "t " << t;
    EXPECT_NEAR(s.energy_to_air_J, 0.5 * m * (v0 * v0 - v0 * v0 / (growth * growth)),
                1e-14 * m * v0 * v0)
        << "t " << t;
  }
  expectAirBooksAddUp(timeline, 100);
}

TEST(DragTest, ADraggedBlockReachesAWallWhenItsCoastingDistanceSaysSo) {
  // x(t) = (m v0 / k)(1 - e^(-kt/m)) = d at t* = -(m/k) ln(1 - k d / (m v0)), where v = v0 - k d/m;
  // it rebounds elastically and decays from -v there.
  const double m = 1.0, v0 = 2.0, k = 0.4, d = 3.0;
  WorldDef world = lineWorld(6.0);
  world.restitution = 1.0;
  world.bodies = {draggedBlock("block", m, 0.0, v0, k)};
  world.walls = {wall("wall", {d + 0.1, 0.0}, {-1.0, 0.0}, 1.0)};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const double t_hit = -(m / k) * std::log(1.0 - k * d / (m * v0));
  const CollisionEvent& hit = timeline.collisions()[0];
  EXPECT_NEAR(hit.time_s, t_hit, 4e-16 * t_hit);
  const double v_hit = v0 - k * d / m;
  EXPECT_NEAR(hit.velocity_a_before_mps.x(), v_hit, 1e-15 * v0);
  EXPECT_NEAR(hit.velocity_a_after_mps.x(), -v_hit, 1e-15 * v0);
  const double t = 5.0;
  const Snapshot s = timeline.sample(t);
  EXPECT_NEAR(s.bodies[0].velocity_mps.x(), -v_hit * std::exp(-k * (t - t_hit) / m), 1e-14 * v0);
  expectAirBooksAddUp(timeline, 60);
}

TEST(DragTest, QuadraticDragReachesAWallAtTheLogarithmsTime) {
  // x = (m/c) ln(1 + c v0 t/m) = d at t* = (m / (c v0))(e^(cd/m) - 1), at v0 e^(-cd/m).
  const double m = 3.0, v0 = 5.0, c = 0.9, d = 2.5;
  WorldDef world = lineWorld(4.0);
  world.restitution = 0.5;
  world.bodies = {draggedBlock("block", m, 0.0, v0, 0.0, c)};
  world.walls = {wall("wall", {d + 0.1, 0.0}, {-1.0, 0.0}, 0.5)};
  const Timeline timeline = simulate(world);
  ASSERT_GE(timeline.collisionCount(), 1);
  const double t_hit = (m / (c * v0)) * std::expm1(c * d / m);
  const CollisionEvent& hit = timeline.collisions()[0];
  EXPECT_NEAR(hit.time_s, t_hit, 4e-16 * t_hit);
  EXPECT_NEAR(hit.velocity_a_before_mps.x(), v0 * std::exp(-c * d / m), 1e-15 * v0);
  expectAirBooksAddUp(timeline, 60);
}

TEST(DragTest, ADraggedBlockHitsAFreeOneAndTheyMoveOnAsTheClosedFormsSay) {
  // Equal masses, e = 1: the dragged block stops at the impact and the free one leaves at the
  // impact speed v0 - k d / m, coasting without drag.
  const double m = 1.5, v0 = 4.0, k = 0.6, d = 2.0;
  WorldDef world = lineWorld(5.0);
  world.restitution = 1.0;
  world.bodies = {draggedBlock("dragged", m, 0.0, v0, k), block("free", m, 0.2, d + 0.2, 0.0)};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const double t_hit = -(m / k) * std::log(1.0 - k * d / (m * v0));
  const double v_hit = v0 - k * d / m;
  EXPECT_NEAR(timeline.collisions()[0].time_s, t_hit, 4e-16 * t_hit);
  const Snapshot s = timeline.sample(5.0);
  EXPECT_NEAR(s.bodies[0].velocity_mps.x(), 0.0, 1e-15 * v0);
  EXPECT_NEAR(s.bodies[0].position_m.x(), d, 1e-14 * d);
  EXPECT_NEAR(s.bodies[1].velocity_mps.x(), v_hit, 1e-15 * v0);
  EXPECT_NEAR(s.bodies[1].position_m.x(), d + 0.2 + v_hit * (5.0 - t_hit), 1e-14 * d);
  expectAirBooksAddUp(timeline, 60);
}

TEST(DragTest, AMergedPairDecaysAtTheSumOfTheirDragsOverTheSumOfTheirMasses) {
  // e = 0: both dragged; they lock at t* with the momentum of the striker at its impact speed
  // and then slow as one: v = v_c e^(-(k1 + k2)(t - t*) / (m1 + m2)).
  const double m1 = 2.0, m2 = 1.0, k1 = 0.3, k2 = 0.5, v0 = 3.0, d = 1.5;
  WorldDef world = lineWorld(8.0);
  world.restitution = 0.0;
  world.bodies = {draggedBlock("a", m1, 0.0, v0, k1), draggedBlock("b", m2, d + 0.2, 0.0, k2)};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const double t_hit = -(m1 / k1) * std::log(1.0 - k1 * d / (m1 * v0));
  EXPECT_NEAR(timeline.collisions()[0].time_s, t_hit, 4e-16 * t_hit);
  const double v_common = m1 * (v0 - k1 * d / m1) / (m1 + m2);
  for (double t : {t_hit + 0.5, 8.0}) {
    const Snapshot s = timeline.sample(t);
    const double v = v_common * std::exp(-(k1 + k2) * (t - t_hit) / (m1 + m2));
    EXPECT_NEAR(s.bodies[0].velocity_mps.x(), v, 1e-14 * v0) << "t " << t;
    EXPECT_NEAR(s.bodies[1].velocity_mps.x(), v, 1e-14 * v0) << "t " << t;
  }
  expectAirBooksAddUp(timeline, 60);
}

// Time of the first landing of a body dropped from height h onto a floor under gravity g with
// linear drag rate r = k/m, by bisection on y(t) = h - (g/r) t + (g/r^2)(1 - e^(-rt)).
double dropLanding_s(double h, double g, double r) {
  double lo = 0.0, hi = 1.0;
  auto y = [&](double t) { return h - (g / r) * t + (g / (r * r)) * (1.0 - std::exp(-r * t)); };
  while (y(hi) > 0.0) hi *= 2.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (y(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(DragTest, ABlockDroppedWithLinearDragLandsWhenItsClosedFormSays) {
  // Gravity along the line: v = -(g m/k)(1 - e^(-kt/m)), approaching the terminal -g m / k.
  const double m = 0.2, k = 0.1, g = 9.81, h = 4.0;
  WorldDef world = lineWorld(3.0);
  world.gravity_mps2 = {-g, 0.0};
  world.restitution = 0.6;
  world.bodies = {draggedBlock("ball", m, h + 0.1, 0.0, k)};
  world.walls = {wall("floor", {0.0, 0.0}, {1.0, 0.0}, 0.6)};
  const Timeline timeline = simulate(world);
  ASSERT_GE(timeline.collisionCount(), 1);
  const double r = k / m;
  const double t_land = dropLanding_s(h, g, r);
  EXPECT_NEAR(timeline.collisions()[0].time_s, t_land, 1e-14 * t_land);
  EXPECT_NEAR(timeline.collisions()[0].velocity_a_before_mps.x(),
              -(g / r) * (1.0 - std::exp(-r * t_land)), 1e-13 * g / r);
  const Snapshot half = timeline.sample(0.5 * t_land);
  EXPECT_NEAR(half.bodies[0].velocity_mps.x(), -(g / r) * (1.0 - std::exp(-r * 0.5 * t_land)),
              1e-15 * g / r);
  expectAirBooksAddUp(timeline, 150);
}

}  // namespace
}  // namespace collide::physics
