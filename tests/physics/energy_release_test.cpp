// SPDX-License-Identifier: MIT
// Energy that comes in: super-elastic impacts (e > 1) and releases of stored energy between
// touching bodies. Expected velocities come from conservation of momentum with the definition of
// e (v_b' - v_a' = e u) or with the released energy (1/2 mu s'^2 - 1/2 mu s^2 = Q); the books
// (kinetic + lost = at the start + released) are checked at every sampled instant.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace energy_release_test {

using testing::block;
using testing::disk;
using testing::wall;

bool hasWarning(const Timeline& timeline, WarningKind kind) {
  for (const Warning& warning : timeline.warnings()) {
    if (warning.kind == kind) return true;
  }
  return false;
}

// The books at 400 instants: every part adds up to the energy at the start plus what was
// released by then, within 1e-9 of the largest energy involved.
void expectBooksBalance(const Timeline& timeline) {
  const double initial_J = timeline.initialKineticEnergy();
  const double scale_J = initial_J + timeline.totalEnergyReleased();
  ASSERT_GT(scale_J, 0.0);
  constexpr int kSamples = 400;
  for (int k = 0; k <= kSamples; ++k) {
    const double t = timeline.duration_s() * k / kSamples;
    const EnergyBooks books = energyBooks(timeline, t);
    EXPECT_NEAR(books.total_J(), initial_J + books.released_J, 1e-9 * scale_J) << "t = " << t;
    EXPECT_GE(books.lost_J, 0.0);
    EXPECT_GE(books.released_J, 0.0);
  }
}

TEST(SuperElasticTest, PairSeparatesAtEClosingSpeedAndGainsHalfMuE2Minus1U2) {
  const double m1 = 1.0, m2 = 3.0, v1 = 2.0, v2 = -1.0, e = 1.5;
  WorldDef world;
  world.duration_s = 3.0;
  world.restitution = e;
  world.bodies = {block("a", m1, 0.5, -2.0, v1), block("b", m2, 0.5, 2.0, v2)};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const CollisionEvent& event = timeline.collisions()[0];
  // Sum p kept and v2' - v1' = e u.
  const double u = v1 - v2, p = m1 * v1 + m2 * v2;
  const double v1_after = (p - m2 * e * u) / (m1 + m2), v2_after = v1_after + e * u;
  EXPECT_NEAR(event.velocity_a_after_mps.x(), v1_after, 1e-14);
  EXPECT_NEAR(event.velocity_b_after_mps.x(), v2_after, 1e-14);
  const double mu = m1 * m2 / (m1 + m2);
  const double gain = 0.5 * mu * (e * e - 1.0) * u * u;
  EXPECT_NEAR(event.energy_released_J, gain, 1e-13);
  EXPECT_EQ(event.energy_lost_J, 0.0);
  EXPECT_NEAR(timeline.totalEnergyReleased(), gain, 1e-13);
  EXPECT_EQ(timeline.totalEnergyLost(), 0.0);
  // The gain is what the kinetic energy grew by.
  const double before = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2;
  const double after = 0.5 * m1 * v1_after * v1_after + 0.5 * m2 * v2_after * v2_after;
  EXPECT_NEAR(after - before, gain, 1e-12);
  EXPECT_FALSE(hasWarning(timeline, WarningKind::kEnergyLedger));
  expectBooksBalance(timeline);
}

