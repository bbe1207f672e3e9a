// The energy ledger: every impact's loss booked at its analytic value and summed with
// compensation; the difference of mechanical energies is only a check.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "physics/engine.hpp"
#include "physics/pi_blocks.hpp"
#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace {

using testing::block;
using testing::wall;

bool hasWarning(const Timeline& timeline, WarningKind kind) {
  for (const Warning& warning : timeline.warnings()) {
    if (warning.kind == kind) return true;
  }
  return false;
}

TEST(EnergyLedgerTest, CompensatedSumKeepsSmallLossesBesideALargeTotal) {
  detail::EnergyLedger ledger;
  ledger.add(1e16);
  // Each 1 J is half an ulp of 1e16: a plain sum rounds every one of them away.
  double plain = 1e16;
  for (int k = 0; k < 1000; ++k) {
    ledger.add(1.0);
    plain += 1.0;
  }
  EXPECT_EQ(plain, 1e16);
  EXPECT_EQ(ledger.total_J(), 1e16 + 1000.0);
}

TEST(EnergyLedgerTest, ExtremeMassRatioBooksTheAnalyticLoss) {
  // The worked example at masses 1e-12 and 1e12 kg: 1e-12 kg at +2 m/s meets 1e12 kg at -1 m/s,
  // e = 0.5. Closing speed 3 m/s; mu = m1 m2 / (m1 + m2) = 1e-12 (1 - 1e-24), so the loss is
  // 1/2 mu (1 - e^2) u^2 = 0.5 * 1e-12 * 0.75 * 9 = 3.375e-12 J. The kinetic energies
  // (5e11 J) cannot show it: their difference is pure round-off.
  const double m1 = 1e-12, m2 = 1e12, e = 0.5;
  WorldDef world;
  world.restitution = e;
  world.duration_s = 4.0;
  world.bodies = {block("a", m1, 0.5, -2.0, 2.0), block("b", m2, 0.5, 2.0, -1.0)};
  const Timeline timeline = simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const double mu = m1 * m2 / (m1 + m2);
  const double expected = 0.5 * mu * (1.0 - e * e) * 3.0 * 3.0;
  EXPECT_NEAR(expected, 3.375e-12, 1e-24);
  EXPECT_NEAR(timeline.totalEnergyLost(), expected, 1e-9 * expected);
  EXPECT_NEAR(timeline.sample(4.0).energy_lost_J, expected, 1e-9 * expected);
  // The measured difference agrees only within the round-off allowance of the 5e11 J involved.
  EXPECT_LE(std::abs(timeline.energyLostMeasured() - expected), timeline.energyLedgerTolerance());
  EXPECT_FALSE(hasWarning(timeline, WarningKind::kEnergyLedger));
  // A ratio of 1e24 is beyond what doubles resolve: said once.
  EXPECT_TRUE(hasWarning(timeline, WarningKind::kPrecision));
}

TEST(EnergyLedgerTest, APrecisionWarningNamesARatioBeyondADoubleInFigures) {
  // 1e18 kg against 1e-300 kg: a ratio of 10^(18 + 300) = 1e+318, more than a double holds
  // (about 1.8e308). The warning gives it in figures, never "inf".
  WorldDef world;
  world.duration_s = 1.0;
  world.bodies = {block("a", 1e-300, 0.5, -2.0, 2.0), block("b", 1e18, 0.5, 2.0, -1.0)};
  const Timeline timeline = simulate(world);
  int said = 0;
  for (const Warning& warning : timeline.warnings()) {
    if (warning.kind != WarningKind::kPrecision) continue;
    ++said;
    EXPECT_NE(warning.message.find("a ratio of 1e+318,"), std::string::npos) << warning.message;
    EXPECT_EQ(warning.message.find("inf"), std::string::npos) << warning.message;
  }
  EXPECT_EQ(said, 1);
}

TEST(EnergyLedgerTest, ElasticSceneBooksExactlyNothing) {
  const Timeline timeline = simulate(piBlocksWorld(6));
  EXPECT_EQ(timeline.totalEnergyLost(), 0.0);
  for (const CollisionEvent& event : timeline.collisions()) ASSERT_EQ(event.energy_lost_J, 0.0);
  // 314,159 impacts on 5e9 J: the measured difference is round-off, within the allowance.
  EXPECT_LE(std::abs(timeline.energyLostMeasured()), timeline.energyLedgerTolerance());
  EXPECT_FALSE(hasWarning(timeline, WarningKind::kEnergyLedger));
}

TEST(EnergyLedgerTest, BookedLossesAddUpToTheMechanicalEnergyDrop) {
  // A block bouncing on an e = 0.8 floor under gravity: every bounce books 1/2 m (1 - e^2) u^2
  // and the total equals the drop in mechanical energy.
  WorldDef world;
  world.duration_s = 3.0;
  world.gravity_mps2 = {-9.81, 0.0};
  world.bodies = {block("ball", 2.0, 0.2, 1.1, 0.0)};
  world.walls = {wall("floor", {0.0, 0.0}, {1.0, 0.0}, 0.8)};
  const Timeline timeline = simulate(world);
  ASSERT_GT(timeline.collisionCount(), 3);
  double sum = 0.0;
  for (const CollisionEvent& event : timeline.collisions()) {
    const double u = event.closing_speed_mps;
    EXPECT_NEAR(event.energy_lost_J,
                0.5 * 2.0 * (1.0 - event.restitution * event.restitution) * u * u,
                1e-12 * (1.0 + u * u));
    sum += event.energy_lost_J;
  }
  EXPECT_NEAR(timeline.totalEnergyLost(), sum, 1e-12 * sum);
  const Snapshot start = timeline.initialState(), end = timeline.sample(3.0);
  EXPECT_NEAR(timeline.mechanicalEnergy(start) - timeline.mechanicalEnergy(end), sum, 1e-9 * sum);
  EXPECT_FALSE(hasWarning(timeline, WarningKind::kEnergyLedger));
}

}  // namespace
}  // namespace collide::physics
