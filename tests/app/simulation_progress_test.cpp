// Progress of a long simulation (issue 14): silent for the first 2 s, then a line redrawn in place
// on a terminal or a plain line every 5 s in a log, nothing under --quiet; and the hook in
// physics::simulate that feeds it. Times are given, not waited for.
#include "app/simulation_progress.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <vector>

#include "app/world_from_scene.hpp"
#include "scene/scene_io.hpp"

namespace collide::app {
namespace {

using Clock = core::SimulationReport::Clock;
using std::chrono::milliseconds;

std::size_t countOf(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
    ++count;
  }
  return count;
}

TEST(SimulationProgressTest, DescribesTheSimulatedTimeTheCollisionsAndTheTimeLeft) {
  // A quarter simulated in 2 s: three quarters left at the same pace take 6 s.
  EXPECT_EQ(core::SimulationReport::describe(900.0, 81234, 2.0, {3600.0}),
            "t = 900 of 3600 s simulated (25%), 81234 collisions, 2.0 s elapsed, about 6.0 s left");
  EXPECT_EQ(core::SimulationReport::describe(12.0, 1, 16.0, {12.0}),
            "t = 12 of 12 s simulated (100%), 1 collision, 16 s elapsed");
  // Hours and days, not a count of seconds: a tenth in 1000 s leaves 9000 s.
  EXPECT_EQ(core::SimulationReport::describe(1.0, 100, 1000.0, {10.0}),
            "t = 1 of 10 s simulated (10%), 100 collisions, 1000 s elapsed, about 2.5 h left");
}

TEST(SimulationProgressTest, ATimeLeftIsStatedOnlyWhileThePaceHolds) {
  // A tenth in 2 s is 18 s more at the average pace. At a recent 0.375 simulated seconds per
  // second the 9 s left take 24 s: within a factor of 2, and the longer is said.
  const std::string start = "t = 1 of 10 s simulated (10%), 100 collisions, 2.0 s elapsed, ";
  EXPECT_EQ(core::SimulationReport::describe(1.0, 100, 2.0, {10.0}, {0.375, 50.0}),
            start + "about 24 s left");
  // At 0.01 the 9 s take 900 s, at 100 they take 0.09 s: the pace is changing, and either figure
  // would be a guess.
  for (const double recent_pace : {0.01, 100.0}) {
    EXPECT_EQ(core::SimulationReport::describe(1.0, 100, 2.0, {10.0}, {recent_pace, 50.0}),
              start + "time left unknown (the pace is changing)");
  }
  // No simulated time gained lately.
  EXPECT_EQ(core::SimulationReport::describe(1.0, 100, 2.0, {10.0}, {0.0, 50.0}),
            start + "time left unknown (simulated time hardly advances)");
}

TEST(SimulationProgressTest, TheCollisionCapBoundsTheTimeLeft) {
  // 20 s at the recent pace (9 s at 0.45 a second), but the cap of 1000 collisions is 900
  // collisions away at 450 a second: 2 s.
  EXPECT_EQ(core::SimulationReport::describe(1.0, 100, 2.0, {10.0, 1000}, {0.45, 450.0}),
            "t = 1 of 10 s simulated (10%), 100 collisions, 2.0 s elapsed, at most 2.0 s left (the "
            "cap of 1000 collisions)");
  // Stalled 100 million collisions into a cap of 400 million, at 20 million a second: 15 s.
  EXPECT_EQ(
      core::SimulationReport::describe(4.774, 100'000'000, 7.0, {10.0, 400'000'000}, {1e-9, 2e7}),
      "t = 4.774 of 10 s simulated (47%), 100000000 collisions, 7.0 s elapsed, time left "
      "unknown (simulated time hardly advances), at most 15 s (the cap of 400 million "
      "collisions)");
}

TEST(SimulationProgressTest, AStallSaysWhereAndWhatEndsIt) {
  const core::RecentPace recent{1e-9, 7.6e6};
  // 5.2 s of simulated time left would take over 1000 times the 7 s so far at 1e-9 a second.
  EXPECT_TRUE(core::SimulationReport::stalled(4.774, 7.0, {10.0}, recent));
  EXPECT_FALSE(core::SimulationReport::stalled(4.774, 7.0, {10.0}, {0.1, 7.6e6}));
  EXPECT_FALSE(core::SimulationReport::stalled(10.0, 7.0, {10.0}, recent)) << "nothing left";
  EXPECT_EQ(core::SimulationReport::stallNote(4.774, {10.0, 400'000'000, true}, recent),
            "collisions pile up at t = 4.774 s: 7.6 million a second while simulated time hardly "
            "advances; with contact.collapse_time = 0 nothing ends a settling series (a body "
            "bouncing ever lower) or an inelastic collapse; the run stops at the cap of 400 "
            "million collisions at the latest");
  EXPECT_EQ(core::SimulationReport::stallNote(2.6, {12.0, 0, false}, {1e-9, 2.9e7}),
            "collisions pile up at t = 2.6 s: 29 million a second while simulated time hardly "
            "advances");
}

TEST(SimulationProgressTest, AStalledLogSaysSoOnceAndKeepsReporting) {
  std::ostringstream out;
  const Clock::time_point start{};
  core::SimulationReport report(out, core::ProgressStyle::kLines, {10.0, 1'000'000'000}, start);
  // 1 simulated second a second for 3 s, then stuck at 3 s while 1000 collisions come every
  // 100 ms, for 20 s: lines at 2 s and every 5 s after, the note once when the pace falls. The
  // cap is 1e9 - 70000 collisions away at 10000 a second: 27.8 h.
  for (int ms = 0; ms <= 23000; ms += 100) {
    const double t_s = std::min(ms, 3000) / 1000.0;
    report.update(t_s, static_cast<std::int64_t>(ms) * 10, start + milliseconds(ms));
  }
  const std::string text = out.str();
  EXPECT_EQ(countOf(text, "collisions pile up at t = 3 s: 10000 a second"), 1u) << text;
  EXPECT_EQ(
      countOf(text, "simulated time hardly advances), at most 27.8 h (the cap of 1.0 billion"), 4u)
      << text;
  EXPECT_NE(text.find("t = 2 of 10 s simulated (20%), 20000 collisions, 2.0 s elapsed, about 8.0 "
                      "s left\n"),
            std::string::npos)
      << text;
}

TEST(SimulationProgressTest, ARunUnderTwoSecondsSaysNothing) {
  for (const core::ProgressStyle style : {core::ProgressStyle::kBar, core::ProgressStyle::kLines}) {
    std::ostringstream out;
    const Clock::time_point start{};
    {
      core::SimulationReport report(out, style, {10.0}, start);
      for (int ms = 0; ms < 2000; ms += 100)
        report.update(ms / 200.0, ms, start + milliseconds(ms));
      report.finish(10.0, 2000, start + milliseconds(1999));
    }
    EXPECT_TRUE(out.str().empty()) << out.str();
  }
}

TEST(SimulationProgressTest, ALogGetsALineAfterTwoSecondsThenEveryFiveAndALastOne) {
  std::ostringstream out;
  const Clock::time_point start{};
  core::SimulationReport report(out, core::ProgressStyle::kLines, {100.0}, start);
  // Updates every 100 ms for 9 s: lines at 2 s and 7 s, then the last at finish.
  for (int ms = 0; ms <= 9000; ms += 100) report.update(ms / 100.0, ms, start + milliseconds(ms));
  report.finish(100.0, 12345, start + milliseconds(9050));
  const std::string text = out.str();
  EXPECT_EQ(countOf(text, "\n"), 3u) << text;
  EXPECT_EQ(countOf(text, "simulating: "), 3u) << text;
  EXPECT_NE(text.find("simulating: t = 20 of 100 s simulated (20%), 2000 collisions, 2.0 s "
                      "elapsed, about 8.0 s left\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("t = 70 of 100 s simulated (70%)"), std::string::npos) << text;
  EXPECT_NE(text.find("t = 100 of 100 s simulated (100%), 12345 collisions, 9.1 s elapsed\n"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find('\r'), std::string::npos) << "no terminal codes in a log";
}

TEST(SimulationProgressTest, ATerminalBarIsRedrawnInPlaceAndEndsItsLine) {
  std::ostringstream out;
  const Clock::time_point start{};
  core::SimulationReport report(out, core::ProgressStyle::kBar, {10.0}, start);
  // 3 s of updates every 50 ms: redrawn at most every 100 ms after the first 2 s.
  for (int ms = 0; ms <= 3000; ms += 50) report.update(ms / 1000.0, ms, start + milliseconds(ms));
  report.finish(10.0, 4000, start + milliseconds(3100));
  const std::string text = out.str();
  const std::size_t redraws = countOf(text, "\rsimulating: ");
  EXPECT_GE(redraws, 10u) << text;
  EXPECT_LE(redraws, 12u) << text;
  EXPECT_EQ(countOf(text, "\n"), 1u) << text;
  EXPECT_EQ(text.back(), '\n');
}

TEST(SimulationProgressTest, QuietSaysNothingHoweverLong) {
  std::ostringstream out;
  const Clock::time_point start{};
  core::SimulationReport report(out, core::ProgressStyle::kSilent, {10.0}, start);
  for (int s = 0; s <= 60; ++s) report.update(s / 6.0, s, start + std::chrono::seconds(s));
  report.finish(10.0, 60, start + std::chrono::seconds(61));
  EXPECT_TRUE(out.str().empty()) << out.str();
}

TEST(SimulationProgressTest, AStoppedRunEndsTheBarsLine) {
  std::ostringstream out;
  const Clock::time_point start{};
  {
    core::SimulationReport report(out, core::ProgressStyle::kBar, {10.0}, start);
    report.update(5.0, 7, start + std::chrono::seconds(3));
    // Destroyed without finish(): the run threw (Ctrl-C).
  }
  EXPECT_EQ(out.str().back(), '\n') << out.str();
}

// The hook in physics::simulate reports times that only grow, within the scene's duration, with
// the collisions so far; simulateReporting feeds them to the innermost scope's stream.
TEST(SimulationProgressTest, TheSimulationHookFeedsTheScopesStream) {
  const physics::WorldDef world = worldFromScene(scene::loadScene("newtons-cradle"));
  std::vector<std::pair<double, std::int64_t>> heard;
  const physics::Timeline timeline = physics::simulate(
      world, [&](double t_s, std::int64_t collisions) { heard.emplace_back(t_s, collisions); });
  ASSERT_GE(heard.size(), 2u);
  for (std::size_t i = 1; i < heard.size(); ++i) {
    EXPECT_GE(heard[i].first, heard[i - 1].first);
    EXPECT_GT(heard[i].second, heard[i - 1].second);
  }
  EXPECT_GE(heard.front().first, 0.0);
  EXPECT_LE(heard.back().first, world.duration_s);
  EXPECT_LE(heard.back().second, timeline.collisionCount());

  std::ostringstream out;
  {
    const SimulationReportScope scope(out, core::ProgressStyle::kLines, Clock::duration::zero());
    {
      // An inner silent scope (a batch worker) wins, and gives the outer one back when it ends.
      const SimulationReportScope silent(out, core::ProgressStyle::kSilent,
                                         Clock::duration::zero());
      simulateReporting(world);
      EXPECT_TRUE(out.str().empty()) << out.str();
    }
    simulateReporting(world);
  }
  // With no quiet time: the first report at once, the last when the run ends.
  EXPECT_EQ(countOf(out.str(), "simulating: "), 2u) << out.str();
  EXPECT_NE(out.str().find("(100%), " + std::to_string(timeline.collisionCount()) + " collisions"),
            std::string::npos)
      << out.str();
  simulateReporting(world);  // no scope: silent, nowhere to write
}

}  // namespace
}  // namespace collide::app