TEST(SuperElasticTest, WallReturnsEUAndDiskPairKeepsTangentialVelocities) {
  WorldDef world;
  world.duration_s = 2.0;
  world.bodies = {block("a", 2.0, 0.2, 1.0, -2.0)};
  world.walls = {wall("w", {0.0, 0.0}, {1.0, 0.0}, 1.25)};
  const Timeline line = simulate(world);
  ASSERT_EQ(line.collisionCount(), 1);
  EXPECT_NEAR(line.collisions()[0].velocity_a_after_mps.x(), 2.5, 1e-15);
  EXPECT_NEAR(line.totalEnergyReleased(), 0.5 * 2.0 * (1.25 * 1.25 - 1.0) * 4.0, 1e-14);

  // Equal disks, head-on along x with a shared y velocity: the normal parts follow the 1D law
  // (equal masses: they swap and grow by e), the tangential part is kept.
  WorldDef plane;
  plane.dimensions = 2;
  plane.duration_s = 2.0;
  plane.restitution = 2.0;
  plane.bodies = {disk("a", 1.0, 0.1, {-1.0, 0.0}, {1.0, 0.5}),
                  disk("b", 1.0, 0.1, {1.0, 0.0}, {-1.0, 0.5})};
  const Timeline timeline = simulate(plane);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const CollisionEvent& event = timeline.collisions()[0];
  // u = 2; p_x = 0, so v_a' = -e u / 2 = -2, v_b' = +2.
  EXPECT_NEAR(event.velocity_a_after_mps.x(), -2.0, 1e-14);
  EXPECT_NEAR(event.velocity_b_after_mps.x(), 2.0, 1e-14);
  EXPECT_NEAR(event.velocity_a_after_mps.y(), 0.5, 1e-15);
  EXPECT_NEAR(event.energy_released_J, 0.5 * 0.5 * (4.0 - 1.0) * 4.0, 1e-13);
  expectBooksBalance(timeline);
}

TEST(SuperElasticTest, RunawayBetweenWallsIsCappedWithAWarningAndStaysFinite) {
  // Each impact doubles the closing speed: without the cap the speeds overflow after ~1000.
  WorldDef world;
  world.duration_s = 5.0;
  world.restitution = 2.0;
  world.bodies = {block("a", 1.0, 0.2, -0.5, 1.0), block("b", 1.0, 0.2, 0.5, 0.0)};
  world.walls = {wall("l", {-1.0, 0.0}, {1.0, 0.0}, 2.0), wall("r", {1.0, 0.0}, {-1.0, 0.0}, 2.0)};
  world.max_collisions = 200000;
  const Timeline timeline = simulate(world);
  EXPECT_TRUE(hasWarning(timeline, WarningKind::kSuperElasticCap));
  const Snapshot end = timeline.sample(world.duration_s);
  for (const BodyState& body : end.bodies) {
    // The cap: no impact faster than 1000 times the starting speed (1 m/s) gains energy, and
    // e <= 2 once more at most.
    EXPECT_LE(std::abs(body.velocity_mps.x()), 2.0 * 1000.0 * 2.0);
  }
  EXPECT_TRUE(std::isfinite(timeline.totalEnergyReleased()));
  EXPECT_FALSE(hasWarning(timeline, WarningKind::kEnergyLedger));
}

// Two blocks at rest, touching, pushed apart by Q: Sum p = 0 and 1/2 m1 v1^2 + 1/2 m2 v2^2 = Q
// give v2 = sqrt(2 Q m1 / (m2 (m1 + m2))), v1 = -m2 v2 / m1.
TEST(ReleaseTest, EnergyReleasedFromRestGivesEqualAndOppositeMomenta) {
  const double m1 = 1.0, m2 = 2.0, q = 3.0, t_release = 0.5;
  WorldDef world;
  world.duration_s = 3.0;
  world.bodies = {block("a", m1, 0.5, -0.25, 0.0), block("b", m2, 0.6, 0.3, 0.0)};
  world.releases = {{0, 1, t_release, q, 0.0}};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const CollisionEvent& event = timeline.collisions()[0];
  EXPECT_TRUE(event.release);
  EXPECT_EQ(event.time_s, t_release);
  const double v2 = std::sqrt(2.0 * q * m1 / (m2 * (m1 + m2))), v1 = -m2 * v2 / m1;
  EXPECT_NEAR(v2, 1.0, 1e-15);  // the preset's round numbers
  const Snapshot after = timeline.sample(1.0);
  EXPECT_NEAR(after.bodies[0].velocity_mps.x(), v1, 1e-14);
  EXPECT_NEAR(after.bodies[1].velocity_mps.x(), v2, 1e-14);
  EXPECT_NEAR(m1 * after.bodies[0].velocity_mps.x() + m2 * after.bodies[1].velocity_mps.x(), 0.0,
              1e-14);
  // At rest and in place until the release.
  const Snapshot before = timeline.sample(0.49);
  EXPECT_EQ(before.bodies[0].velocity_mps.x(), 0.0);
  EXPECT_EQ(before.bodies[1].position_m.x(), 0.3);
  EXPECT_DOUBLE_EQ(timeline.totalEnergyReleased(), q);
  EXPECT_DOUBLE_EQ(event.energy_released_J, q);
  EXPECT_EQ(timeline.totalEnergyLost(), 0.0);
  EXPECT_FALSE(hasWarning(timeline, WarningKind::kEnergyLedger));
  expectBooksBalance(timeline);
}

