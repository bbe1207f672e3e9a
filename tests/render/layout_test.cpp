// Layout arithmetic, no GL.
#include "render/layout.hpp"

#include <gtest/gtest.h>

#include "frame_models.hpp"

namespace collide::render {
namespace {

TEST(LayoutTest, BarSitsBelowSceneAndIsWholePixels) {
  for (const auto& [w, h] : {std::pair{320, 180}, {640, 360}, {1920, 1080}, {3840, 2160}}) {
    const FrameLayout layout = computeFrameLayout(w, h);
    EXPECT_LT(layout.scene.y1, layout.bar_outer.y0) << w << "x" << h;
    EXPECT_LE(layout.scene.y1, layout.world_clip_y1_px);
    EXPECT_LE(layout.world_clip_y1_px, layout.bar_outer.y0);
    EXPECT_LE(layout.bar_outer.y1, h);
    EXPECT_EQ(layout.bar_inner.x0, std::round(layout.bar_inner.x0));
    EXPECT_EQ(layout.bar_inner.x1, std::round(layout.bar_inner.x1));
    EXPECT_EQ(layout.bar_inner.y0, std::round(layout.bar_inner.y0));
    EXPECT_EQ(layout.bar_inner.y1, std::round(layout.bar_inner.y1));
    EXPECT_GT(layout.bar_inner.height(), 0.0);
  }
}

TEST(LayoutTest, SizesScaleWithHeight) {
  const FrameLayout small = computeFrameLayout(640, 360);
  const FrameLayout large = computeFrameLayout(3840, 2160);
  EXPECT_NEAR(large.scene.height() / small.scene.height(), 6.0, 6.0 / small.scene.height() * 2);
  EXPECT_DOUBLE_EQ(large.outline_px / small.outline_px, 6.0);
  EXPECT_DOUBLE_EQ(large.arrow_head_length_px / small.arrow_head_length_px, 6.0);
}

TEST(LayoutTest, FitViewKeepsMetresSquareAndCentres) {
  const PixelRect area{10.0, 20.0, 410.0, 120.0};   // 400 × 100 px
  const ViewWindow view{{-1.0, -1.0}, {1.0, 1.0}};  // 2 × 2 m: height limits the scale
  const WorldToPixel to_px = fitView(view, area);
  EXPECT_DOUBLE_EQ(to_px.px_per_m, 50.0);
  const core::Vec2 center = to_px.toPixel({0.0, 0.0});
  EXPECT_DOUBLE_EQ(center.x(), 210.0);
  EXPECT_DOUBLE_EQ(center.y(), 70.0);
  // World y up is pixel y down.
  EXPECT_DOUBLE_EQ(to_px.toPixel({0.0, 1.0}).y(), 20.0);
  EXPECT_DOUBLE_EQ(to_px.toPixel({1.0, 0.0}).x(), 260.0);
}

TEST(LayoutTest, BarEdgesAreCumulativeAndClamped) {
  const PixelRect inner{10.0, 0.0, 110.0, 5.0};
  EnergyBar bar;
  bar.full_scale_J = 2.0;
  bar.segments = {{0.5, {}, ""}, {-1.0, {}, ""}, {1.0, {}, ""}, {1.0, {}, ""}};
  const std::vector<double> edges = barSegmentEdgesPx(bar, inner);
  ASSERT_EQ(edges.size(), 5u);
  EXPECT_DOUBLE_EQ(edges[0], 10.0);
  EXPECT_DOUBLE_EQ(edges[1], 35.0);
  EXPECT_DOUBLE_EQ(edges[2], 35.0);  // negative energy: empty segment
  EXPECT_DOUBLE_EQ(edges[3], 85.0);
  EXPECT_DOUBLE_EQ(edges[4], 110.0);  // 2.5 J of 2 J: clamped to the end
}

}  // namespace
}  // namespace collide::render
