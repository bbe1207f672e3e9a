// SPDX-License-Identifier: MIT
// Captions of a video with slow motion (recoil: ten times slower around the shot and the
// bullet's impact): each cue is told in simulated time, so it stands where the video shows that
// instant, a cue too short to read joins the next, and the last one ends the scene at its
// simulated end ("End, t = 2.000 s"), not at the video's longer length.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "cli_runner.hpp"
#include "scene/scene_desc.hpp"
#include "scratch.hpp"

namespace collide {
namespace release_captions_test {

// "00:00:01.870 --> 00:00:01.957" -> the start in seconds.
double cueStart_s(const std::string& timing) {
  const int h = std::stoi(timing.substr(0, 2)), m = std::stoi(timing.substr(3, 2));
  return 3600.0 * h + 60.0 * m + std::stod(timing.substr(6, 6));
}

TEST(ReleaseCaptionsGLTest, CuesOfASlowMotionVideoStandWhereTheVideoShowsTheirInstant) {
  test::ScratchDir dir("collide-release-captions");
  const test::CliResult r = test::run(
      {"render", "recoil", "--size", "160x90", "--captions", "-o", dir.file("recoil.mp4"), "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream vtt(dir.file("recoil.vtt"));
  std::stringstream text;
  text << vtt.rdbuf();
  const std::string captions = text.str();
  // The video's clock: the simulated time each playback instant shows.
  const app::Animation animation = app::animate(scene::loadPreset("recoil"), {160, 90});
  std::istringstream lines(captions);
  std::string previous, line;
  int checked = 0;
  while (std::getline(lines, line)) {
    // A cue that tells an event at "t = 0.250 s: ..." starts where the video shows 0.250 s:
    // within the told time's rounding (0.5 ms) and the start's (to the millisecond of playback,
    // slowed ten times: 0.05 ms).
    if (line.rfind("t = ", 0) == 0 && previous.find(" --> ") != std::string::npos) {
      const double told_s = std::stod(line.substr(4, line.find(' ', 4) - 4));
      EXPECT_NEAR(animation.frames.simulatedAt(cueStart_s(previous)), told_s, 6e-4) << line;
      ++checked;
    }
    previous = line;
  }
  // The shot's cue would last 9 ms of simulated time (about 0.09 s of video): the shot and the
  // bullet's impact share one cue, from the shot.
  EXPECT_EQ(checked, 1) << captions;
  EXPECT_NE(captions.find("pushes rifle and bullet apart."), std::string::npos) << captions;
  EXPECT_LT(captions.find("pushes rifle and bullet apart."),
            captions.find("\nt = 0.259 s: bullet hits the wall"))
      << captions;
  EXPECT_EQ(captions.find("\n\n", captions.find("pushes rifle")),
            std::string::npos)  // no cue break after the shot: the rest is one cue
      << captions;
  EXPECT_NE(captions.find("End, t = 2.000 s: 1 collision."), std::string::npos) << captions;
}

}  // namespace release_captions_test
}  // namespace collide
