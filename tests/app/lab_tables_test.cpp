// SPDX-License-Identifier: MIT
// collide data --tracker and --vernier, in-process: the Tracker model read back the way Tracker
// reads delimited text (a reader written here from Tracker's own rules, not from collide's
// writer), and the Vernier table's header rows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace collide::lab_tables_test {
namespace {

using test::CliResult;
using test::run;

std::vector<std::string> splitFields(const std::string& line, char delimiter) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, delimiter)) fields.push_back(field);
  if (!line.empty() && line.back() == delimiter) fields.emplace_back();
  return fields;
}

std::vector<std::string> textLines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

// A number as Java's Double.parseDouble reads the entries here (plain decimals), else NaN.
double javaNumber(const std::string& text) {
  if (text.empty()) return NAN;
  std::size_t used = 0;
  try {
    const double value = std::stod(text, &used);
    return used == text.size() ? value : NAN;
  } catch (const std::exception&) {
    return NAN;
  }
}

// What Tracker makes of a delimited text file (OSP DataTool.parseData, then ParticleDataTrack's
// point data): delimiters tried in turn (space, tab, comma, semicolon), "//" lines skipped; before
// any data, a row with a single entry that is not a number is the model's name and a row of
// entries none of which is a number holds the column names; every other row of numbers is data.
// Points are columns "x<name>" followed by "y<name>" (Tracker shows "_" in a name as a space);
// "t" or "time" is the clock.
struct TrackerModel {
  std::string name;
  std::vector<double> t;
  std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> points;
  std::vector<std::string> point_order;
};

bool readWith(const std::string& text, char delimiter, TrackerModel& model) {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  for (const std::string& line : textLines(text)) {
    if (line.rfind("//", 0) == 0) continue;
    const std::vector<std::string> entries = splitFields(line, delimiter);
    int words = 0;
    for (const std::string& entry : entries) words += std::isnan(javaNumber(entry)) ? 1 : 0;
    if (rows.empty() && model.name.empty() && entries.size() == 1 && words == 1) {
      model.name = entries[0];
    } else if (rows.empty() && columns.empty() && words == static_cast<int>(entries.size())) {
      columns = entries;
    } else if (words == 0 && !entries.empty()) {
      std::vector<double> row;
      for (const std::string& entry : entries) row.push_back(javaNumber(entry));
      rows.push_back(row);
    }
  }
  if (rows.empty()) return false;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const std::string& column = columns[c];
    std::vector<double> values;
    for (const std::vector<double>& row : rows) values.push_back(c < row.size() ? row[c] : NAN);
    if (column == "t" || column == "time") model.t = values;
    if (column[0] == 'y' && c > 0 && columns[c - 1] == "x" + column.substr(1)) {
      std::string point = column.substr(1);
      for (char& ch : point) ch = ch == '_' ? ' ' : ch;
      std::vector<double> xs;
      for (const std::vector<double>& row : rows) xs.push_back(row[c - 1]);
      model.points[point] = {xs, values};
      model.point_order.push_back(point);
    }
  }
  return true;
}

TrackerModel readTrackerModel(const std::string& text) {
  for (const char delimiter : {' ', '\t', ',', ';'}) {
    TrackerModel model;
    if (readWith(text, delimiter, model)) return model;
  }
  return {};
}

// The worked example (4 s; cart 1 at -2 m, 2 m/s; cart 2 at 2 m, -1 m/s): Tracker's model at
// 50 frames per second against the CSV at 0.02 s, the same instants.
TEST(LabTablesTest, TrackerModelReadsBackToTheCsvPositions) {
  const CliResult tracker = run({"data", "worked-example", "--tracker", "-", "--fps", "50"});
  ASSERT_EQ(tracker.exit_code, 0) << tracker.err;
  const CliResult csv = run({"data", "worked-example", "--csv", "-", "--dt", "0.02"});
  ASSERT_EQ(csv.exit_code, 0) << csv.err;

  const TrackerModel model = readTrackerModel(tracker.out);
  EXPECT_EQ(model.name, "worked-example");
  ASSERT_EQ(model.point_order, (std::vector<std::string>{"cart 1", "cart 2"})) << tracker.out;
  // One row per frame of `collide render --fps 50`: frames k / 50 s for k < 4 s x 50.
  ASSERT_EQ(model.t.size(), 200u);
  for (std::size_t k = 0; k < model.t.size(); ++k) {
    ASSERT_NEAR(model.t[k], static_cast<double>(k) / 50.0, 1e-12) << k;
  }
  // CSV rows: t_s, then per cart its columns; the positions found by their names.
  std::map<double, std::vector<double>> csv_rows;
  const std::vector<std::string> table = textLines(csv.out);
  const std::vector<std::string> header = splitFields(table.at(0), ',');
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t x1 = column("cart 1_x_m"), x2 = column("cart 2_x_m");
  ASSERT_LT(x2, header.size()) << table.at(0);
  for (std::size_t r = 1; r < table.size(); ++r) {
    std::vector<double> row;
    for (const std::string& field : splitFields(table[r], ',')) row.push_back(javaNumber(field));
    csv_rows[row[0]] = row;
  }
  int compared = 0;
  for (std::size_t k = 0; k < model.t.size(); ++k) {
    const auto row = csv_rows.find(model.t[k]);
    ASSERT_NE(row, csv_rows.end()) << "no CSV row at t = " << model.t[k];
    EXPECT_EQ(model.points.at("cart 1").first[k], row->second[x1]) << model.t[k];
    EXPECT_EQ(model.points.at("cart 2").first[k], row->second[x2]) << model.t[k];
    EXPECT_EQ(model.points.at("cart 1").second[k], 0.0);  // a 1D scene: on the track
    ++compared;
  }
  EXPECT_EQ(compared, 200);
  // Before the impact at 3.5 m / 3 m/s, cart 1 moves at 2 m/s from -2 m: at 1 s it is at 0 m.
  EXPECT_DOUBLE_EQ(model.points.at("cart 1").first[50], 0.0);
}

