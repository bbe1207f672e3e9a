// SPDX-License-Identifier: MIT
// A legend line kept from the frame before (compose/legend_placement.hpp, keepLegend) whose text
// grew between two texts so that neither edge nor its middle fits (ballistic-pendulum 640x360's
// "v1' = v2' = 0.0477 m/s, -143 deg" between the ruler and the notes): it slides along its row
// the least that fits, never farther than it grew. A few boxes, no picture (well under a
// millisecond).
#include <gtest/gtest.h>

#include <optional>
#include <vector>

#include "compose/legend_placement.hpp"

namespace collide::compose {
namespace {

constexpr double kTextPx = 10.0, kLinePx = 12.0;
// The line stood at kWasX_px, kWasWidthPx wide, its middle at 70 px.
constexpr double kWasX_px = 30.0, kWasWidthPx = 80.0;

// Texts on the line's row that end at left_end_px and begin at right_start_px; no gaps kept.
Obstacles between(double left_end_px, double right_start_px) {
  Obstacles obstacles(Box{0.0, 0.0, 300.0, 100.0}, 0.0, 0.0, 0.0);
  obstacles.addText({0.0, 0.0, left_end_px, kLinePx});
  obstacles.addText({right_start_px, 0.0, 300.0, kLinePx});
  return obstacles;
}

frame::FrameLayout layout() {
  frame::FrameLayout frame_layout;
  frame_layout.text_px = kTextPx;
  return frame_layout;
}

std::optional<std::vector<core::Vec2>> keptGrownTo(double width_px, const Obstacles& obstacles) {
  const std::vector<std::optional<KeptLine>> wanted = {
      KeptLine{core::Vec2{kWasX_px, 0.0}, kWasWidthPx}};
  return keepLegend({width_px}, wanted, obstacles, layout(), kLinePx);
}

TEST(LegendKeepTest, AGrownLineSlidesTheLeastThatFitsBetweenTwoTexts) {
  // Texts ending at 25 px and beginning at 122 px. 96 px wide, flush left the line ends at 126,
  // flush right it starts at 14, its middle kept it starts at 22: all run into a text. Between
  // 25 and 122 it fits, nearest its middle flush with the left text's end: a slide of 3 px (in
  // whole pixels, so no more than a pixel beyond).
  constexpr double kLeftEndPx = 25.0, kRightStartPx = 122.0, kGrownPx = 96.0;
  const auto at = keptGrownTo(kGrownPx, between(kLeftEndPx, kRightStartPx));
  ASSERT_TRUE(at.has_value());
  ASSERT_EQ(at->size(), 1U);
  EXPECT_EQ((*at)[0].y(), 0.0);
  EXPECT_GE((*at)[0].x(), kLeftEndPx);
  EXPECT_LE((*at)[0].x(), kLeftEndPx + 1.0);
  EXPECT_LE((*at)[0].x() + kGrownPx, kRightStartPx);
}

TEST(LegendKeepTest, AGrownLineSlidesNoFartherThanItGrew) {
  // Texts ending at 10 px and beginning at 100 px. 82 px wide (2 px more than it was): it fits
  // between 10 and 100 only starting at 18 px or less, 11 px left of its middle's place (29):
  // farther than it grew, so it is not kept.
  EXPECT_FALSE(keptGrownTo(82.0, between(10.0, 100.0)).has_value());
}

}  // namespace
}  // namespace collide::compose
