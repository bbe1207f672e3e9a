// Distances label placement measures between a text box and a line (a leader, an arrow, a wall):
// each expected value is worked out here by Pythagoras from the drawn positions.
#include <gtest/gtest.h>

#include <cmath>

#include "compose/placement_obstacles.hpp"

namespace collide::compose {
namespace {

const Box kBox{0.0, 0.0, 4.0, 2.0};

TEST(PlacementDistanceTest, AnEndStraightAboveTheBoxIsItsGap) {
  // (2, 5) is 3 above the top edge; the corners are sqrt(2^2 + 3^2) from the nearest end.
  EXPECT_DOUBLE_EQ(distance(kBox, {2.0, 5.0}, {2.0, 9.0}), 3.0);
}

TEST(PlacementDistanceTest, ALinePastACornerIsTheCornersDistance) {
  // x = 6 from y = -4 to 8 passes the right edge at 2; its ends are sqrt(2^2 + 4^2) and
  // sqrt(2^2 + 6^2) away.
  EXPECT_DOUBLE_EQ(distance(kBox, {6.0, -4.0}, {6.0, 8.0}), 2.0);
  // x + y = 9 from (5, 4) to (8, 1): the corner (4, 2) lies |4 + 2 - 9| / sqrt(2) from it, its
  // foot (5.5, 3.5) inside the segment; the nearer end (5, 4) is sqrt(1 + 4) away, farther.
  EXPECT_NEAR(distance(kBox, {5.0, 4.0}, {8.0, 1.0}), 3.0 / std::sqrt(2.0), 1e-12);
}

TEST(PlacementDistanceTest, AnEndDiagonallyOffACornerIsTheHypotenuse) {
  // (7, 6) is 3 right of and 4 above the corner (4, 2); the segment runs away from the box.
  EXPECT_DOUBLE_EQ(distance(kBox, {7.0, 6.0}, {10.0, 6.0}), 5.0);
  // A point: 3 right of and 3 above the corner.
  EXPECT_NEAR(distance(kBox, {7.0, 5.0}, {7.0, 5.0}), 3.0 * std::sqrt(2.0), 1e-12);
}

TEST(PlacementDistanceTest, ALineThroughTheBoxIsAtNoDistance) {
  EXPECT_EQ(distance(kBox, {-1.0, 1.0}, {5.0, 1.0}), 0.0);
  EXPECT_EQ(distance(kBox, {-3.0, -1.0}, {5.0, 3.0}), 0.0);  // a diagonal in at x = 0, y = 0.5
}

}  // namespace
}  // namespace collide::compose
