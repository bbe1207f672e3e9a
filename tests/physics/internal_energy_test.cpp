// SPDX-License-Identifier: MIT
// Molecules with insides: the Borgnakke-Larsen exchange. Expected values come from conservation
// (translational + internal energy and momentum are kept), from the Beta distribution's mean
// (a / (a + b)), from detailed balance (at equilibrium a collision is as likely to gain kinetic
// energy as to lose it), from equipartition (every degree of freedom holds kT/2) and from the
// two-dimensional Maxwell-Boltzmann distribution (speeds Rayleigh: <v^4> = 2 <v^2>^2).
#include "physics/internal_energy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "random_scenes.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace internal_energy_test {

using testing::disk;
using testing::numbered;

// 196 disks (radius 3 cm, 10 g, 14 x 14) in a 2 m box, velocity components uniform in
// [-1, 1) m/s: about 10^4 disk-disk collisions in 40 s. Internal energies start at 0.
WorldDef gasWithInsides(int internal_dof, double duration_s = 40.0) {
  WorldDef world;
  world.dimensions = 2;
  world.duration_s = duration_s;
  world.internal_dof = internal_dof;
  world.walls = testing::boxWalls(1.0);
  testing::Dice dice(11);
  for (int k = 0; k < 196; ++k) {
    const core::Vec2 centre(-0.91 + 0.14 * (k % 14), -0.91 + 0.14 * (k / 14));
    world.bodies.push_back(disk(numbered("d", k), 0.01, 0.03, centre,
                                {dice.uniform(-1.0, 1.0), dice.uniform(-1.0, 1.0)}));
  }
  return world;
}

double pairKinetic_J(const WorldDef& world, const CollisionEvent& event, bool after) {
  const core::Vec2& va = after ? event.velocity_a_after_mps : event.velocity_a_before_mps;
  const core::Vec2& vb = after ? event.velocity_b_after_mps : event.velocity_b_before_mps;
  return 0.5 * world.bodies[event.body_a].mass_kg * va.squaredNorm() +
         0.5 * world.bodies[event.body_b].mass_kg * vb.squaredNorm();
}

TEST(MoleculesWithInsidesSharesTest, FollowTheirBetaMeansAndAddUpToTheCollisionEnergy) {
  // X = E_tr' / E_c ~ Beta(3/2, zeta): mean 3 / (3 + 2 zeta); each internal share has mean
  // (zeta / 2) / (3/2 + zeta). 10^5 draws: the standard error is below 1e-3.
  for (int dof : {1, 2}) {
    std::uint64_t state = 1234;
    constexpr int kDraws = 100000;
    double sum_x = 0.0, sum_a = 0.0, sum_b = 0.0;
    for (int k = 0; k < kDraws; ++k) {
      const detail::Shares s = detail::borgnakkeLarsen(0.7, 0.2, 0.1, dof, state);
      EXPECT_NEAR(s.translational_J + s.internal_a_J + s.internal_b_J, 1.0, 1e-15);
      ASSERT_GE(s.translational_J, 0.0);
      ASSERT_GE(s.internal_a_J, 0.0);
      ASSERT_GE(s.internal_b_J, 0.0);
      sum_x += s.translational_J, sum_a += s.internal_a_J, sum_b += s.internal_b_J;
    }
    const double zeta = dof;
    EXPECT_NEAR(sum_x / kDraws, 3.0 / (3.0 + 2.0 * zeta), 4e-3) << "zeta " << dof;
    EXPECT_NEAR(sum_a / kDraws, 0.5 * zeta / (1.5 + zeta), 4e-3) << "zeta " << dof;
    EXPECT_NEAR(sum_b / kDraws, 0.5 * zeta / (1.5 + zeta), 4e-3) << "zeta " << dof;
  }
}

TEST(BorgnakkeLarsenTest, ImpulseKeepsTheReboundDirectionAndSetsTheSharedEnergy) {
  // Masses 1 and 3 kg (mu = 3/4), g = (2, 1) closing along n = (1, 0): the rebound's direction
  // is (-2, 1), and 1/2 mu g'^2 = 0.6 J gives |g'| = sqrt(1.6).
  const core::Vec2 va(2.0, 1.0), vb(0.0, 0.0), n(1.0, 0.0);
  const double ma = 1.0, mb = 3.0, mu = 0.75;
  const core::Vec2 j = detail::exchangeImpulse(va, vb, n, mu, 0.6);
  const core::Vec2 va_after = va + j / ma, vb_after = vb - j / mb;
  const core::Vec2 g_after = va_after - vb_after;
  EXPECT_NEAR(0.5 * mu * g_after.squaredNorm(), 0.6, 1e-15);
  EXPECT_NEAR(g_after.normalized().x(), -2.0 / std::sqrt(5.0), 1e-15);
  EXPECT_NEAR(g_after.normalized().y(), 1.0 / std::sqrt(5.0), 1e-15);
  const core::Vec2 p_change = ma * (va_after - va) + mb * (vb_after - vb);
  EXPECT_NEAR(p_change.norm(), 0.0, 1e-15);
}

