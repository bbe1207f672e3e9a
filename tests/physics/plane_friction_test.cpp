// SPDX-License-Identifier: MIT
// Sliding friction on a table (2D): every expected number from the closed forms of motion under a
// constant deceleration mu g along the velocity (a disk at v stops after v / (mu g), having slid
// v^2 / (2 mu g) along its velocity), conservation of momentum at the impacts, and the books
// (kinetic + lost + to the surface = the start; the disks' momentum + the surface's = the start,
// as vectors). Times of impact are checked against roots found here independently: bisection on
// the distance of the centres computed from the closed-form positions in long double.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace plane_friction_test {

using testing::disk;
using testing::wall;

constexpr double kSurfaceG = 9.81;  // the table's g, m/s^2

BodyDef slidingDisk(const char* name, double mass_kg, double radius_m, core::Vec2 x_m,
                    core::Vec2 v_mps, double mu) {
  BodyDef body = disk(name, mass_kg, radius_m, x_m, v_mps);
  body.friction = mu;
  body.static_friction = mu;
  return body;
}

WorldDef table(double duration_s) {
  WorldDef world;
  world.dimensions = 2;
  world.duration_s = duration_s;
  world.surface_gravity_mps2 = kSurfaceG;
  return world;
}

// Where a disk that starts at x0 with v0 and slows at mu g is at time t (long double), and
// whether it has stopped by then.
struct Slide {
  long double x0, y0, vx, vy, decel;
  void at(long double t, long double& x, long double& y) const {
    const long double speed = std::sqrt(vx * vx + vy * vy);
    const long double stop = speed > 0 ? speed / decel : 0;
    const long double tau = std::min(t, stop);
    const long double along = speed > 0 ? speed * tau - 0.5L * decel * tau * tau : 0;
    x = x0 + (speed > 0 ? vx / speed * along : 0);
    y = y0 + (speed > 0 ? vy / speed * along : 0);
  }
  static Slide of(const BodyDef& b) {
    return {b.position_m.x(), b.position_m.y(), b.velocity_mps.x(), b.velocity_mps.y(),
            static_cast<long double>(b.friction) * kSurfaceG};
  }
};

// The first time two sliding disks touch, by bisection on their distance less the summed radii
// over a bracket [lo, hi] where it changes sign once.
double meetingTime(const Slide& a, const Slide& b, long double reach, long double lo,
                   long double hi) {
  auto gap = [&](long double t) {
    long double xa, ya, xb, yb;
    a.at(t, xa, ya);
    b.at(t, xb, yb);
    return std::hypot(xb - xa, yb - ya) - reach;
  };
  EXPECT_GT(gap(lo), 0.0L);
  EXPECT_LT(gap(hi), 0.0L);
  for (int k = 0; k < 200; ++k) {
    const long double mid = 0.5L * (lo + hi);
    (gap(mid) > 0 ? lo : hi) = mid;
  }
  return static_cast<double>(0.5L * (lo + hi));
}

// Kinetic + lost + to the surface, against the start's energy, at `samples` instants.
void expectBooksAddUp(const Timeline& timeline, int samples) {
  const double start_J = energyBooks(timeline, 0.0).total_J();
  double surface_before = 0.0;
  for (int k = 0; k <= samples; ++k) {
    const double t = timeline.duration_s() * k / samples;
    const EnergyBooks books = energyBooks(timeline, t);
    EXPECT_NEAR(books.total_J(), start_J, 1e-12 * start_J) << "t " << t;
    EXPECT_GE(books.surface_J, surface_before - 1e-14 * start_J) << "t " << t;
    surface_before = books.surface_J;
  }
}

TEST(PlaneFrictionTest, ADiskStopsAfterVOverMuGHavingSlidVSquaredOverTwoMuGAlongItsPath) {
  const double mu = 0.25, m = 0.17;
  const core::Vec2 v(1.2, -0.5);  // |v| = 1.3
  WorldDef world = table(1.0);
  world.bodies = {slidingDisk("puck", m, 0.03, {0.1, 0.2}, v, mu)};
  const Timeline timeline = simulate(world);
  const double speed = 1.3, t_stop = speed / (mu * kSurfaceG);
  const double d = speed * speed / (2.0 * mu * kSurfaceG);
  const core::Vec2 heading = v / speed;
  // Before the stop: along a straight line, s = v t - mu g t^2 / 2.
  const double t_half = 0.5 * t_stop;
  const Snapshot half = timeline.sample(t_half);
  const double s_half = speed * t_half - 0.5 * mu * kSurfaceG * t_half * t_half;
  EXPECT_NEAR((half.bodies[0].position_m - (core::Vec2(0.1, 0.2) + s_half * heading)).norm(), 0.0,
              1e-15);
  EXPECT_NEAR((half.bodies[0].velocity_mps - (speed - mu * kSurfaceG * t_half) * heading).norm(),
              0.0, 1e-15);
  // After it: at rest where the closed form puts it, and held there.
  for (double t : {t_stop * (1.0 + 1e-12), 0.9, 1.0}) {
    const Snapshot s = timeline.sample(t);
    EXPECT_NEAR((s.bodies[0].position_m - (core::Vec2(0.1, 0.2) + d * heading)).norm(), 0.0, 1e-15)
        << "t " << t;
    EXPECT_EQ(s.bodies[0].velocity_mps.norm(), 0.0) << "t " << t;
  }
  const Snapshot before = timeline.sample(t_stop * (1.0 - 1e-6));
  EXPECT_NEAR(before.bodies[0].velocity_mps.norm(), mu * kSurfaceG * t_stop * 1e-6, 1e-12);
  // All its kinetic energy and momentum (a vector) went into the surface.
  const Snapshot end = timeline.sample(1.0);
  EXPECT_NEAR(end.energy_to_surface_J, 0.5 * m * speed * speed, 1e-15);
  EXPECT_NEAR((end.surface_momentum_kgmps - m * v).norm(), 0.0, 1e-15);
  EXPECT_TRUE(timeline.warnings().empty());
  expectBooksAddUp(timeline, 40);
}

