// collide data --csv and --json, in-process: the table's shape, the clamp warning, the contract.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace collide {
namespace {

using Result = test::CliResult;
using test::run;

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

TEST(DataCliTest, CsvToStdoutHasOneRowPerStep) {
  const Result r = run({"data", "worked-example", "--csv", "-", "--dt", "0.05"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const std::vector<std::string> rows = lines(r.out);
  ASSERT_EQ(rows.size(), 1u + 81u);  // header and t = 0, 0.05, ..., 4 s
  EXPECT_EQ(rows[0],
            "t_s,cart 1_x_m,cart 1_v_mps,cart 1_p_kgmps,cart 1_ke_J,cart 1_pe_J,cart 2_x_m,"
            "cart 2_v_mps,cart 2_p_kgmps,cart 2_ke_J,cart 2_pe_J,p_total_kgmps,energy_lost_J,"
            "energy_released_J");
  // t = 0: cart 1 at -2 m moving at 2 m/s (p 2, KE 2 J), cart 2 at 2 m at -1 m/s (p -1, KE
  // 0.5 J), no gravity: the energy columns add up to 2.5 J.
  EXPECT_EQ(rows[1], "0,-2,2,2,2,0,2,-1,-1,0.5,0,1,0,0");
  EXPECT_EQ(rows.back().substr(0, 2), "4,");
}

TEST(DataCliTest, DataVersionOneWritesTheOlderShape) {
  const Result csv =
      run({"data", "worked-example", "--csv", "-", "--dt", "0.05", "--data-version", "1"});
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  const std::vector<std::string> rows = lines(csv.out);
  ASSERT_EQ(rows.size(), 1u + 81u);
  EXPECT_EQ(rows[0],
            "t_s,cart 1_x_m,cart 1_v_mps,cart 1_ke_J,cart 1_p_kgmps,cart 2_x_m,cart 2_v_mps,"
            "cart 2_ke_J,cart 2_p_kgmps,p_total_kgmps,ke_total_J,energy_lost_J");
  EXPECT_EQ(rows[1], "0,-2,2,2,2,2,-1,0.5,-1,1,2.5,0");
  const Result json =
      run({"data", "worked-example", "--json", "-", "--events", "--data-version", "1"});
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json summary = nlohmann::json::parse(json.out);
  EXPECT_FALSE(summary.contains("data_version"));
  ASSERT_EQ(summary.at("collisions").size(), 1u) << json.out;
  EXPECT_EQ(summary.at("collisions")[0].at("a"), 0);  // numbered from 0 in version 1
  EXPECT_EQ(summary.at("collisions")[0].at("b"), 1);
}

TEST(DataCliTest, DataVersionOutsideTheVersionsIsRefusedAsTyped) {
  for (const char* typed : {"0", "3", "-1"}) {
    const Result r = run({"data", "worked-example", "--json", "-", "--data-version", typed});
    EXPECT_EQ(r.exit_code, 2) << typed;
    EXPECT_EQ(r.err, "collide: --data-version: " + std::string(typed) +
                         ": allowed: 1 or 2 (the default)\n");
    EXPECT_TRUE(r.out.empty());
  }
  const Result alone = run({"data", "worked-example", "--tracker", "-", "--data-version", "1"});
  EXPECT_EQ(alone.exit_code, 2);
  EXPECT_EQ(alone.err,
            "collide: --data-version: only applies to --json and --csv; allowed: add --json "
            "PATH|- or --csv PATH|-\n");
}

TEST(DataCliTest, StepOutsideTheLimitsIsRefusedAsTyped) {
  // Every numeric option is checked like a scene value: exit 2, the value echoed as typed.
  for (const char* typed : {"1", "0.00001", "nan", "inf", "-0.01", "0.050000001"}) {
    const Result r = run({"data", "worked-example", "--csv", "-", "--dt", typed});
    EXPECT_EQ(r.exit_code, 2) << typed;
    EXPECT_EQ(r.err,
              "collide: --dt: " + std::string(typed) + ": allowed: 0.0005 to 0.05 seconds\n");
    EXPECT_TRUE(r.out.empty());
  }
  // The limits themselves are allowed: 0.05 s over 4 s is 81 rows after the header.
  const Result widest = run({"data", "worked-example", "--csv", "-", "--dt", "0.05"});
  ASSERT_EQ(widest.exit_code, 0) << widest.err;
  EXPECT_EQ(lines(widest.out).size(), 1u + 81u);
}

TEST(DataCliTest, JsonAndCsvTogetherAndTheirMisuse) {
  EXPECT_EQ(run({"data", "worked-example"}).exit_code, 2);
  EXPECT_EQ(run({"data", "worked-example", "--json", "-", "--csv", "-"}).exit_code, 2);
  EXPECT_EQ(run({"data", "worked-example", "--csv", "-", "--events"}).exit_code, 2);
  EXPECT_EQ(run({"data", "worked-example", "--json", "-", "--dt", "0.01"}).exit_code, 2);
  const Result json = run({"data", "worked-example", "--json", "-"});
  ASSERT_EQ(json.exit_code, 0);
  EXPECT_EQ(nlohmann::json::parse(json.out).at("collision_count"), 1) << json.out;
}

}  // namespace
}  // namespace collide

namespace collide {
namespace {

// --events through the command: the worked example's one collision, every number derived here
// (1 kg at +2 m/s meets 1 kg at −1 m/s, e = 0.5; the 3.5 m between their faces closes at 3 m/s,
// the centres 4 m apart, so the carts are 0.5 m from centre to centre when they meet).
TEST(DataCliTest, EventsCarryTheCollisionsNumbers) {
  const Result r = test::run({"data", "worked-example", "--json", "-", "--events"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json json = nlohmann::json::parse(r.out);
  ASSERT_EQ(json.at("events").size(), 1u) << r.out;
  const nlohmann::json& c = json.at("events")[0];
  const double m1 = 1.0, m2 = 1.0, v1 = 2.0, v2 = -1.0, e = 0.5, t = 3.5 / 3.0;
  EXPECT_EQ(c.at("kind"), "impact");
  EXPECT_EQ(c.at("a"), 1);
  EXPECT_EQ(c.at("b"), 2);
  EXPECT_NEAR(c.at("time").get<double>(), t, 1e-12);
  EXPECT_EQ(c.at("restitution").get<double>(), e);
  EXPECT_NEAR(c.at("positions")[0][0].get<double>(), -2.0 + v1 * t, 1e-12);
  EXPECT_NEAR(c.at("positions")[1][0].get<double>(), 2.0 + v2 * t, 1e-12);
  const double v1_after = ((m1 - e * m2) * v1 + (1 + e) * m2 * v2) / (m1 + m2);
  const double v2_after = ((1 + e) * m1 * v1 + (m2 - e * m1) * v2) / (m1 + m2);
  EXPECT_NEAR(c.at("velocities_before")[0][0].get<double>(), v1, 1e-15);
  EXPECT_NEAR(c.at("velocities_before")[1][0].get<double>(), v2, 1e-15);
  EXPECT_NEAR(c.at("velocities_after")[0][0].get<double>(), v1_after, 1e-14);
  EXPECT_NEAR(c.at("velocities_after")[1][0].get<double>(), v2_after, 1e-14);
  const double lost = 0.5 * (m1 * m2 / (m1 + m2)) * (1 - e * e) * (v1 - v2) * (v1 - v2);
  EXPECT_NEAR(c.at("energy_lost").get<double>(), lost, 1e-14);
  EXPECT_EQ(c.at("energy_released").get<double>(), 0.0);
  EXPECT_NEAR(json.at("energy_lost").get<double>(), lost, 1e-14);
}

}  // namespace
}  // namespace collide
