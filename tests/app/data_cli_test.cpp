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
  EXPECT_EQ(rows[0].rfind("t_s,cart 1_x_m,cart 1_v_mps,cart 1_ke_J,cart 1_p_kgmps,", 0), 0u);
  // t = 0: cart 1 at -2 m moving at 2 m/s (KE 2 J, p 2), cart 2 at 2 m at -1 m/s (KE 0.5, p -1).
  EXPECT_EQ(rows[1], "0,-2,2,2,2,2,-1,0.5,-1,1,2.5,0");
  EXPECT_EQ(rows.back().substr(0, 2), "4,");
}

TEST(DataCliTest, StepOutsideTheLimitsIsClampedWithAWarning) {
  const Result r = run({"data", "worked-example", "--csv", "-", "--dt", "1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "warning: --dt 1 s is outside 0.0005 to 0.05 s; using 0.05 s\n");
  EXPECT_EQ(lines(r.out).size(), 1u + 81u);
  const Result small =
      run({"data", "worked-example", "--csv", "-", "--dt", "0.00001", "--duration", "0.01"});
  ASSERT_EQ(small.exit_code, 0);
  EXPECT_NE(small.err.find("using 0.0005 s"), std::string::npos) << small.err;
  EXPECT_EQ(lines(small.out).size(), 1u + 21u);
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
