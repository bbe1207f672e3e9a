// SPDX-License-Identifier: MIT
// Version 2 of the CSV (the default): the energy books in every row, every expected number derived
// here from momentum conservation, the definition of e and free fall.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "report/csv_table.hpp"
#include "report_test_scenes.hpp"

namespace collide::report {
namespace {

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;

  std::size_t column(const std::string& name) const {
    for (std::size_t k = 0; k < header.size(); ++k) {
      if (header[k] == name) return k;
    }
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
  // Every _J column but energy_released_J, less energy_released_J: the energy at the start.
  double books(const std::vector<double>& row) const {
    double sum = 0.0;
    for (std::size_t k = 0; k < header.size(); ++k) {
      const std::string& name = header[k];
      if (name.size() < 2 || name.compare(name.size() - 2, 2, "_J") != 0) continue;
      sum += name == "energy_released_J" ? -row[k] : row[k];
    }
    return sum;
  }
};

Table tableOf(const physics::WorldDef& world, double step_s) {
  std::ostringstream out;
  writeCsv(out, physics::simulate(world), step_s);
  Table table;
  std::istringstream lines(out.str());
  std::string line;
  for (bool first = true; std::getline(lines, line); first = false) {
    std::istringstream cells(line);
    std::vector<double> values;
    for (std::string cell; std::getline(cells, cell, ',');) {
      if (first) {
        table.header.push_back(cell);
      } else {
        values.push_back(std::stod(cell));
      }
    }
    if (!first) table.rows.push_back(values);
  }
  return table;
}

TEST(CsvBooksTest, TwoBlocksRowsMatchTheAnalyticCollision) {
  const double e = 0.5, m1 = 2.0, m2 = 1.0, u1 = 3.0, t_hit = 0.5;
  const double v1 = (m1 * u1 - m2 * e * u1) / (m1 + m2);  // momentum and v2 - v1 = e u1
  const double v2 = v1 + e * u1;
  const double ke0 = 0.5 * m1 * u1 * u1;
  const double lost = 0.5 * (m1 * m2 / (m1 + m2)) * (1.0 - e * e) * u1 * u1;
  const Table table = tableOf(test::twoBlocks(e, 1.0), 0.05);
  const std::vector<std::string> header = {
      "t_s",        "left_x_m",      "left_v_mps",    "left_p_kgmps",     "left_ke_J",
      "left_pe_J",  "right_x_m",     "right_v_mps",   "right_p_kgmps",    "right_ke_J",
      "right_pe_J", "p_total_kgmps", "energy_lost_J", "energy_released_J"};
  EXPECT_EQ(table.header, header);
  ASSERT_EQ(table.rows.size(), 21u);  // t = 0, 0.05, ..., 1
  for (const std::vector<double>& row : table.rows) {
    ASSERT_EQ(row.size(), header.size());
    const double t = row[0];
    const bool after = t >= t_hit;
    const double w1 = after ? v1 : u1, w2 = after ? v2 : 0.0;
    EXPECT_NEAR(row[1], after ? -1.0 + u1 * t_hit + v1 * (t - t_hit) : -1.0 + u1 * t, 1e-12);
    EXPECT_NEAR(row[2], w1, 1e-12);
    EXPECT_NEAR(row[3], m1 * w1, 1e-12);
    EXPECT_NEAR(row[4], 0.5 * m1 * w1 * w1, 1e-12);
    EXPECT_EQ(row[5], 0.0);  // no gravity
    EXPECT_NEAR(row[6], after ? 1.0 + v2 * (t - t_hit) : 1.0, 1e-12);
    EXPECT_NEAR(row[9], 0.5 * m2 * w2 * w2, 1e-12);
    EXPECT_NEAR(row[11], m1 * u1, 1e-12);
    EXPECT_NEAR(row[12], after ? lost : 0.0, 1e-12);
    EXPECT_EQ(row[13], 0.0);
    EXPECT_NEAR(table.books(row), ke0, 1e-12 * ke0) << "t = " << t;
  }
}

// A ball of 0.5 kg and radius 0.1 m dropped from rest at 2 m onto a floor (e = 0.8): before the
// bounce its height follows free fall, pe_J = m g y; every row adds up to m g y0.
TEST(CsvBooksTest, FallingBallsPotentialEnergyAndBooks) {
  physics::WorldDef world;
  world.dimensions = 2;
  world.duration_s = 1.5;
  world.restitution = 0.8;
  world.gravity_mps2 = {0.0, -9.81};
  world.walls.push_back({"floor", {0.0, 0.0}, {0.0, 1.0}, 0.8});
  world.bodies.push_back({"ball", physics::Shape::kDisk, 0.5, 0.1, {0.0, 2.0}, {0.0, 0.0}});
  const double m = 0.5, g = 9.81, y0 = 2.0, r = 0.1;
  const double t_bounce = std::sqrt(2.0 * (y0 - r) / g);
  const double u = g * t_bounce;
  const Table table = tableOf(world, 0.05);
  const std::size_t y = table.column("ball_y_m"), pe = table.column("ball_pe_J");
  const std::size_t lost = table.column("energy_lost_J");
  ASSERT_EQ(table.rows.size(), 31u);
  for (const std::vector<double>& row : table.rows) {
    const double t = row[0];
    if (t < t_bounce) {
      EXPECT_NEAR(row[y], y0 - 0.5 * g * t * t, 1e-12) << "t = " << t;
      EXPECT_EQ(row[lost], 0.0);
    } else if (row[lost] > 0.0) {  // after the bounce, before any rest
      EXPECT_NEAR(row[lost], 0.5 * m * (1.0 - 0.64) * u * u, 1e-12 * m * g * y0);
    }
    EXPECT_NEAR(row[pe], m * g * row[y], 1e-12 * m * g * y0);
    EXPECT_NEAR(table.books(row), m * g * y0, 1e-12 * m * g * y0) << "t = " << t;
  }
}

// Soft contact (Hunt-Crossley spring): while the blocks touch, the spring holds energy and the
// loss accrues; the books add up at every row.
TEST(CsvBooksTest, SoftContactSpringHoldsEnergyWhileCompressed) {
  physics::WorldDef world = test::twoBlocks(0.5, 1.0);
  world.contact_model = physics::ContactModel::kSpringDamper;
  world.contact_duration_s = 0.1;
  const double ke0 = 0.5 * 2.0 * 3.0 * 3.0;
  const double lost = 0.5 * (2.0 / 3.0) * (1.0 - 0.25) * 9.0;  // within 1 %, the model's promise
  const Table table = tableOf(world, 0.005);
  const std::size_t spring = table.column("spring_1_2_J"), books = table.column("energy_lost_J");
  int compressed = 0, accruing = 0;
  for (const std::vector<double>& row : table.rows) {
    const double t = row[0];
    if (t < 0.5 || t > 0.61) {  // the contact lasts 0.1 s from 0.5 s
      EXPECT_EQ(row[spring], 0.0) << "t = " << t;
    } else {
      compressed += row[spring] > 0.0 ? 1 : 0;
      accruing += row[books] > 0.0 && row[books] < 0.99 * lost ? 1 : 0;
    }
    if (t < 0.5) {
      EXPECT_EQ(row[books], 0.0);
    }
    if (t > 0.61) {
      EXPECT_NEAR(row[books], lost, 0.01 * lost);
    }
    EXPECT_NEAR(table.books(row), ke0, 1e-9 * ke0) << "t = " << t;
  }
  EXPECT_GE(compressed, 15);  // some 20 rows inside the contact
  EXPECT_GE(accruing, 5);
}

}  // namespace
}  // namespace collide::report
