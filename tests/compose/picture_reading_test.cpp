// SPDX-License-Identifier: MIT
// Pictures that issue 37 named as misleading, read as the painters lay them out (render::
// drawnItems, `collide layout`'s items; no GL, no pixels): a comparison grid's strobe says what
// its images are in each panel, as a single strobe's caption does. Each check lays out one
// picture per size (well under a second in all).
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "frame_layouts.hpp"
#include "render/frame_layout.hpp"
#include "scene/scene_desc.hpp"

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

INSTANTIATE_TEST_SUITE_P(Sizes, PictureReadingTest, test::videoSizes(), test::sizeName);

}  // namespace
}  // namespace collide
