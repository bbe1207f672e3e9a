// SPDX-License-Identifier: MIT
// Sliding friction on a line: every expected number from the closed forms of motion under a
// constant deceleration mu g (a block at v stops after v / (mu g), having slid v^2 / (2 mu g)),
// conservation of momentum at the impacts, and the books (kinetic + lost + to the surface = the
// start; the bodies' momentum + the surface's = the start).
#include <gtest/gtest.h>

#include <cmath>

#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace {

using testing::block;

constexpr double kSurfaceG = 9.81;  // the surface's g, m/s^2

BodyDef slidingBlock(const char* name, double mass_kg, double x_m, double v_mps, double mu) {
  BodyDef body = block(name, mass_kg, 0.2, x_m, v_mps);
  body.friction = mu;
  body.static_friction = mu;
  return body;
}

WorldDef frictionWorld(double duration_s) {
  WorldDef world;
  world.dimensions = 1;
  world.duration_s = duration_s;
  world.surface_gravity_mps2 = kSurfaceG;
  return world;
}

// Kinetic + gravity + lost + to the surface, against the start's energy and what was released,
// at `samples` instants over the run.
void expectSurfaceBooksAddUp(const Timeline& timeline, int samples) {
  const double start_J = energyBooks(timeline, 0.0).total_J();
  for (int k = 0; k <= samples; ++k) {
    const double t = timeline.duration_s() * k / samples;
    const EnergyBooks books = energyBooks(timeline, t);
    EXPECT_NEAR(books.total_J(), start_J + books.released_J, 1e-12 * start_J) << "t " << t;
    EXPECT_GE(books.surface_J, 0.0);
  }
}

TEST(FrictionTest, ABlockStopsAfterVOverMuGHavingSlidVSquaredOverTwoMuG) {
  const double v = 2.0, mu = 0.3, m = 1.5;
  WorldDef world = frictionWorld(2.0);
  world.bodies = {slidingBlock("block", m, 0.0, v, mu)};
  const Timeline timeline = simulate(world);
  const double t_stop = v / (mu * kSurfaceG), d = v * v / (2.0 * mu * kSurfaceG);
  // Before the stop: x = v t - mu g t^2 / 2 exactly (to rounding).
  const double t_half = 0.5 * t_stop;
  const Snapshot half = timeline.sample(t_half);
  EXPECT_NEAR(half.bodies[0].position_m.x(), v * t_half - 0.5 * mu * kSurfaceG * t_half * t_half,
              1e-15);
  EXPECT_NEAR(half.bodies[0].velocity_mps.x(), v - mu * kSurfaceG * t_half, 1e-15);
  // After it: at rest where the closed form puts it, and held there.
  for (double t : {t_stop * (1.0 + 1e-12), 1.0, 2.0}) {
    const Snapshot s = timeline.sample(t);
    EXPECT_NEAR(s.bodies[0].position_m.x(), d, 1e-15) << "t " << t;
    EXPECT_EQ(s.bodies[0].velocity_mps.x(), 0.0) << "t " << t;
  }
  // Just before the stop it still moves, at mu g times the time left.
  const Snapshot before = timeline.sample(t_stop * (1.0 - 1e-6));
  EXPECT_NEAR(before.bodies[0].velocity_mps.x(), mu * kSurfaceG * t_stop * 1e-6, 1e-12);
  // All its kinetic energy and momentum went into the surface.
  const Snapshot end = timeline.sample(2.0);
  EXPECT_NEAR(end.energy_to_surface_J, 0.5 * m * v * v, 1e-14);
  EXPECT_NEAR(end.surface_momentum_kgmps.x(), m * v, 1e-14);
  EXPECT_NEAR(timeline.totalEnergyToSurface(), 0.5 * m * v * v, 1e-14);
  EXPECT_TRUE(timeline.warnings().empty());
  expectSurfaceBooksAddUp(timeline, 40);
}

