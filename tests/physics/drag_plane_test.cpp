// SPDX-License-Identifier: MIT
// Air drag in the plane (linear, F = -k v): every expected number from the closed form of a
// projectile under gravity g and drag rate r = k/m, written out here from m dv/dt = m g - k v:
//   v(t) = v0 e^(-rt) + (g/r)(1 - e^(-rt)),
//   x(t) = x0 + (v0 / r)(1 - e^(-rt)) + (g/r) t - (g/r^2)(1 - e^(-rt)),
// its landing found by bisection on that y(t), impacts between disks at the times the closed
// form of the coasting disk gives, and the books at every sampled instant. Random scenes:
// drag_plane_property_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace {

using testing::disk;
using testing::wall;

// One coordinate of the closed form: position and velocity at t from p0, v0 and gravity g along it.
struct Axis {
  double p0, v0, g;
  double at(double r, double t) const {
    const double decayed = -std::expm1(-r * t);  // 1 - e^(-rt), its digits kept at small rt
    return p0 + (v0 / r) * decayed + (g / r) * t - (g / (r * r)) * decayed;
  }
  double speed(double r, double t) const {
    return v0 * std::exp(-r * t) + (g / r) * -std::expm1(-r * t);
  }
};

// The first t in (0, 100] where height.at(r, t) falls to `level`, by bisection.
double firstFallTo(const Axis& height, double r, double level) {
  double lo = 1e-9, hi = 1e-3;
  while (height.at(r, hi) > level) hi *= 2.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (height.at(r, mid) > level ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void expectPlaneAirBooksAddUp(const Timeline& timeline, int samples) {
  const double start_J = energyBooks(timeline, 0.0).total_J();
  double scale_J = 0.0;
  for (int k = 0; k <= samples; ++k) {
    const double t = timeline.duration_s() * k / samples;
    const EnergyBooks books = energyBooks(timeline, t);
    scale_J = std::max(scale_J, books.kineticTotal_J() + std::abs(books.gravity_J));
    EXPECT_NEAR(books.total_J(), start_J, 1e-12 * std::max(scale_J, std::abs(start_J)))
        << "t " << t;
    EXPECT_GE(books.air_J, 0.0) << "t " << t;
  }
  for (const Warning& warning : timeline.warnings()) {
    EXPECT_NE(warning.kind, WarningKind::kEnergyLedger) << warning.message;
  }
}

TEST(DragPlaneTest, AProjectileWithLinearDragLandsWhereItsClosedFormSays) {
  // 0.5 kg thrown at 12 m/s, 50 degrees up, k = 0.1 kg/s (r = 0.2 /s), from 1 m above the floor.
  const double m = 0.5, k = 0.1, r = k / m, g = 9.81, radius = 0.05;
  const double speed = 12.0, angle = 50.0 * std::acos(-1.0) / 180.0;
  const Axis x{-8.0, speed * std::cos(angle), 0.0}, y{1.0, speed * std::sin(angle), -g};
  WorldDef world;
  world.dimensions = 2;
  world.duration_s = 4.0;
  world.gravity_mps2 = {0.0, -g};
  world.restitution = 0.5;
  BodyDef ball = disk("ball", m, radius, {x.p0, y.p0}, {x.v0, y.v0});
  ball.drag_linear_kgps = k;
  world.bodies = {ball};
  world.walls = {wall("floor", {0.0, 0.0}, {0.0, 1.0}, 0.5)};
  const Timeline timeline = simulate(world);
  ASSERT_GE(timeline.collisionCount(), 1);
  const double t_land = firstFallTo(y, r, radius);
  const CollisionEvent& landing = timeline.collisions()[0];
  EXPECT_NEAR(landing.time_s, t_land, 1e-13 * t_land);
  // The range with drag, and less than the drag-free one.
  const double range = x.at(r, t_land) - x.p0;
  const Snapshot at_landing = timeline.sample(t_land);
  EXPECT_NEAR(at_landing.bodies[0].position_m.x() - x.p0, range, 1e-12 * range);
  EXPECT_LT(range, x.v0 * 2.0 * y.v0 / g);
  EXPECT_NEAR(landing.velocity_a_before_mps.y(), y.speed(r, t_land), 1e-12 * speed);
  EXPECT_NEAR(landing.velocity_a_before_mps.x(), x.speed(r, t_land), 1e-12 * speed);
  // Halfway up, the closed form in both coordinates.
  const double t_half = 0.5 * t_land;
  const Snapshot half = timeline.sample(t_half);
  EXPECT_NEAR(half.bodies[0].position_m.x(), x.at(r, t_half), 1e-13 * std::abs(x.p0));
  EXPECT_NEAR(half.bodies[0].position_m.y(), y.at(r, t_half), 1e-13 * 10.0);
  EXPECT_NEAR(half.bodies[0].velocity_mps.y(), y.speed(r, t_half), 1e-14 * speed);
  expectPlaneAirBooksAddUp(timeline, 200);
}

TEST(DragPlaneTest, ACoastingDiskHitsAnotherWhenItsCoastingDistanceSaysSo) {
  // No gravity: the dragged disk coasts d = (v0/r)(1 - e^(-rt)) to touch the resting one, at
  // t* = -ln(1 - r d / v0) / r with speed v0 - r d; head-on, equal masses, e = 1: it stops.
  const double m = 1.0, k = 0.3, r = k / m, v0 = 2.0, radius = 0.1, d = 1.5;
  WorldDef world;
  world.dimensions = 2;
  world.duration_s = 3.0;
  world.restitution = 1.0;
  BodyDef striker = disk("striker", m, radius, {0.0, 0.0}, {v0, 0.0});
  striker.drag_linear_kgps = k;
  world.bodies = {striker, disk("target", m, radius, {d + 2.0 * radius, 0.0}, {0.0, 0.0})};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const double t_hit = -std::log1p(-r * d / v0) / r;
  EXPECT_NEAR(timeline.collisions()[0].time_s, t_hit, 1e-14 * t_hit);
  const Snapshot end = timeline.sample(3.0);
  EXPECT_NEAR(end.bodies[0].velocity_mps.x(), 0.0, 1e-14 * v0);
  EXPECT_NEAR(end.bodies[1].velocity_mps.x(), v0 - r * d, 1e-14 * v0);
  EXPECT_NEAR(end.energy_to_air_J, 0.5 * m * (v0 * v0 - (v0 - r * d) * (v0 - r * d)),
              1e-14 * m * v0 * v0);
  expectPlaneAirBooksAddUp(timeline, 100);
}

TEST(DragPlaneTest, AFreeDiskSlowsAsV0TimesEToTheMinusKtOverMAlongAStraightLine) {
  // No gravity, no walls: v(t) = v0 e^(-kt/m) keeps its direction, and the disk coasts
  // (m/k)(1 - e^(-kt/m)) v0 towards the point m v0 / k ahead; the air takes 1/2 m (v0^2 - v^2).
  const double m = 2.0, k = 0.8, r = k / m;
  const core::Vec2 v0(1.5, -2.0), x0(0.5, 1.0);
  WorldDef world;
  world.dimensions = 2;
  world.duration_s = 5.0;
  BodyDef puck = disk("puck", m, 0.2, x0, v0);
  puck.drag_linear_kgps = k;
  world.bodies = {puck};
  const Timeline timeline = simulate(world);
  EXPECT_EQ(timeline.collisionCount(), 0);
  for (int i = 0; i <= 20; ++i) {
    const double t = world.duration_s * i / 20;
    const Snapshot s = timeline.sample(t);
    const core::Vec2 v = v0 * std::exp(-r * t);
    const core::Vec2 x = x0 + v0 * (-std::expm1(-r * t) / r);
    EXPECT_NEAR(s.bodies[0].velocity_mps.x(), v.x(), 1e-14 * v0.norm()) << "t " << t;
    EXPECT_NEAR(s.bodies[0].velocity_mps.y(), v.y(), 1e-14 * v0.norm()) << "t " << t;
    EXPECT_NEAR(s.bodies[0].position_m.x(), x.x(), 1e-14 * 10.0) << "t " << t;
    EXPECT_NEAR(s.bodies[0].position_m.y(), x.y(), 1e-14 * 10.0) << "t " << t;
    EXPECT_NEAR(s.energy_to_air_J, 0.5 * m * (v0.squaredNorm() - v.squaredNorm()),
                1e-14 * m * v0.squaredNorm())
        << "t " << t;
  }
  expectPlaneAirBooksAddUp(timeline, 100);
}

TEST(DragPlaneTest, DisksThatTheAirPressesTogetherEndTheRunWithAWarning) {
  // A striker without drag at v0 runs into a disk with drag at rest, d ahead, at e = 0: it
  // arrives at d / v0, the two move on at v0 / 2, and the air slows the one ahead only: pressed
  // together, a lasting contact the event model does not follow. The run stops there.
  const double m = 1.0, radius = 0.1, v0 = 2.0, d = 1.0;
  WorldDef world;
  world.dimensions = 2;
  world.duration_s = 2.0;
  world.restitution = 0.0;
  BodyDef target = disk("target", m, radius, {d + 2.0 * radius, 0.0}, {0.0, 0.0});
  target.drag_linear_kgps = 0.5;
  world.bodies = {disk("striker", m, radius, {0.0, 0.0}, {v0, 0.0}), target};
  const Timeline timeline = simulate(world);
  // The impact, and at the same instant the first of the pressed ones (at no closing speed),
  // which the rule stops at.
  ASSERT_EQ(timeline.collisionCount(), 2);
  for (const CollisionEvent& impact : timeline.collisions()) {
    EXPECT_NEAR(impact.time_s, d / v0, 1e-15);
  }
  EXPECT_NEAR(timeline.collisions()[1].closing_speed_mps, 0.0, 1e-15 * v0);
  EXPECT_EQ(timeline.status(), SimulationStatus::kStalled);
  EXPECT_NEAR(timeline.simulatedUntil_s(), d / v0, 1e-15);
  ASSERT_EQ(timeline.warnings().size(), 1u);
  const std::string& message = timeline.warnings()[0].message;
  EXPECT_NE(message.find("disks \"striker\" and \"target\" were pressed together"),
            std::string::npos)
      << message;
}

TEST(DragPlaneTest, DisksWithEqualRatesMoveOnTogetherAfterAnImpactAtEZero) {
  // Equal rates r = k/m: the striker coasts d in t* = -ln(1 - r d / v0) / r, arriving at
  // v* = v0 - r d; e = 0 between equal masses leaves both at v* / 2, and the air slows both
  // alike (v* / 2) e^(-r (t - t*)): never pressed, never apart.
  const double m = 0.5, k = 0.2, r = k / m, radius = 0.1, v0 = 2.0, d = 1.0;
  WorldDef world;
  world.dimensions = 2;
  world.duration_s = 3.0;
  world.restitution = 0.0;
  BodyDef striker = disk("striker", m, radius, {0.0, 0.0}, {v0, 0.0});
  BodyDef target = disk("target", m, radius, {d + 2.0 * radius, 0.0}, {0.0, 0.0});
  striker.drag_linear_kgps = target.drag_linear_kgps = k;
  world.bodies = {striker, target};
  const Timeline timeline = simulate(world);
  EXPECT_EQ(timeline.status(), SimulationStatus::kComplete);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const double t_hit = -std::log1p(-r * d / v0) / r, v_hit = v0 - r * d;
  EXPECT_NEAR(timeline.collisions()[0].time_s, t_hit, 1e-14 * t_hit);
  const Snapshot end = timeline.sample(world.duration_s);
  const double v_end = 0.5 * v_hit * std::exp(-r * (world.duration_s - t_hit));
  EXPECT_NEAR(end.bodies[0].velocity_mps.x(), v_end, 1e-14 * v0);
  EXPECT_NEAR(end.bodies[1].velocity_mps.x(), v_end, 1e-14 * v0);
  EXPECT_NEAR(end.bodies[1].position_m.x() - end.bodies[0].position_m.x(), 2.0 * radius, 1e-14);
  expectPlaneAirBooksAddUp(timeline, 100);
}

}  // namespace
}  // namespace collide::physics