TEST(PlaneFrictionTest, ADiskMeetsAWallAtTheRootOfItsQuadraticAndStopsOnTheWayBack) {
  // Towards the wall x = 1 at 45 degrees: the gap along x is 1 - r - x0 - vx t + mu g t^2 / (2
  // sqrt 2), its smaller root the impact; an elastic wall turns vx round, and the disk slows on
  // along its new heading to a stop.
  const double mu = 0.2, r = 0.05, x0 = 0.0, v = 3.0;
  const double g = mu * kSurfaceG, c = std::sqrt(0.5);
  WorldDef world = table(2.0);
  world.bodies = {slidingDisk("puck", 1.0, r, {x0, 0.0}, {v * c, v * c}, mu)};
  world.walls = {wall("cushion", {1.0, 0.0}, {-1.0, 0.0})};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisions().size(), 1u);
  // g_x = gap0 - v c t + g c t^2 / 2 = 0, the smaller root in the stable form.
  const double gap0 = 1.0 - r - x0;
  const double disc = v * c * v * c - 2.0 * g * c * gap0;
  const double t_hit = 2.0 * gap0 / (v * c + std::sqrt(disc));
  EXPECT_NEAR(timeline.collisions()[0].time_s, t_hit, 1e-15 * t_hit);
  // The speed is unchanged by the elastic wall: it stops at v / (mu g) in all, after sliding
  // v^2 / (2 mu g) along the folded path.
  const double t_stop = v / g, path = v * v / (2.0 * g);
  const double s_hit = v * t_hit - 0.5 * g * t_hit * t_hit;
  const core::Vec2 at_wall(x0 + s_hit * c, s_hit * c);
  const core::Vec2 expected = at_wall + (path - s_hit) * core::Vec2(-c, c);
  const Snapshot end = timeline.sample(2.0);
  EXPECT_NEAR((end.bodies[0].position_m - expected).norm(), 0.0, 1e-14);
  EXPECT_EQ(end.bodies[0].velocity_mps.norm(), 0.0);
  EXPECT_GT(2.0, t_stop);
  EXPECT_NEAR(end.energy_to_surface_J, 0.5 * v * v, 1e-14);
  expectBooksAddUp(timeline, 40);
}

TEST(PlaneFrictionTest, TwoDisksSlowingAlongDifferentLinesMeetAtTheRootOfTheirGap) {
  // Two pucks slowing on crossing paths (different mu, so the relative motion is no straight
  // line): their distance less the radii is a quartic's root in t, found here by bisection on
  // the closed-form positions.
  WorldDef world = table(1.5);
  world.bodies = {slidingDisk("a", 0.2, 0.04, {-1.0, 0.05}, {3.0, 0.1}, 0.3),
                  slidingDisk("b", 0.3, 0.05, {0.0, -0.7}, {0.1, 1.9}, 0.1)};
  const Timeline timeline = simulate(world);
  ASSERT_GE(timeline.collisions().size(), 1u);
  const double t =
      meetingTime(Slide::of(world.bodies[0]), Slide::of(world.bodies[1]), 0.09L, 0.0L, 0.45L);
  EXPECT_NEAR(timeline.collisions()[0].time_s, t, 4e-15);
  // Momentum at the impact: the disks' change is equal and opposite.
  const CollisionEvent& hit = timeline.collisions()[0];
  const core::Vec2 dp_a = 0.2 * (hit.velocity_a_after_mps - hit.velocity_a_before_mps);
  const core::Vec2 dp_b = 0.3 * (hit.velocity_b_after_mps - hit.velocity_b_before_mps);
  EXPECT_NEAR((dp_a + dp_b).norm(), 0.0, 1e-15);
  expectBooksAddUp(timeline, 60);
  // The disks' momentum plus the surface's is the start's, a vector, at every instant.
  const core::Vec2 p0 = timeline.momentum(timeline.initialState());
  for (int k = 0; k <= 30; ++k) {
    const Snapshot s = timeline.sample(1.5 * k / 30);
    EXPECT_NEAR((timeline.momentum(s) + s.surface_momentum_kgmps - p0).norm(), 0.0, 1e-15);
  }
}