TEST(FrictionTest, StaticFrictionHoldsABlockOnASlopeThatKineticFrictionCouldNot) {
  // Sliding up a slope (gravity -2 m/s^2 along the line) it decelerates at 2 + mu_k g and stops
  // after v / (2 + mu_k g); then mu_s g = 2.943 m/s^2 > 2 holds it.
  const double v = 1.0, mu_k = 0.1, g_along = -2.0;
  WorldDef world = frictionWorld(1.0);
  BodyDef body = slidingBlock("block", 1.0, 0.0, v, mu_k);
  body.static_friction = 0.3;
  world.bodies = {body};
  world.gravity_mps2 = {g_along, 0.0};
  const double decel = -g_along + mu_k * kSurfaceG;
  const double t_stop = v / decel, d = v * v / (2.0 * decel);
  const Timeline held = simulate(world);
  for (double t : {t_stop * (1.0 + 1e-9), 0.7, 1.0}) {
    const Snapshot s = held.sample(t);
    EXPECT_NEAR(s.bodies[0].position_m.x(), d, 1e-15) << "t " << t;
    EXPECT_EQ(s.bodies[0].velocity_mps.x(), 0.0) << "t " << t;
  }
  // With mu_s = 0.15 (1.47 m/s^2 < 2) it slides back down at 2 - mu_k g from the stop.
  world.bodies[0].static_friction = 0.15;
  const Timeline slides = simulate(world);
  const double back = -g_along - mu_k * kSurfaceG;
  const double t = 1.0, dt = t - t_stop;
  const Snapshot s = slides.sample(t);
  EXPECT_NEAR(s.bodies[0].velocity_mps.x(), -back * dt, 1e-14);
  EXPECT_NEAR(s.bodies[0].position_m.x(), d - 0.5 * back * dt * dt, 1e-14);
  expectSurfaceBooksAddUp(held, 20);
  expectSurfaceBooksAddUp(slides, 20);
}

TEST(FrictionTest, TwoDeceleratingBlocksMeetAtTheRootOfTheirQuadraticGap) {
  // Gap g(t) = d - (v1 - v2) t + (mu1 - mu2) g t^2 / 2 while both slide (the front block stops
  // at v2 / (mu2 g) = 0.34 s, after the root).
  const double v1 = 3.0, v2 = 1.0, mu1 = 0.1, mu2 = 0.3, d = 0.5;
  WorldDef world = frictionWorld(1.0);
  world.bodies = {slidingBlock("behind", 1.0, 0.0, v1, mu1),
                  slidingBlock("ahead", 2.0, 0.2 + d, v2, mu2)};
  const Timeline timeline = simulate(world);
  ASSERT_GE(timeline.collisionCount(), 1);
  // c2 t^2 + c1 t + c0 = 0 with the cancellation-free formula, the smaller positive root.
  const double c2 = 0.5 * (mu1 - mu2) * kSurfaceG, c1 = -(v1 - v2), c0 = d;
  const double q = -0.5 * (c1 - std::sqrt(c1 * c1 - 4.0 * c2 * c0));
  const double t_meet = c0 / q;
  ASSERT_LT(t_meet, v2 / (mu2 * kSurfaceG));
  const CollisionEvent& first = timeline.collisions().front();
  EXPECT_NEAR(first.time_s, t_meet, 4e-16 * t_meet);
  EXPECT_NEAR(first.velocity_a_before_mps.x(), v1 - mu1 * kSurfaceG * t_meet, 1e-14);
  EXPECT_NEAR(first.velocity_b_before_mps.x(), v2 - mu2 * kSurfaceG * t_meet, 1e-14);
  expectSurfaceBooksAddUp(timeline, 40);
}