// Everything below simulates the gas (10^4 collisions and more): Release only (scripts/test
// leaves MoleculesWithInsides* out of the sanitizer pass, as it does the 10^5 draws above).
TEST(MoleculesWithInsidesGasTest, TranslationalPlusInternalEnergyIsKeptOver10000Collisions) {
  const Timeline timeline = simulate(gasWithInsides(2));
  ASSERT_EQ(timeline.status(), SimulationStatus::kComplete);
  ASSERT_GE(timeline.collisionCount(), 10000);
  const double initial_J = timeline.initialKineticEnergy();
  for (int k = 0; k <= 40; ++k) {
    const EnergyBooks books = energyBooks(timeline, timeline.duration_s() * k / 40);
    EXPECT_NEAR(books.kineticTotal_J() + books.internal_J, initial_J, 1e-9 * initial_J) << k;
    EXPECT_EQ(books.lost_J, 0.0);
    EXPECT_NEAR(books.total_J(), initial_J, 1e-9 * initial_J) << k;
  }
  // Energy went inside: by the end the disks hold a good part of it there.
  EXPECT_GT(energyBooks(timeline, timeline.duration_s()).internal_J, 0.3 * initial_J);
  EXPECT_TRUE(timeline.warnings().empty());
}

TEST(MoleculesWithInsidesGasTest, AboutHalfTheCollisionsGainKineticEnergy) {
  // At equilibrium detailed balance makes a gain exactly as likely as a loss; from a cold start
  // the first collisions mostly lose, so all 10^4 still lie within 40 % to 60 %.
  const WorldDef world = gasWithInsides(2);
  const Timeline timeline = simulate(world);
  const std::vector<CollisionEvent>& events = timeline.collisions();
  int pairs = 0, gains = 0, late_pairs = 0, late_gains = 0;
  for (const CollisionEvent& event : events) {
    if (event.body_b < 0) continue;
    const bool gain = pairKinetic_J(world, event, true) > pairKinetic_J(world, event, false);
    ++pairs, gains += gain;
    if (event.time_s > 0.5 * world.duration_s) ++late_pairs, late_gains += gain;
  }
  ASSERT_GE(pairs, 10000);
  const double fraction = double(gains) / pairs, late = double(late_gains) / late_pairs;
  EXPECT_GT(fraction, 0.40);
  EXPECT_LT(fraction, 0.60);
  // Relaxed: within 3 standard errors of 1/2 (sqrt(1/4 / n) ~ 0.007 for n ~ 5000).
  EXPECT_NEAR(late, 0.5, 3.0 * std::sqrt(0.25 / late_pairs)) << late_pairs;
}

// The time average over the second half of a run of the internal energy per internal degree
// of freedom, over the translational energy per translational one (2 per disk).
double equipartitionRatio(const Timeline& timeline, int internal_dof) {
  double internal_J = 0.0, translational_J = 0.0;
  for (int k = 0; k <= 200; ++k) {
    const double t = timeline.duration_s() * (0.5 + 0.5 * k / 200);
    const EnergyBooks books = energyBooks(timeline, t);
    internal_J += books.internal_J;
    translational_J += books.kineticTotal_J();
  }
  return (internal_J / internal_dof) / (translational_J / 2.0);
}

TEST(MoleculesWithInsidesGasTest, InternalAndTranslationalEnergyReachEquipartition) {
  for (int dof : {1, 2}) {
    const Timeline timeline = simulate(gasWithInsides(dof, 60.0));
    EXPECT_NEAR(equipartitionRatio(timeline, dof), 1.0, 0.05) << "zeta " << dof;
  }
}

TEST(MoleculesWithInsidesGasTest, SpeedsRelaxToMaxwellBoltzmann) {
  // In a plane Maxwell-Boltzmann speeds are Rayleigh distributed: <v^4> = 8 s^4, <v^2> = 2 s^2,
  // so <v^4> / <v^2>^2 = 2 at any temperature. The start (components uniform in a square) has
  // (1/5 + 2/9 + 1/5) / (2/3)^2 = 1.4.
  const Timeline timeline = simulate(gasWithInsides(2));
  double v2 = 0.0, v4 = 0.0;
  for (int k = 0; k <= 40; ++k) {
    const Snapshot snapshot = timeline.sample(timeline.duration_s() * (0.5 + 0.5 * k / 40));
    for (const BodyState& body : snapshot.bodies) {
      const double s2 = body.velocity_mps.squaredNorm();
      v2 += s2, v4 += s2 * s2;
    }
  }
  const double n = 41.0 * 196.0;
  EXPECT_NEAR((v4 / n) / ((v2 / n) * (v2 / n)), 2.0, 0.1);
}

TEST(MoleculesWithInsidesGasTest, TheSeedMakesRunsRepeatAndSamplingReplaysThem) {
  const Timeline first = simulate(gasWithInsides(1, 10.0));
  const Timeline second = simulate(gasWithInsides(1, 10.0));
  ASSERT_EQ(first.collisionCount(), second.collisionCount());
  for (std::size_t i = 0; i < first.collisions().size(); ++i) {
    ASSERT_EQ(first.collisions()[i].velocity_a_after_mps,
              second.collisions()[i].velocity_a_after_mps);
  }
  // Backwards, then forwards: the checkpoints carry the generator's state and the insides.
  const double late = first.sample(9.0).internal_energy_J;
  EXPECT_EQ(first.sample(1.0).internal_energy_J, second.sample(1.0).internal_energy_J);
  EXPECT_EQ(first.sample(9.0).internal_energy_J, late);
}

}  // namespace internal_energy_test
}  // namespace collide::physics
