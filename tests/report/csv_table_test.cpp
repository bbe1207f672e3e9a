// The CSV table against the physics: every value recomputed here from momentum conservation and
// the definition of e.
#include "report/csv_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "report_test_scenes.hpp"

namespace collide::report {
namespace {

std::vector<std::vector<std::string>> parseCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::vector<std::string> fields;
    std::istringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) fields.push_back(cell);
    rows.push_back(fields);
  }
  return rows;
}

TEST(CsvTableTest, TimeStepIsClampedToTheReferenceLimits) {
  EXPECT_EQ(clampTimeStep(0.01).step_s, 0.01);
  EXPECT_FALSE(clampTimeStep(0.01).clamped);
  EXPECT_EQ(clampTimeStep(0.0001).step_s, 0.0005);
  EXPECT_TRUE(clampTimeStep(0.0001).clamped);
  EXPECT_EQ(clampTimeStep(1.0).step_s, 0.05);
  EXPECT_TRUE(clampTimeStep(1.0).clamped);
  EXPECT_TRUE(clampTimeStep(std::nan("")).clamped);
  EXPECT_FALSE(clampTimeStep(0.0005).clamped);
  EXPECT_FALSE(clampTimeStep(0.05).clamped);
}

TEST(CsvTableTest, RowTimesCoverTheDurationAndEndOnIt) {
  const std::vector<double> even = csvRowTimes(1.0, 0.1);
  ASSERT_EQ(even.size(), 11u);
  EXPECT_EQ(even[3], 0.3);  // rounded to the nanosecond, not 0.30000000000000004
  EXPECT_EQ(even.back(), 1.0);
  const std::vector<double> uneven = csvRowTimes(1.0, 0.3);
  ASSERT_EQ(uneven.size(), 5u);  // 0, 0.3, 0.6, 0.9 and the end
  EXPECT_EQ(uneven.back(), 1.0);
}

// Version 1, the older shape (--data-version 1).
TEST(CsvTableTest, ValuesMatchTheAnalyticCollision) {
  const double e = 0.5, m1 = 2.0, m2 = 1.0, u1 = 3.0, u2 = 0.0, t_hit = 0.5;
  const double p = m1 * u1 + m2 * u2;
  const double v1 = (p - m2 * e * (u1 - u2)) / (m1 + m2);  // momentum and v2 - v1 = e (u1 - u2)
  const double v2 = v1 + e * (u1 - u2);
  const double ke0 = 0.5 * m1 * u1 * u1 + 0.5 * m2 * u2 * u2;
  const double ke1 = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2;

  std::ostringstream out;
  writeCsv(out, physics::simulate(test::twoBlocks(e, 1.0)), 0.05, 1);
  const auto rows = parseCsv(out.str());
  ASSERT_EQ(rows.size(), 1u + 21u);  // header, t = 0, 0.05, ..., 1
  const std::vector<std::string> header = {"t_s",           "left_x_m",     "left_v_mps",
                                           "left_ke_J",     "left_p_kgmps", "right_x_m",
                                           "right_v_mps",   "right_ke_J",   "right_p_kgmps",
                                           "p_total_kgmps", "ke_total_J",   "energy_lost_J"};
  EXPECT_EQ(rows[0], header);

  for (std::size_t r = 1; r < rows.size(); ++r) {
    ASSERT_EQ(rows[r].size(), header.size()) << "row " << r;
    std::vector<double> value;
    for (const std::string& cell : rows[r]) value.push_back(std::stod(cell));
    const double t = value[0];
    EXPECT_NEAR(t, 0.05 * static_cast<double>(r - 1), 1e-12);
    const bool after = t >= t_hit;
    const double x1 = after ? -1.0 + u1 * t_hit + v1 * (t - t_hit) : -1.0 + u1 * t;
    const double x2 = after ? 1.0 + v2 * (t - t_hit) : 1.0;
    const double w1 = after ? v1 : u1, w2 = after ? v2 : u2;
    EXPECT_NEAR(value[1], x1, 1e-9) << "t = " << t;
    EXPECT_NEAR(value[2], w1, 1e-9);
    EXPECT_NEAR(value[3], 0.5 * m1 * w1 * w1, 1e-9);
    EXPECT_NEAR(value[4], m1 * w1, 1e-9);
    EXPECT_NEAR(value[5], x2, 1e-9) << "t = " << t;
    EXPECT_NEAR(value[6], w2, 1e-9);
    EXPECT_NEAR(value[7], 0.5 * m2 * w2 * w2, 1e-9);
    EXPECT_NEAR(value[8], m2 * w2, 1e-9);
    EXPECT_NEAR(value[9], p, 1e-9);
    EXPECT_NEAR(value[10], after ? ke1 : ke0, 1e-9);
    EXPECT_NEAR(value[11], after ? ke0 - ke1 : 0.0, 1e-9);
  }
}

TEST(CsvTableTest, TwoDimensionalColumnsAndQuotedNames) {
  physics::WorldDef world;
  world.dimensions = 2;
  world.bodies.push_back({"a, b", physics::Shape::kDisk, 1.0, 0.1, {0.0, 0.0}, {1.0, 2.0}});
  EXPECT_EQ(csvHeader(world),
            "t_s,\"a, b_x_m\",\"a, b_y_m\",\"a, b_vx_mps\",\"a, b_vy_mps\",\"a, b_ke_J\","
            "\"a, b_px_kgmps\",\"a, b_py_kgmps\",px_total_kgmps,py_total_kgmps,ke_total_J,"
            "energy_lost_J");
}

}  // namespace
}  // namespace collide::report