TEST(FrictionTest, ALockedPairSkidsVSquaredOverTwoMuGAndTheSurfaceTakesTheMomentum) {
  // A 1500 kg car at 20 m/s locks (e = 0) with a 1000 kg car at rest 1 m ahead; both skid with
  // mu = 0.7. The car slides 1 m first: v_hit^2 = 20^2 - 2 mu g (1 m). Momentum at the impact
  // gives V = 1500 v_hit / 2500, and the pair skids V^2 / (2 mu g).
  const double m1 = 1500.0, m2 = 1000.0, v1 = 20.0, mu = 0.7, gap = 1.0;
  WorldDef world = frictionWorld(4.0);
  world.restitution = 0.0;
  world.bodies = {slidingBlock("car 1", m1, 0.0, v1, mu),
                  slidingBlock("car 2", m2, 0.2 + gap, 0.0, mu)};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const double v_hit = std::sqrt(v1 * v1 - 2.0 * mu * kSurfaceG * gap);
  const double big_v = m1 * v_hit / (m1 + m2);
  const CollisionEvent& impact = timeline.collisions().front();
  EXPECT_TRUE(impact.merged);
  EXPECT_NEAR(impact.velocity_a_before_mps.x(), v_hit, 1e-12);
  EXPECT_NEAR(impact.velocity_a_after_mps.x(), big_v, 1e-12);
  const double skid = big_v * big_v / (2.0 * mu * kSurfaceG);
  const Snapshot end = timeline.sample(4.0);
  EXPECT_NEAR(end.bodies[1].position_m.x() - (0.2 + gap), skid, 1e-12);
  EXPECT_EQ(end.bodies[0].velocity_mps.x(), 0.0);
  // Momentum: the bodies' and the surface's add up to the start's at every instant.
  for (int k = 0; k <= 40; ++k) {
    const Snapshot s = timeline.sample(4.0 * k / 40);
    EXPECT_NEAR(timeline.momentum(s).x() + s.surface_momentum_kgmps.x(), m1 * v1, 1e-10);
  }
  // Energy: the impact took 1/2 mu_red v_hit^2, the surface the rest of the start's.
  const double lost = 0.5 * (m1 * m2 / (m1 + m2)) * v_hit * v_hit;
  EXPECT_NEAR(timeline.totalEnergyLost(), lost, 1e-9);
  EXPECT_NEAR(timeline.totalEnergyToSurface(), 0.5 * m1 * v1 * v1 - lost, 1e-9);
  expectSurfaceBooksAddUp(timeline, 40);
}

TEST(FrictionTest, ABlockPushedByALessRoughOneSlidesOnWithItAsOne) {
  // Touching at 2 m/s, mu 0.1 behind and 0.5 ahead: the one behind presses on, so the two
  // slide as one at the mass-weighted deceleration (0.1 * 1 + 0.5 * 3) g / 4 = 0.4 g.
  WorldDef world = frictionWorld(1.0);
  world.bodies = {slidingBlock("behind", 1.0, 0.0, 2.0, 0.1),
                  slidingBlock("ahead", 3.0, 0.2, 2.0, 0.5)};
  const Timeline timeline = simulate(world);
  const double decel = 0.4 * kSurfaceG, t_stop = 2.0 / decel;
  for (double t : {0.25, 0.5, 1.0}) {
    const Snapshot s = timeline.sample(t);
    const double tau = std::min(t, t_stop);
    const double x = 2.0 * tau - 0.5 * decel * tau * tau;
    EXPECT_NEAR(s.bodies[0].position_m.x(), x, 1e-14) << "t " << t;
    EXPECT_NEAR(s.bodies[1].position_m.x(), 0.2 + x, 1e-14) << "t " << t;
  }
  EXPECT_EQ(timeline.collisionCount(), 0);
  expectSurfaceBooksAddUp(timeline, 20);
}

TEST(FrictionTest, ABlockAtRestOnALevelTrackStaysThereAndFrictionlessBlocksAreUntouched) {
  WorldDef world = frictionWorld(1.0);
  world.bodies = {slidingBlock("moving", 1.0, 0.0, 1.0, 0.0),
                  slidingBlock("resting", 1.0, 5.0, 0.0, 0.4)};
  const Timeline timeline = simulate(world);
  const Snapshot end = timeline.sample(1.0);
  EXPECT_EQ(end.bodies[0].position_m.x(), 1.0);  // mu = 0: free flight, exactly
  EXPECT_EQ(end.bodies[1].position_m.x(), 5.0);
  EXPECT_EQ(end.energy_to_surface_J, 0.0);
}

}  // namespace
}  // namespace collide::physics
