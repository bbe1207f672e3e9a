// The JSON summary of a two-block collision, with every expected number derived here.
#include "report/json_summary.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "physics/pi_blocks.hpp"
#include "physics/simulate.hpp"
#include "report/json_writer.hpp"
#include "report_test_scenes.hpp"

namespace collide::report {
namespace {

using test::twoBlocks;

// Version 1 (--data-version 1) unless asked otherwise: the tests of the older shape come first.
std::string summaryOf(const physics::WorldDef& world, bool events, int version = 1) {
  std::ostringstream out;
  writeJsonSummary(out, physics::simulate(world), {"two-blocks", events, version});
  return out.str();
}

// The numbers a reader of the file sees, parsed: x and y of a [x, y] pair.
core::Vec2 pair(const nlohmann::json& value) {
  EXPECT_TRUE(value.is_array() && value.size() == 2) << value;
  return {value.at(0).get<double>(), value.at(1).get<double>()};
}

TEST(JsonSummaryTest, ReportsMomentumEnergyAndFinalVelocities) {
  const double e = 0.5, m1 = 2.0, m2 = 1.0, v1 = 3.0, v2 = 0.0;
  const double p = m1 * v1 + m2 * v2;
  // Momentum conservation and v2' - v1' = e (v1 - v2).
  const double v1_after = (p - m2 * e * (v1 - v2)) / (m1 + m2);
  const double v2_after = v1_after + e * (v1 - v2);
  const double ke_before = 0.5 * m1 * v1 * v1;
  const double ke_after = 0.5 * m1 * v1_after * v1_after + 0.5 * m2 * v2_after * v2_after;

  const std::string text = summaryOf(twoBlocks(e), false);
  const nlohmann::json json = nlohmann::json::parse(text);
  EXPECT_EQ(json.at("scene"), "two-blocks") << text;
  EXPECT_EQ(json.at("dimensions"), 1);
  EXPECT_EQ(json.at("collision_count"), 1);
  ASSERT_EQ(json.at("bodies").size(), 2u);
  EXPECT_EQ(json.at("bodies")[0].at("name"), "left");
  EXPECT_EQ(json.at("bodies")[0].at("mass"), m1);
  EXPECT_EQ(pair(json.at("bodies")[0].at("initial_velocity")), core::Vec2(v1, 0.0));
  EXPECT_EQ(pair(json.at("bodies")[1].at("initial_velocity")), core::Vec2(v2, 0.0));
  EXPECT_NEAR(pair(json.at("bodies")[0].at("final_velocity")).x(), v1_after, 1e-14);
  EXPECT_NEAR(pair(json.at("bodies")[1].at("final_velocity")).x(), v2_after, 1e-14);
  EXPECT_EQ(pair(json.at("bodies")[1].at("final_velocity")).y(), 0.0);
  EXPECT_EQ(pair(json.at("momentum_initial")), core::Vec2(p, 0.0));
  EXPECT_NEAR(pair(json.at("momentum_final")).x(), p, 1e-14);
  EXPECT_EQ(json.at("kinetic_energy_initial").get<double>(), ke_before);
  EXPECT_NEAR(json.at("kinetic_energy_final").get<double>(), ke_after, 1e-13);
  EXPECT_NEAR(json.at("energy_lost").get<double>(), ke_before - ke_after, 1e-13);
  EXPECT_FALSE(json.contains("collisions"));
}

TEST(JsonSummaryTest, InitialQuantitiesAreTheStateBeforeAnImpactAtTimeZero) {
  // The blocks of twoBlocks, touching at t = 0 while "left" approaches: the impact happens at
  // t = 0, and the initial quantities are still the given ones (3 and 0 m/s, 1/2 2 3^2 = 9 J).
  physics::WorldDef world = twoBlocks(0.5);
  world.bodies[1].position_m.x() = world.bodies[0].position_m.x() + 0.5;
  const std::string text = summaryOf(world, false);
  const nlohmann::json json = nlohmann::json::parse(text);
  EXPECT_EQ(json.at("collision_count"), 1) << text;
  EXPECT_EQ(pair(json.at("bodies")[0].at("initial_velocity")), core::Vec2(3.0, 0.0)) << text;
  EXPECT_EQ(pair(json.at("bodies")[1].at("initial_velocity")), core::Vec2(0.0, 0.0)) << text;
  EXPECT_EQ(pair(json.at("momentum_initial")), core::Vec2(6.0, 0.0)) << text;
  EXPECT_EQ(json.at("kinetic_energy_initial").get<double>(), 9.0) << text;
}

// Each collision with its partners, time, velocities before and after and energy lost, all
// derived here: the blocks meet when the 1.5 m gap has closed at 3 m/s; the loss is
// ½ μ (1 − e²) u² with μ = m1 m2 / (m1 + m2) and u the closing speed.
TEST(JsonSummaryTest, EventsListEachCollisionWithItsPartnersAndEnergies) {
  for (const double e : {1.0, 0.5, 0.0}) {
    SCOPED_TRACE(e);
    const double m1 = 2.0, m2 = 1.0, u = 3.0, p = m1 * u;
    const double v1_after = (p - m2 * e * u) / (m1 + m2);
    const double v2_after = v1_after + e * u;
    const double loss = 0.5 * (m1 * m2 / (m1 + m2)) * (1.0 - e * e) * u * u;
    const std::string text = summaryOf(twoBlocks(e), true);
    const nlohmann::json json = nlohmann::json::parse(text);
    ASSERT_EQ(json.at("collisions").size(), 1u) << text;
    const nlohmann::json& c = json.at("collisions")[0];
    EXPECT_NEAR(c.at("time").get<double>(), 1.5 / 3.0, 1e-15);
    EXPECT_EQ(c.at("a"), 0);
    EXPECT_EQ(c.at("b"), 1);
    EXPECT_EQ(c.at("restitution").get<double>(), e);
    EXPECT_EQ(pair(c.at("normal")), core::Vec2(1.0, 0.0));
    ASSERT_EQ(c.at("velocities_before").size(), 2u);
    EXPECT_EQ(pair(c.at("velocities_before")[0]), core::Vec2(u, 0.0));
    EXPECT_EQ(pair(c.at("velocities_before")[1]), core::Vec2(0.0, 0.0));
    ASSERT_EQ(c.at("velocities_after").size(), 2u);
    EXPECT_NEAR(pair(c.at("velocities_after")[0]).x(), v1_after, 1e-14);
    EXPECT_NEAR(pair(c.at("velocities_after")[1]).x(), v2_after, 1e-14);
    EXPECT_NEAR(c.at("energy_lost").get<double>(), loss, 1e-13);
    EXPECT_NEAR(c.at("energy_lost_analytic").get<double>(), loss, 1e-13);
  }
}

}  // namespace
}  // namespace collide::report

namespace collide::report {
namespace {

TEST(JsonSummaryTest, EventsListEveryCollisionEvenPastTheStoredLog) {
  // Galperin's blocks with 2 digits: 31 collisions, of which only 4 are kept in memory.
  physics::WorldDef world = physics::piBlocksWorld(2);
  world.max_recorded_collisions = 4;
  const physics::Timeline timeline = physics::simulate(world);
  ASSERT_TRUE(timeline.collisionsTruncated());
  std::ostringstream out;
  writeJsonSummary(out, timeline, {"pi-blocks", true, 1});
  const nlohmann::json json = nlohmann::json::parse(out.str());
  EXPECT_EQ(json.at("collision_count"), 31);
  ASSERT_EQ(json.at("collisions").size(), 31u);
  // Galperin: every collision is elastic, so none loses energy.
  for (const nlohmann::json& collision : json.at("collisions")) {
    EXPECT_EQ(collision.at("energy_lost_analytic").get<double>(), 0.0) << collision;
  }
}

}  // namespace
}  // namespace collide::report
