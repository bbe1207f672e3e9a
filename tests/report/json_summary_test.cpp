// The JSON summary of a two-block collision, with every expected number derived here.
#include "report/json_summary.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "physics/pi_blocks.hpp"
#include "physics/simulate.hpp"
#include "report/json_writer.hpp"
#include "report_test_scenes.hpp"

namespace collide::report {
namespace {

using test::contains;
using test::twoBlocks;

std::string summaryOf(const physics::WorldDef& world, bool events) {
  std::ostringstream out;
  writeJsonSummary(out, physics::simulate(world), {"two-blocks", events});
  return out.str();
}

TEST(JsonSummaryTest, ReportsMomentumEnergyAndFinalVelocities) {
  const double e = 0.5, m1 = 2.0, m2 = 1.0, v1 = 3.0, v2 = 0.0;
  const double p = m1 * v1 + m2 * v2;
  // Momentum conservation and v2' - v1' = e (v1 - v2).
  const double v1_after = (p - m2 * e * (v1 - v2)) / (m1 + m2);
  const double v2_after = v1_after + e * (v1 - v2);
  const double ke_before = 0.5 * m1 * v1 * v1;
  const double ke_after = 0.5 * m1 * v1_after * v1_after + 0.5 * m2 * v2_after * v2_after;

  const std::string json = summaryOf(twoBlocks(e), false);
  EXPECT_TRUE(contains(json, "\"scene\": \"two-blocks\"")) << json;
  EXPECT_TRUE(contains(json, "\"dimensions\": 1"));
  EXPECT_TRUE(contains(json, "\"collision_count\": 1"));
  EXPECT_TRUE(contains(json, "\"name\": \"left\""));
  EXPECT_TRUE(contains(json, "\"initial_velocity\": [3, 0]"));
  EXPECT_TRUE(contains(json, "\"final_velocity\": [" + shortestDecimal(v1_after) + ", 0]")) << json;
  EXPECT_TRUE(contains(json, "\"final_velocity\": [" + shortestDecimal(v2_after) + ", 0]")) << json;
  EXPECT_TRUE(contains(json, "\"momentum_initial\": [" + shortestDecimal(p) + ", 0]"));
  EXPECT_TRUE(contains(json, "\"kinetic_energy_initial\": " + shortestDecimal(ke_before)));
  // Final values are computed by the engine; compare numerically through the text.
  const std::size_t at = json.find("\"energy_lost\": ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_NEAR(std::stod(json.substr(at + 15)), ke_before - ke_after, 1e-12);
  EXPECT_FALSE(contains(json, "\"collisions\""));
}

TEST(JsonSummaryTest, EventsListEachCollisionWithItsPartnersAndEnergies) {
  const std::string json = summaryOf(twoBlocks(1.0), true);
  EXPECT_TRUE(contains(json, "\"collisions\": [")) << json;
  EXPECT_TRUE(contains(json, "\"a\": 0"));
  EXPECT_TRUE(contains(json, "\"b\": 1"));
  EXPECT_TRUE(contains(json, "\"restitution\": 1"));
  EXPECT_TRUE(contains(json, "\"normal\": [1, 0]"));
  // Elastic, equal closing speed reversed: before [3,0],[0,0]; after 1 and 4 m/s (m1 = 2 m2).
  EXPECT_TRUE(contains(json, "\"velocities_before\": [\n")) << json;
  EXPECT_TRUE(contains(json, "\"energy_lost_analytic\": 0"));
  // Time of impact: gap 1.5 m closed at 3 m/s.
  EXPECT_TRUE(contains(json, "\"time\": 0.5"));
}

}  // namespace
}  // namespace collide::report

namespace collide::report {
namespace {

std::size_t occurrences(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
    ++count;
  }
  return count;
}

TEST(JsonSummaryTest, EventsListEveryCollisionEvenPastTheStoredLog) {
  // Galperin's blocks with 2 digits: 31 collisions, of which only 4 are kept in memory.
  physics::WorldDef world = physics::piBlocksWorld(2);
  world.max_recorded_collisions = 4;
  const physics::Timeline timeline = physics::simulate(world);
  ASSERT_TRUE(timeline.collisionsTruncated());
  std::ostringstream out;
  writeJsonSummary(out, timeline, {"pi-blocks", true});
  EXPECT_NE(out.str().find("\"collision_count\": 31"), std::string::npos);
  EXPECT_EQ(occurrences(out.str(), "\"energy_lost_analytic\""), 31u);
}

}  // namespace
}  // namespace collide::report