TEST(ReleaseTest, StatedSpeedAddsToTheSeparationOfAMovingPair) {
  // Moving together at 1 m/s; the release adds 2 m/s of separation: Sum p = 4 kg m/s kept,
  // v_b' - v_a' = 2, so v_a' = (4 - 3 * 2) / 4 = -0.5, v_b' = 1.5; Q = 1/2 mu 2^2 = 1.5 J.
  WorldDef world;
  world.duration_s = 2.0;
  world.bodies = {block("a", 1.0, 0.5, 0.0, 1.0), block("b", 3.0, 0.5, 0.5, 1.0)};
  world.releases = {{0, 1, 0.0, 0.0, 2.0}};
  const Timeline timeline = simulate(world);
  const Snapshot s = timeline.sample(1.0);
  EXPECT_NEAR(s.bodies[0].velocity_mps.x(), -0.5, 1e-15);
  EXPECT_NEAR(s.bodies[1].velocity_mps.x(), 1.5, 1e-15);
  EXPECT_NEAR(timeline.totalEnergyReleased(), 0.5 * 0.75 * 4.0, 1e-15);
  expectBooksBalance(timeline);
}

TEST(ReleaseTest, RecoilOfARifleFromTheBulletsShare) {
  // 4 kg rifle, 10 g bullet, Q = 802 J: the bullet takes m_r / (m_r + m_b) of Q.
  const double m_r = 4.0, m_b = 0.01, q = 802.0;
  WorldDef world;
  world.duration_s = 1.0;
  world.bodies = {block("rifle", m_r, 1.0, 0.0, 0.0), block("bullet", m_b, 0.05, 0.525, 0.0)};
  world.releases = {{0, 1, 0.25, q, 0.0}};
  const Timeline timeline = simulate(world);
  const Snapshot s = timeline.sample(0.5);
  const double recoil = -std::sqrt(2.0 * q * m_b / (m_r * (m_r + m_b)));
  const double bullet = -m_r * recoil / m_b;
  EXPECT_NEAR(recoil, -1.0, 1e-15);
  EXPECT_NEAR(s.bodies[0].velocity_mps.x(), recoil, 1e-13);
  EXPECT_NEAR(s.bodies[1].velocity_mps.x(), bullet, 1e-10);
  expectBooksBalance(timeline);
}

TEST(ReleaseTest, BodiesThatNoLongerTouchReleaseNothingAndSaySo) {
  WorldDef world;
  world.duration_s = 2.0;
  world.bodies = {block("a", 1.0, 0.5, 0.0, 0.0), block("b", 1.0, 0.5, 0.5, 1.0)};
  world.releases = {{0, 1, 1.0, 5.0, 0.0}};
  const Timeline timeline = simulate(world);
  EXPECT_EQ(timeline.collisionCount(), 0);
  EXPECT_TRUE(hasWarning(timeline, WarningKind::kReleaseSkipped));
  EXPECT_EQ(timeline.totalEnergyReleased(), 0.0);
  EXPECT_EQ(timeline.sample(2.0).bodies[0].velocity_mps.x(), 0.0);
}

}  // namespace energy_release_test
}  // namespace collide::physics
