// StaleRects: which parts of a kept copy of a frame a buffer must bring up to date. Expected
// rectangles are worked out by hand from the ones noted.
#include "core/stale_rects.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace collide::core {
namespace {

bool same(const ImageRect& a, const ImageRect& b) {
  return a.x0 == b.x0 && a.y0 == b.y0 && a.x1 == b.x1 && a.y1 == b.y1;
}

TEST(StaleRectsTest, ANewBufferIsBroughtUpToDateWholeOnceAndThenOnlyWhereDrawn) {
  StaleRects stale;
  const std::vector<ImageRect> drawn = {{10, 20, 30, 40}};
  stale.note(&drawn);  // ignored: the buffer must be read whole anyway
  EXPECT_EQ(stale.take(), nullptr);
  const std::vector<ImageRect>* nothing = stale.take();
  ASSERT_NE(nothing, nullptr) << "up to date after a take: nothing left to read";
  EXPECT_TRUE(nothing->empty());
  stale.note(&drawn);
  const std::vector<ImageRect>* rects = stale.take();
  ASSERT_NE(rects, nullptr);
  ASSERT_EQ(rects->size(), 1u);
  EXPECT_TRUE(same((*rects)[0], drawn[0]));
}

TEST(StaleRectsTest, RectanglesOfSeveralFramesAreJoinedWhereTheyOverlap) {
  StaleRects stale;
  stale.take();
  // Two frames of a body moving 5 px right, and a far-off one that meets neither.
  const std::vector<ImageRect> first = {{0, 0, 10, 10}, {100, 100, 110, 110}};
  const std::vector<ImageRect> second = {{5, 0, 15, 10}};
  stale.note(&first);
  stale.note(&second);
  const std::vector<ImageRect>* rects = stale.take();
  ASSERT_NE(rects, nullptr);
  ASSERT_EQ(rects->size(), 2u);
  // The overlapping pair's bounding box is x 0..15, y 0..10.
  const ImageRect joined{0, 0, 15, 10};
  const bool in_order = same((*rects)[0], joined) && same((*rects)[1], first[1]);
  const bool swapped = same((*rects)[1], joined) && same((*rects)[0], first[1]);
  EXPECT_TRUE(in_order || swapped);
}

TEST(StaleRectsTest, AWholeFrameDrawnOrAChangeInPlaceMakesTheBufferStaleEverywhere) {
  StaleRects stale;
  stale.take();
  const std::vector<ImageRect> drawn = {{1, 2, 3, 4}};
  stale.note(&drawn);
  stale.note(nullptr);
  stale.note(&drawn);
  EXPECT_EQ(stale.take(), nullptr);
  stale.note(&drawn);
  stale.markWhole();
  EXPECT_EQ(stale.take(), nullptr);
}

TEST(StaleRectsTest, TheAnswerStaysAsTakenWhileLaterChangesAreNoted) {
  // The encode thread stages from the answer while the next frame's changes are noted.
  StaleRects stale;
  stale.take();
  const std::vector<ImageRect> first = {{0, 0, 4, 4}};
  const std::vector<ImageRect> second = {{50, 50, 60, 60}};
  stale.note(&first);
  const std::vector<ImageRect>* rects = stale.take();
  ASSERT_NE(rects, nullptr);
  stale.note(&second);
  ASSERT_EQ(rects->size(), 1u);
  EXPECT_TRUE(same((*rects)[0], first[0]));
  const std::vector<ImageRect>* next = stale.take();
  ASSERT_NE(next, nullptr);
  ASSERT_EQ(next->size(), 1u);
  EXPECT_TRUE(same((*next)[0], second[0]));
}

}  // namespace
}  // namespace collide::core
