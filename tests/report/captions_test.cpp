// Narration cues and caption files: the cues start at the collision times, the files parse as
// WebVTT and SubRip, and the numbers in the words are the physics'.
#include "report/captions.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "report/narration.hpp"
#include "report_test_scenes.hpp"

namespace collide::report {
namespace {

struct ParsedCue {
  double start_s, end_s;
  std::string text;
};

double parseTimestamp(const std::string& text) {
  static const std::regex kTime(R"((\d\d):(\d\d):(\d\d)[.,](\d\d\d))");
  std::smatch m;
  EXPECT_TRUE(std::regex_match(text, m, kTime)) << text;
  if (m.empty()) return -1.0;
  return std::stoi(m[1]) * 3600.0 + std::stoi(m[2]) * 60.0 + std::stoi(m[3]) +
         std::stoi(m[4]) / 1000.0;
}

// A strict reader of the subset of WebVTT / SubRip that the writers produce: blocks separated by
// one blank line; each block an identifier line, a timing line, then text lines.
std::vector<ParsedCue> parseCaptions(const std::string& file, bool webvtt) {
  std::istringstream in(file);
  std::string line;
  if (webvtt) {
    std::getline(in, line);
    EXPECT_TRUE(line == "WEBVTT" || line.rfind("WEBVTT ", 0) == 0) << line;
    std::getline(in, line);
    EXPECT_EQ(line, "");
  }
  std::vector<ParsedCue> cues;
  int expected_id = 1;
  while (std::getline(in, line)) {
    EXPECT_EQ(line, std::to_string(expected_id++));
    std::string timing;
    std::getline(in, timing);
    const char separator = webvtt ? '.' : ',';
    static const std::regex kTiming(R"((\S+) --> (\S+))");
    std::smatch m;
    EXPECT_TRUE(std::regex_match(timing, m, kTiming)) << timing;
    if (m.empty()) return cues;
    EXPECT_NE(m[1].str().find(separator), std::string::npos);
    ParsedCue cue{parseTimestamp(m[1]), parseTimestamp(m[2]), ""};
    EXPECT_LT(cue.start_s, cue.end_s) << timing;
    while (std::getline(in, line) && !line.empty()) {
      EXPECT_EQ(line.find("-->"), std::string::npos);
      cue.text += (cue.text.empty() ? "" : "\n") + line;
    }
    EXPECT_FALSE(cue.text.empty());
    cues.push_back(cue);
  }
  return cues;
}

TEST(CaptionsTest, TimestampsRoundToTheMillisecond) {
  EXPECT_EQ(captionTimestamp(0.0, '.'), "00:00:00.000");
  EXPECT_EQ(captionTimestamp(7.0 / 6.0, '.'), "00:00:01.167");
  EXPECT_EQ(captionTimestamp(3725.5, ','), "01:02:05,500");
}

TEST(CaptionsTest, OneCueAtTheStartOnePerCollisionOneAtTheEnd) {
  const physics::Timeline timeline = physics::simulate(test::twoBlocksAndWall(0.5));
  const auto& events = timeline.collisions();
  ASSERT_GE(events.size(), 3u);  // left-right, right-wall, right-left again
  ASSERT_LT(events.back().time_s, 3.0);
  // The last collision (2.83 s) leaves 1.17 s: the end cue gets 0.5 s of it.
  const std::vector<Cue> cues = narrate(timeline, {"Two blocks", 0.0, 50, 0.5, 0.5});
  ASSERT_EQ(cues.size(), events.size() + 2);
  EXPECT_EQ(cues.back().start_s, 3.5);
  EXPECT_EQ(cues.front().start_s, 0.0);
  for (std::size_t i = 0; i < events.size(); ++i) {
    EXPECT_EQ(cues[i + 1].start_s, events[i].time_s);
    EXPECT_EQ(cues[i].end_s, cues[i + 1].start_s);
  }
  EXPECT_EQ(cues.back().end_s, 4.0);
  EXPECT_NE(cues[2].text.find("the wall \"far\""), std::string::npos) << cues[2].text;
  EXPECT_NE(
      cues.back().text.find("End, t = 4.000 s: " + std::to_string(events.size()) + " collisions"),
      std::string::npos)
      << cues.back().text;
}

TEST(CaptionsTest, CollisionCueNamesSpeedRestitutionAndEnergy) {
  // 2 kg at 3 m/s on 1 kg at rest, e = 0.5: v1' = (6 - 1.5) / 3 = 1.5, v2' = 3.
  // KE before 9 J, after 0.5*2*2.25 + 0.5*1*9 = 6.75 J: 2.25 J lost, 25%.
  const physics::Timeline timeline = physics::simulate(test::twoBlocks(0.5));
  const std::vector<Cue> cues = narrate(timeline, {"Two blocks"});
  ASSERT_EQ(cues.size(), 3u);
  EXPECT_EQ(cues[0].text,
            "Two blocks.\nLeft (2 kg) is moving right at 3.00 m/s; right (1 kg) is at rest.\n"
            "Total kinetic energy 9.00 J.");
  EXPECT_EQ(cues[1].text,
            "t = 0.500 s: left hits right at a closing speed of 3.00 m/s (e = 0.5).\n"
            "2.25 J of their 9.00 J of kinetic energy (25.0%) turns into heat and deformation.\n"
            "Afterwards left is moving right at 1.50 m/s and right is moving right at 3.00 m/s.");
  EXPECT_NE(cues[2].text.find("2.25 J (25.0%) turned into heat"), std::string::npos);
  EXPECT_NE(cues[2].text.find("Total momentum 6.00 kg·m/s before and after."), std::string::npos);
}

TEST(CaptionsTest, WebVttAndSrtParseWithCueTimesAtTheCollisions) {
  const physics::Timeline timeline = physics::simulate(test::twoBlocksAndWall(0.5));
  const std::vector<Cue> cues = narrate(timeline, {"Blocks <&> wall"});
  // The default end cue waits 2 s after the last collision (2.83 s): its words join that cue.
  ASSERT_EQ(cues.size(), timeline.collisions().size() + 1);
  EXPECT_NE(cues.back().text.find("End, t = 4.000 s: "), std::string::npos);
  std::ostringstream vtt, srt;
  writeWebVtt(vtt, cues, "Blocks <&> wall");
  writeSrt(srt, cues);
  for (const bool webvtt : {true, false}) {
    const std::vector<ParsedCue> parsed = parseCaptions(webvtt ? vtt.str() : srt.str(), webvtt);
    ASSERT_EQ(parsed.size(), cues.size());
    for (std::size_t i = 0; i < cues.size(); ++i) {
      EXPECT_NEAR(parsed[i].start_s, cues[i].start_s, 0.0005 + 1e-12);
      EXPECT_NEAR(parsed[i].end_s, cues[i].end_s, 0.0005 + 1e-12);
    }
    for (std::size_t i = 0; i < timeline.collisions().size(); ++i) {
      EXPECT_NEAR(parsed[i + 1].start_s, timeline.collisions()[i].time_s, 0.0005 + 1e-12);
    }
  }
  EXPECT_NE(vtt.str().find("Blocks &lt;&amp;&gt; wall."), std::string::npos) << vtt.str();
}

TEST(CaptionsTest, ManyCollisionsAreSummedUpAfterTheCap) {
  const physics::Timeline timeline = physics::simulate(test::twoBlocksAndWall(1.0));
  NarrationOptions options{"", 0.0, 1};
  const std::vector<Cue> cues = narrate(timeline, options);
  ASSERT_EQ(cues.size(), 4u);  // start, first collision, "N more", end
  EXPECT_NE(cues[2].text.find("more collision"), std::string::npos) << cues[2].text;
  EXPECT_EQ(cues[2].start_s, timeline.collisions()[1].time_s);
}

}  // namespace
}  // namespace collide::report
