// SPDX-License-Identifier: MIT
// Version 2 of the JSON summary (the default): bodies numbered from 1, positions and energies at
// both ends, and "events" of every kind whose losses add up; every expected number derived here.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "physics/pi_blocks.hpp"
#include "physics/simulate.hpp"
#include "report/json_summary.hpp"
#include "report_test_scenes.hpp"

namespace collide::report {
namespace {

nlohmann::json versionTwoSummary(const physics::WorldDef& world, bool events) {
  std::ostringstream out;
  writeJsonSummary(out, physics::simulate(world), {"scene", events});
  return nlohmann::json::parse(out.str());
}

double xOf(const nlohmann::json& vector) {
  return vector.at(0).get<double>();
}
double yOf(const nlohmann::json& vector) {
  return vector.at(1).get<double>();
}

double eventSum(const nlohmann::json& events, const char* key) {
  double sum = 0.0;
  for (const nlohmann::json& event : events) sum += event.at(key).get<double>();
  return sum;
}

TEST(JsonEventsTest, SummaryNumbersBodiesFromOneWithPositionsAndEnergies) {
  // twoBlocks with e = 0.5: 2 kg at -1 m moving at 3 m/s meets 1 kg at rest at 1 m at t = 0.5 s.
  const double e = 0.5, m1 = 2.0, m2 = 1.0, u = 3.0;
  const double v1 = (m1 * u - m2 * e * u) / (m1 + m2), v2 = v1 + e * u;
  const double ke0 = 0.5 * m1 * u * u;
  const nlohmann::json json = versionTwoSummary(test::twoBlocks(e), false);
  EXPECT_EQ(json.at("data_version"), 2);
  EXPECT_EQ(json.at("gravity"), nlohmann::json::array({0.0, 0.0}));
  ASSERT_EQ(json.at("bodies").size(), 2u);
  const nlohmann::json &left = json.at("bodies")[0], &right = json.at("bodies")[1];
  EXPECT_EQ(left.at("number"), 1);
  EXPECT_EQ(right.at("number"), 2);
  EXPECT_EQ(xOf(left.at("initial_position")), -1.0);
  EXPECT_EQ(xOf(right.at("initial_position")), 1.0);
  // At the end (3 s): from the impact's place (0.5 m and 1 m) at the velocities after.
  EXPECT_NEAR(xOf(left.at("final_position")), -1.0 + u * 0.5 + v1 * 2.5, 1e-12);
  EXPECT_NEAR(xOf(right.at("final_position")), 1.0 + v2 * 2.5, 1e-12);
  EXPECT_EQ(json.at("energy_initial").get<double>(), ke0);
  EXPECT_EQ(json.at("potential_energy_initial").get<double>(), 0.0);
  EXPECT_EQ(json.at("energy_released").get<double>(), 0.0);
  const double lost = 0.5 * (m1 * m2 / (m1 + m2)) * (1.0 - e * e) * u * u;
  EXPECT_NEAR(json.at("energy_lost").get<double>(), lost, 1e-13);
  EXPECT_NEAR(json.at("energy_final").get<double>(), ke0 - lost, 1e-13);
  EXPECT_FALSE(json.contains("events"));
  EXPECT_FALSE(json.contains("collisions"));
}

TEST(JsonEventsTest, ImpactAndWallEventsWithPositionsAndPartners) {
  // twoBlocksAndWall: after the impact at 0.5 s (positions 0.5 m and 1 m), "right" at v2 reaches
  // the wall at 3 m with its face (0.25 m from its centre) at 0.5 + 1.75 / v2 s.
  const double e = 0.5, m1 = 2.0, m2 = 1.0, u = 3.0;
  const double v1 = (m1 * u - m2 * e * u) / (m1 + m2), v2 = v1 + e * u;
  const nlohmann::json json = versionTwoSummary(test::twoBlocksAndWall(e), true);
  const nlohmann::json& events = json.at("events");
  ASSERT_GE(events.size(), 2u) << json;
  const nlohmann::json &impact = events[0], &wall = events[1];
  EXPECT_EQ(impact.at("kind"), "impact");
  EXPECT_EQ(impact.at("a"), 1);
  EXPECT_EQ(impact.at("b"), 2);
  EXPECT_NEAR(impact.at("time").get<double>(), 0.5, 1e-15);
  ASSERT_EQ(impact.at("positions").size(), 2u);
  EXPECT_NEAR(xOf(impact.at("positions")[0]), 0.5, 1e-12);
  EXPECT_NEAR(xOf(impact.at("positions")[1]), 1.0, 1e-12);
  EXPECT_NEAR(xOf(impact.at("velocities_after")[0]), v1, 1e-14);
  EXPECT_NEAR(xOf(impact.at("velocities_after")[1]), v2, 1e-14);
  EXPECT_EQ(wall.at("kind"), "wall");
  EXPECT_EQ(wall.at("a"), 2);
  EXPECT_EQ(wall.at("b"), nlohmann::json({{"wall", "far"}}));
  EXPECT_NEAR(wall.at("time").get<double>(), 0.5 + 1.75 / v2, 1e-12);
  ASSERT_EQ(wall.at("positions").size(), 1u);  // a wall has no entry
  EXPECT_NEAR(xOf(wall.at("positions")[0]), 2.75, 1e-12);
  EXPECT_NEAR(xOf(wall.at("velocities_after")[0]), -v2, 1e-12);  // the wall's e is 1
  EXPECT_NEAR(eventSum(events, "energy_lost"), json.at("energy_lost").get<double>(), 1e-13);
}

TEST(JsonEventsTest, EventsListEveryCollisionEvenPastTheStoredLog) {
  // Galperin's blocks with 2 digits: 31 elastic collisions, of which only 4 are kept in memory.
  physics::WorldDef world = physics::piBlocksWorld(2);
  world.max_recorded_collisions = 4;
  const nlohmann::json json = versionTwoSummary(world, true);
  ASSERT_EQ(json.at("events").size(), 31u);
  for (const nlohmann::json& event : json.at("events")) {
    EXPECT_TRUE(event.at("kind") == "impact" || event.at("kind") == "wall") << event;
    EXPECT_EQ(event.at("energy_lost").get<double>(), 0.0) << event;
  }
}

// Soft contacts (0.1 s each): twoBlocks meet at 0.5 s; a third block at 5 m moving at 1 m/s meets
// a wall at 5.8 m with its face (0.25 m ahead) at 0.55 s, while the first contact lasts. The log
// is in time order: both starts, then both ends, each end where its pair just touches again.
TEST(JsonEventsTest, SoftContactsStartAndEndInTimeOrder) {
  physics::WorldDef world = test::twoBlocks(0.5, 0.7);
  world.contact_model = physics::ContactModel::kSpringDamper;
  world.contact_duration_s = 0.1;
  world.bodies.push_back({"third", physics::Shape::kBlock, 1.0, 0.5, {5.0, 0.0}, {1.0, 0.0}});
  world.walls.push_back({"far wall", {5.8, 0.0}, {-1.0, 0.0}, 1.0});
  const nlohmann::json json = versionTwoSummary(world, true);
  const nlohmann::json& events = json.at("events");
  ASSERT_EQ(events.size(), 4u) << json;
  const char* kinds[] = {"contact_start", "contact_start", "contact_end", "contact_end"};
  const double times[] = {0.5, 0.55, 0.6, 0.65};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(events[k].at("kind"), kinds[k]) << events[k];
    EXPECT_NEAR(events[k].at("time").get<double>(), times[k], 1e-9) << events[k];
  }
  EXPECT_EQ(events[2].at("a"), 1);
  EXPECT_EQ(events[2].at("b"), 2);
  EXPECT_NEAR(events[2].at("duration").get<double>(), 0.1, 1e-9);
  EXPECT_NEAR(xOf(events[2].at("positions")[1]) - xOf(events[2].at("positions")[0]), 0.5, 1e-9);
  EXPECT_EQ(events[3].at("b"), nlohmann::json({{"wall", "far wall"}}));
  EXPECT_NEAR(xOf(events[3].at("positions")[0]), 5.8 - 0.25, 1e-9);
  EXPECT_EQ(events[0].at("energy_lost").get<double>(), 0.0);  // booked at the end
  const double lost = json.at("energy_lost").get<double>();
  EXPECT_GT(events[2].at("energy_lost").get<double>(), 0.0);
  EXPECT_NEAR(eventSum(events, "energy_lost"), lost, 1e-12 * lost);
}

// A 1 kg bob on a 1 m string, at the bottom moving at 6 m/s: between sqrt(2 g L) and
// sqrt(5 g L), so the string goes slack where the tension m (v^2 / L + g cos theta) reaches 0,
// with v^2 = v0^2 - 2 g L (1 - cos theta): cos theta = (2 g L - v0^2) / (3 g L). The bob flies a
// parabola, and the string snaps taut with a loss: the events' losses add up to energy_lost.
TEST(JsonEventsTest, AStringGoingSlackAndTautIsLoggedWithItsLoss) {
  const double g = 9.81, length = 1.0, v0 = 6.0, m = 1.0;
  physics::WorldDef world;
  world.dimensions = 2;
  world.duration_s = 1.5;
  world.gravity_mps2 = {0.0, -g};
  physics::BodyDef bob{"bob", physics::Shape::kDisk, m, 0.05, {0.0, -length}, {v0, 0.0}};
  bob.on_string = true;
  bob.pivot_m = {0.0, 0.0};
  world.bodies.push_back(bob);
  const nlohmann::json json = versionTwoSummary(world, true);
  const nlohmann::json& events = json.at("events");
  ASSERT_GE(events.size(), 2u) << json;
  const nlohmann::json &slack = events[0], &taut = events[1];
  EXPECT_EQ(slack.at("kind"), "string_slack");
  EXPECT_EQ(slack.at("a"), 1);
  EXPECT_FALSE(slack.contains("b"));
  const double cos_theta = (2.0 * g * length - v0 * v0) / (3.0 * g * length);
  const double sin_theta = std::sqrt(1.0 - cos_theta * cos_theta);
  EXPECT_NEAR(xOf(slack.at("positions")[0]), length * sin_theta, 1e-9);
  EXPECT_NEAR(yOf(slack.at("positions")[0]), -length * cos_theta, 1e-9);
  const double speed = std::sqrt(v0 * v0 - 2.0 * g * length * (1.0 - cos_theta));
  EXPECT_NEAR(
      std::hypot(xOf(slack.at("velocities_before")[0]), yOf(slack.at("velocities_before")[0])),
      speed, 1e-9);
  EXPECT_EQ(slack.at("energy_lost").get<double>(), 0.0);
  EXPECT_EQ(taut.at("kind"), "string_taut");
  // The jerk takes the velocity along the string (string restitution 0): 1/2 m (v.r)^2, r the
  // unit vector from the pivot to the bob.
  const double rx = xOf(taut.at("positions")[0]), ry = yOf(taut.at("positions")[0]);
  EXPECT_NEAR(std::hypot(rx, ry), length, 1e-9);
  const double radial =
      (xOf(taut.at("velocities_before")[0]) * rx + yOf(taut.at("velocities_before")[0]) * ry) /
      length;
  EXPECT_NEAR(taut.at("energy_lost").get<double>(), 0.5 * m * radial * radial, 1e-9);
  EXPECT_GT(taut.at("energy_lost").get<double>(), 0.0);
  const double lost = json.at("energy_lost").get<double>();
  EXPECT_NEAR(eventSum(events, "energy_lost"), lost, 1e-12 * lost);
  // The books: 1/2 m v0^2 + m g (-L) at the start.
  EXPECT_NEAR(json.at("energy_initial").get<double>(), 0.5 * m * v0 * v0 - m * g * length, 1e-12);
  EXPECT_NEAR(json.at("energy_final").get<double>() + lost, json.at("energy_initial").get<double>(),
              1e-9);
}

}  // namespace
}  // namespace collide::report