TEST(PlaneFrictionTest, AGrazeOfADiskSlidingPastOneAtRestIsNotMissed) {
  // The moving disk's path passes the resting one's centre at 1 - 1e-9 of the summed radii:
  // the gap dips below zero for a moment only, and that moment is the impact.
  const double reach = 0.1, offset = reach * (1.0 - 1e-9);
  WorldDef world = table(1.0);
  world.bodies = {slidingDisk("moving", 1.0, 0.05, {-0.5, 0.0}, {1.5, 0.0}, 0.1),
                  slidingDisk("resting", 1.0, 0.05, {0.0, offset}, {0.0, 0.0}, 0.1)};
  const Timeline timeline = simulate(world);
  ASSERT_GE(timeline.collisions().size(), 1u);
  // Along x alone: x(t) = -0.5 + 1.5 t - mu g t^2 / 2 reaches -sqrt(reach^2 - offset^2).
  const double dx = std::sqrt((reach - offset) * (reach + offset));
  const double g = 0.1 * kSurfaceG, gap0 = 0.5 - dx;
  const double t_hit = 2.0 * gap0 / (1.5 + std::sqrt(1.5 * 1.5 - 2.0 * g * gap0));
  // A graze's time is ill-conditioned: a rounding of the positions, 1e-16 m, moves it by that
  // over the normal closing speed (1.2 m/s times dx / reach = 5e-5): 2e-12 s.
  EXPECT_NEAR(timeline.collisions()[0].time_s, t_hit, 1e-10);
}

TEST(PlaneFrictionTest, ALockedPairSkidsVSquaredOverTwoMuGWithItsMassWeightedMu) {
  // Head-on, e = 0 with sticking: the pair moves off at V = m_a v_hit / (m_a + m_b) and skids
  // V^2 / (2 mu g) with mu = (mu_a m_a + mu_b m_b) / (m_a + m_b).
  const double ma = 1500.0, mb = 1000.0, mua = 0.7, mub = 0.5, v0 = 20.0, gap = 5.0;
  WorldDef world = table(6.0);
  world.restitution = 0.0;
  world.inelastic_mode = InelasticMode::kStick;
  world.bodies = {slidingDisk("car 1", ma, 2.0, {0.0, 0.0}, {v0, 0.0}, mua),
                  slidingDisk("car 2", mb, 2.0, {4.0 + gap, 0.0}, {0.0, 0.0}, mub)};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisions().size(), 1u);
  const double ga = mua * kSurfaceG;
  const double v_hit = std::sqrt(v0 * v0 - 2.0 * ga * gap);
  const double t_hit = (v0 - v_hit) / ga;
  EXPECT_NEAR(timeline.collisions()[0].time_s, t_hit, 1e-14);
  const double big_v = ma * v_hit / (ma + mb), mu = (mua * ma + mub * mb) / (ma + mb);
  const double skid = big_v * big_v / (2.0 * mu * kSurfaceG);
  const double x_hit = gap;  // car 1 slid the gap; the centre of mass is then at
  const double com_hit = (ma * x_hit + mb * (4.0 + gap)) / (ma + mb);
  const Snapshot end = timeline.sample(6.0);
  const double com_end =
      (ma * end.bodies[0].position_m.x() + mb * end.bodies[1].position_m.x()) / (ma + mb);
  EXPECT_NEAR(com_end - com_hit, skid, 1e-12);
  EXPECT_EQ(end.bodies[0].velocity_mps.norm(), 0.0);
  EXPECT_EQ(end.bodies[1].velocity_mps.norm(), 0.0);
  EXPECT_EQ(timeline.status(), SimulationStatus::kComplete);
  // All the momentum ended in the surface; all the energy in the surface or lost at the lock.
  EXPECT_NEAR(end.surface_momentum_kgmps.x(), ma * v0, 1e-12 * ma * v0);
  EXPECT_NEAR(end.energy_to_surface_J + end.energy_lost_J, 0.5 * ma * v0 * v0,
              1e-13 * ma * v0 * v0);
}

TEST(PlaneFrictionTest, AStuckPairThatWouldTurnStopsTheRunWithAWarning) {
  // Off-centre, e = 0 with sticking: the pair spins, which friction would slow in no closed
  // form: the run stops at the impact and says why.
  WorldDef world = table(2.0);
  world.restitution = 0.0;
  world.inelastic_mode = InelasticMode::kStick;
  world.bodies = {slidingDisk("a", 1.0, 0.05, {-0.5, 0.0}, {2.0, 0.0}, 0.2),
                  slidingDisk("b", 1.0, 0.05, {0.0, 0.05}, {0.0, 0.0}, 0.2)};
  const Timeline timeline = simulate(world);
  EXPECT_EQ(timeline.status(), SimulationStatus::kStalled);
  ASSERT_FALSE(timeline.warnings().empty());
  EXPECT_NE(timeline.warnings().back().message.find("would turn as it slides with friction"),
            std::string::npos)
      << timeline.warnings().back().message;
}

}  // namespace plane_friction_test
}  // namespace collide::physics