// Slow motion: the video's time runs slower around the bullet's impact, so the model has more
// frames than the scene's seconds at the rate, its clock still steps one frame at a time, and
// its first and last rows show the scene's start and end.
TEST(LabTablesTest, TrackerModelFollowsASlowMotionVideosFrames) {
  const CliResult tracker = run({"data", "ballistic-pendulum", "--tracker", "-", "--fps", "20"});
  ASSERT_EQ(tracker.exit_code, 0) << tracker.err;
  const TrackerModel model = readTrackerModel(tracker.out);
  ASSERT_EQ(model.point_order, (std::vector<std::string>{"block", "bullet"}));
  EXPECT_GT(model.t.size(), 2.5 * 20 + 1);  // the scene lasts 2.5 s
  for (std::size_t k = 0; k < model.t.size(); ++k) {
    ASSERT_NEAR(model.t[k], static_cast<double>(k) / 20.0, 1e-12) << k;
  }
  // The bullet starts 0.5 m left of and 1 m below the pivot's level, the block hangs 1 m below.
  EXPECT_EQ(model.points.at("bullet").first[0], -0.5);
  EXPECT_EQ(model.points.at("bullet").second[0], -1.0);
  EXPECT_EQ(model.points.at("block").second[0], -1.0);
}

TEST(LabTablesTest, VernierTableHasItsHeaderRowsAndUnits) {
  const CliResult r = run({"data", "worked-example", "--vernier", "-", "--dt", "0.05"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> rows = textLines(r.out);
  ASSERT_GT(rows.size(), 8u);
  EXPECT_EQ(rows[0], "Vernier Format 3");
  EXPECT_EQ(splitFields(rows[1], '\t').at(0),
            "collide");                  // the data source; no date: same every run
  EXPECT_EQ(rows[2], "worked-example");  // the data set's name
  const std::vector<std::string> long_names = splitFields(rows[3], '\t');
  const std::vector<std::string> short_names = splitFields(rows[4], '\t');
  const std::vector<std::string> units = splitFields(rows[5], '\t');
  EXPECT_EQ(long_names.at(1), "cart 1 position");
  EXPECT_EQ(short_names,
            (std::vector<std::string>{"t", "x1", "v1", "x2", "v2", "p", "KE", "Elost"}));
  EXPECT_EQ(units, (std::vector<std::string>{"s", "m", "m/s", "m", "m/s", "kg m/s", "J", "J"}));
  EXPECT_EQ(long_names.size(), units.size());
  EXPECT_EQ(rows[6], "");
  // 0.05 s steps over 4 s: 81 rows of as many numbers as columns.
  ASSERT_EQ(rows.size(), 7u + 81u);
  std::vector<double> first;
  for (const std::string& field : splitFields(rows[7], '\t')) first.push_back(javaNumber(field));
  ASSERT_EQ(first.size(), units.size());
  // t = 0: 1 kg at -2 m, 2 m/s and 1 kg at 2 m, -1 m/s: p = 1 kg m/s, KE = 2 + 0.5 J, none lost.
  EXPECT_EQ(first, (std::vector<double>{0.0, -2.0, 2.0, 2.0, -1.0, 1.0, 2.5, 0.0}));
}

TEST(LabTablesTest, OptionsThatDoNotApplyAreRefused) {
  const CliResult fps = run({"data", "worked-example", "--csv", "-", "--fps", "30"});
  EXPECT_EQ(fps.exit_code, 2);
  EXPECT_EQ(fps.err, "collide: --fps: only applies to --tracker; allowed: add --tracker PATH|-\n");
  const CliResult both = run({"data", "worked-example", "--tracker", "-", "--vernier", "-"});
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_TRUE(both.out.empty());
  EXPECT_EQ(run({"data", "worked-example", "--tracker", "-", "--fps", "0"}).exit_code, 2);
  EXPECT_EQ(run({"data", "worked-example", "--vernier", "-", "--dt", "1"}).exit_code, 2);
}

}  // namespace
}  // namespace collide::lab_tables_test
