// Layout arithmetic, no GL.
#include "frame/layout.hpp"

#include <gtest/gtest.h>

#include "frame_models.hpp"

namespace collide::render {
namespace {

TEST(LayoutTest, BarSitsBelowSceneAndIsWholePixels) {
  for (const auto& [w, h] : {std::pair{320, 180}, {640, 360}, {1920, 1080}, {3840, 2160}}) {
    const frame::FrameLayout frame = frame::computeFrameLayout(w, h);
    const frame::PanelLayout& layout = frame.panel();
    EXPECT_LT(layout.scene.y1, layout.bar_outer.y0) << w << "x" << h;
    EXPECT_LE(layout.scene.y1, layout.world_clip.y1);
    EXPECT_LE(layout.world_clip.y1, layout.bar_outer.y0);
    EXPECT_LE(layout.bar_outer.y1, layout.bar_labels.y0 + 1e-9);
    EXPECT_LE(layout.bar_labels.y1, layout.caption.y0 + 1e-9);
    EXPECT_LE(frame.header.y1, layout.heading.y0);
    EXPECT_LE(layout.bar_outer.y1, h);
    EXPECT_EQ(layout.bar_inner.x0, std::round(layout.bar_inner.x0));
    EXPECT_EQ(layout.bar_inner.x1, std::round(layout.bar_inner.x1));
    EXPECT_EQ(layout.bar_inner.y0, std::round(layout.bar_inner.y0));
    EXPECT_EQ(layout.bar_inner.y1, std::round(layout.bar_inner.y1));
    EXPECT_GT(layout.bar_inner.height(), 0.0);
  }
}

TEST(LayoutTest, SizesScaleWithHeight) {
  const frame::FrameLayout small = frame::computeFrameLayout(640, 360);
  const frame::FrameLayout large = frame::computeFrameLayout(3840, 2160);
  EXPECT_NEAR(large.panel().scene.height() / small.panel().scene.height(), 6.0,
              6.0 / small.panel().scene.height() * 4);
  EXPECT_NEAR(large.text_px / small.text_px, 6.0, 0.5 / small.text_px * 6.0);  // whole pixels
  EXPECT_DOUBLE_EQ(large.outline_px / small.outline_px, 6.0);
  EXPECT_DOUBLE_EQ(large.arrow_head_length_px / small.arrow_head_length_px, 6.0);
}

TEST(LayoutTest, FitViewKeepsMetresSquareAndCentres) {
  const frame::PixelRect area{10.0, 20.0, 410.0, 120.0};   // 400 × 100 px
  const frame::ViewWindow view{{-1.0, -1.0}, {1.0, 1.0}};  // 2 × 2 m: height limits the scale
  const frame::WorldToPixel to_px = frame::fitView(view, area);
  EXPECT_DOUBLE_EQ(to_px.px_per_m, 50.0);
  const core::Vec2 center = to_px.toPixel({0.0, 0.0});
  EXPECT_DOUBLE_EQ(center.x(), 210.0);
  EXPECT_DOUBLE_EQ(center.y(), 70.0);
  // World y up is pixel y down.
  EXPECT_DOUBLE_EQ(to_px.toPixel({0.0, 1.0}).y(), 20.0);
  EXPECT_DOUBLE_EQ(to_px.toPixel({1.0, 0.0}).x(), 260.0);
}

TEST(LayoutTest, RulerCoversOnlyTheDrawnRegion) {
  // A 2.6 m table at 100 px/m, ticks at least 50 px apart: 0.5 m is the smallest 1-2-5 step
  // of 0.5 m or more, and the ticks are the multiples of it inside [-1.3, 1.3] m.
  const frame::RulerAxis axis = frame::rulerAxis(-1.3, 1.3, 100.0, 50.0);
  EXPECT_DOUBLE_EQ(axis.from_m, -1.3);
  EXPECT_DOUBLE_EQ(axis.to_m, 1.3);
  EXPECT_DOUBLE_EQ(axis.step_m, 0.5);
  ASSERT_EQ(axis.ticks_m.size(), 5u);
  for (std::size_t k = 0; k < axis.ticks_m.size(); ++k) {
    EXPECT_NEAR(axis.ticks_m[k], -1.0 + 0.5 * k, 1e-12);
  }
  // 60 px minimum at 100 px/m is 0.6 m: the next step up is 1 m.
  EXPECT_DOUBLE_EQ(frame::rulerAxis(0.0, 3.0, 100.0, 60.0).step_m, 1.0);
}

TEST(LayoutTest, RulerLeavesOutAnAxisWithOneTick) {
  // 0.3 m tall at 100 px/m with 0.5 m steps: only the 0 tick would show, which gives no scale.
  EXPECT_TRUE(frame::rulerAxis(-0.1, 0.2, 100.0, 50.0).ticks_m.empty());
  // Two ticks (0 and 0.5) are a scale.
  EXPECT_EQ(frame::rulerAxis(-0.1, 0.6, 100.0, 50.0).ticks_m.size(), 2u);
  // Nothing drawn for a degenerate mapping.
  EXPECT_TRUE(frame::rulerAxis(0.0, 1.0, 0.0, 50.0).ticks_m.empty());
}

TEST(LayoutTest, BarEdgesAreCumulativeAndClamped) {
  const frame::PixelRect inner{10.0, 0.0, 110.0, 5.0};
  frame::EnergyBar bar;
  bar.full_scale_J = 2.0;
  bar.segments = {{0.5, {}, ""}, {-1.0, {}, ""}, {1.0, {}, ""}, {1.0, {}, ""}};
  const std::vector<double> edges = frame::barSegmentEdgesPx(bar, inner);
  ASSERT_EQ(edges.size(), 5u);
  EXPECT_DOUBLE_EQ(edges[0], 10.0);
  EXPECT_DOUBLE_EQ(edges[1], 35.0);
  EXPECT_DOUBLE_EQ(edges[2], 35.0);  // negative energy: empty segment
  EXPECT_DOUBLE_EQ(edges[3], 85.0);
  EXPECT_DOUBLE_EQ(edges[4], 110.0);  // 2.5 J of 2 J: clamped to the end
}

TEST(LayoutTest, GridPanelsAndChartsDoNotOverlap) {
  const frame::FrameLayout layout = frame::computeFrameLayout(1280, 720, {3, 1, 1, 1.0});
  ASSERT_EQ(layout.panels.size(), 3u);
  ASSERT_EQ(layout.charts.size(), 1u);
  for (std::size_t i = 0; i < 3; ++i) {
    const frame::PanelLayout& p = layout.panels[i];
    EXPECT_LT(p.cell.x1, layout.charts[0].x0);
    EXPECT_LE(p.scene.x1, p.bar_outer.x0);  // readouts in a column right of the scene
    EXPECT_GT(p.bar_inner.width(), 0.0);
    if (i > 0) {
      EXPECT_LT(layout.panels[i - 1].cell.y1, p.cell.y0);
    }
  }
}

TEST(LayoutTest, ChartAloneFillsTheFrame) {
  const frame::FrameLayout layout = frame::computeFrameLayout(640, 360, {0, 1, 1, 1.0});
  ASSERT_EQ(layout.charts.size(), 1u);
  EXPECT_TRUE(layout.panels.empty());
  EXPECT_GT(layout.charts[0].width(), 0.9 * 640 - 40);
}

TEST(LayoutTest, SpreadIntervalsKeepsOrderAndSeparates) {
  // Two labels wanting the same spot move apart symmetrically.
  std::vector<double> x0 = frame::spreadIntervals({50.0, 50.0}, {20.0, 20.0}, 2.0, 0.0, 100.0);
  EXPECT_DOUBLE_EQ(x0[0], 29.0);
  EXPECT_DOUBLE_EQ(x0[1], 51.0);
  // Clamped at the left edge: the cluster slides right.
  x0 = frame::spreadIntervals({0.0, 5.0, 80.0}, {10.0, 10.0, 10.0}, 0.0, 0.0, 100.0);
  EXPECT_DOUBLE_EQ(x0[0], 0.0);
  EXPECT_DOUBLE_EQ(x0[1], 10.0);
  EXPECT_DOUBLE_EQ(x0[2], 75.0);
  // Unsorted wishes: placed by wish, returned in the given order.
  x0 = frame::spreadIntervals({80.0, 50.0, 50.0}, {10.0, 20.0, 20.0}, 2.0, 0.0, 100.0);
  EXPECT_DOUBLE_EQ(x0[0], 75.0);
  EXPECT_DOUBLE_EQ(x0[1], 29.0);
  EXPECT_DOUBLE_EQ(x0[2], 51.0);
}

// A label is stated by its body, or where placement moved it to the legend (wrapped in two lines
// there: joined again with a space); the body's own text wins over the legend's.
TEST(LayoutTest, StatedLabelIsByTheBodyOrJoinedFromTheLegend) {
  frame::PanelModel panel;
  panel.bodies.resize(2);
  panel.bodies[0].label = "m₁ = 1.00 kg";
  panel.legend.entries = {{1, "v₂′ =", {0.0, 0.0}, false},
                          {0, "v₁′ = +1.00 m/s", {0.0, 20.0}, false},
                          {1, "+0.500 m/s", {10.0, 40.0}, false},
                          {0, "m₁ = 2.00 kg", {0.0, 60.0}, true}};
  EXPECT_EQ(frame::statedLabel(panel, 0, true), "m₁ = 1.00 kg");
  EXPECT_EQ(frame::statedLabel(panel, 0, false), "v₁′ = +1.00 m/s");
  EXPECT_EQ(frame::statedLabel(panel, 1, false), "v₂′ = +0.500 m/s");
  EXPECT_EQ(frame::statedLabel(panel, 1, true), "");
}

}  // namespace
}  // namespace collide::render
