// SPDX-License-Identifier: MIT
// Pictures that issue 37 named as misleading, read as the painters lay them out (render::
// drawnItems, `collide layout`'s items; no GL, no pixels): a comparison grid's strobe says what
// its images are in each panel, as a single strobe's caption does; a ball swinging into a row of
// others shows its velocity up to the strike. Each check lays out a picture or a dozen frames per
// size (well under a second in all).
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "frame_layouts.hpp"
#include "render/frame_layout.hpp"
#include "scene/scene_desc.hpp"
#include "video_frame_checks.hpp"

namespace collide {
namespace {

// The words of `text`, split at white space (a wrapped text's lines joined).
std::vector<std::string> wordsOf(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

// The words an item draws, its lines read one after the other.
std::vector<std::string> drawnWords(const frame::DrawnItem& item) {
  std::string joined;
  for (const std::string& line : item.lines) joined += line + " ";
  return wordsOf(joined);
}

class PictureReadingTest : public ::testing::TestWithParam<test::PictureSize> {};

// compare-restitution's strobe drew no caption in any of its three panels: nothing said that the
// images stand at 2 per second, nor that one more stands at the instant of a collision (its
// uneven spacing read as a change of speed). Each panel's caption, as the frame description asks
// for it, is drawn whole: every word, none cut off.
TEST_P(PictureReadingTest, GridStrobeDrawsEachPanelsWholeCaption) {
  const auto [width_px, height_px] = GetParam();
  const app::Animation animation =
      app::animate(scene::loadPreset("compare-restitution"), {width_px, height_px});
  const frame::FrameModel frame = animation.frames.strobeFrame(0.0);
  ASSERT_GE(frame.panels.size(), 2u) << "a comparison grid";
  const std::vector<frame::DrawnItem> items = render::drawnItems(frame, width_px, height_px);
  for (std::size_t p = 0; p < frame.panels.size(); ++p) {
    SCOPED_TRACE("panel " + std::to_string(p + 1));
    const std::vector<std::string> asked = wordsOf(frame.panels[p].caption);
    ASSERT_FALSE(asked.empty()) << "a strobe's panel has a caption to show";
    const frame::DrawnItem* caption = nullptr;
    for (const frame::DrawnItem& item : items) {
      if (item.kind == "caption" && item.panel == static_cast<int>(p)) caption = &item;
    }
    ASSERT_NE(caption, nullptr) << "no caption drawn for \"" << frame.panels[p].caption << "\"";
    EXPECT_EQ(drawnWords(*caption), asked);
    EXPECT_LE(caption->box.x1, width_px);
    EXPECT_LE(caption->box.y1, height_px);
  }
}

// newtons-cradle: ball 1 swings down into the row and strikes ball 2. Its arrow straight on
// would run into ball 2, so it was left out in the frames before the strike: the one moving
// body showed no velocity. In every frame from the release to the first collision (simulated
// here, every 30th of a second of playback), ball 1 moves and its arrow is drawn: to its scale
// or with a break, through no wall and no other body.
TEST_P(PictureReadingTest, SwingingBallShowsItsVelocityUpToTheStrike) {
  const auto [width_px, height_px] = GetParam();
  const app::Animation animation =
      app::animate(scene::loadPreset("newtons-cradle"), {width_px, height_px});
  const compose::FrameSource& source = animation.frames;
  ASSERT_FALSE(source.panelTimeline(0).collisions().empty());
  const double strike_s = source.panelTimeline(0).collisions().front().time_s;
  int frames = 0;
  for (int k = 1;; ++k) {
    const double playback_s = k / 30.0;
    const double t_s = source.simulatedAt(playback_s);
    if (t_s >= strike_s) break;
    SCOPED_TRACE("t = " + std::to_string(t_s) + " s");
    const double speed_mps = source.panelTimeline(0).sample(t_s).bodies[0].velocity_mps.norm();
    ASSERT_GT(speed_mps, 0.0) << "ball 1 is moving";
    const std::vector<frame::DrawnItem> items =
        render::drawnItems(source.frameAt(playback_s), width_px, height_px);
    const frame::DrawnItem* arrow = nullptr;
    for (const frame::DrawnItem& item : items) {
      if (item.kind == "arrow" && item.body == 0 && item.arrow) arrow = &item;
    }
    ASSERT_NE(arrow, nullptr) << "ball 1's velocity is not shown";
    EXPECT_GT((arrow->arrow->to_px - arrow->arrow->from_px).norm(), 0.0);
    EXPECT_NEAR(arrow->arrow->value_mps, speed_mps, 1e-9 * speed_mps);
    EXPECT_EQ(test::arrowThroughSomething(items), "");
    EXPECT_EQ(test::arrowOffItsValue(items), "");
    ++frames;
  }
  EXPECT_GE(frames, 5) << "the swing before the strike was walked";
}

INSTANTIATE_TEST_SUITE_P(Sizes, PictureReadingTest, test::videoSizes(), test::sizeName);

}  // namespace
}  // namespace collide
