// Framing, checked on the frame description (no pixels read): in every 2D preset the scene (its
// bodies wherever they go over the whole timeline, plus its walls or box) fills at least 70 % of
// the panel's drawing area in one direction, at 1280x720 and 640x360, and is wholly inside it.
// The extent is recomputed here from the timeline and the scene's sizes, not from compose's plan.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "frame/layout.hpp"
#include "frame_layouts.hpp"
#include "painted_geometry.hpp"
#include "pixel_rects.hpp"
#include "render/text/text_metrics.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

constexpr double kLeastFill = 0.70;  // of the drawing area, in the fuller direction
constexpr int kSamples = 1000;       // timeline instants sampled for the bodies' reach

struct Extent {
  core::Vec2 low = core::Vec2::Constant(INFINITY), high = core::Vec2::Constant(-INFINITY);
  void add(const core::Vec2& p) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
};

// Everything the scene puts in the world over its whole run, metres (lab frame).
Extent sceneExtent(const scene::SceneDesc& scene, const physics::Timeline& timeline) {
  Extent extent;
  const double end = timeline.duration_s();
  for (int s = 0; s <= kSamples; ++s) {
    const physics::Snapshot snapshot = timeline.sample(end * s / kSamples);
    for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
      const double r =
          scene.bodies[i].shape == "disk" ? scene.bodies[i].size_m : 0.5 * scene.bodies[i].size_m;
      extent.add(snapshot.bodies[i].position_m - core::Vec2{r, r});
      extent.add(snapshot.bodies[i].position_m + core::Vec2{r, r});
    }
  }
  // Pivots hold strings and their bars.
  for (const scene::BodyDesc& body : scene.bodies) {
    if (!body.pivot_m) continue;
    const double reach = body.shape == "disk" ? body.size_m : 0.5 * body.size_m;
    extent.add(*body.pivot_m - core::Vec2{reach, reach});
    extent.add(*body.pivot_m + core::Vec2{reach, reach});
  }
  // A wall is a line: only its offset along its normal bounds the scene.
  for (const scene::WallDesc& wall : scene::allWalls(scene)) {
    const core::Vec2 n = wall.normal.normalized();
    if (std::abs(n.x()) > 0.99) {
      extent.low.x() = std::min(extent.low.x(), wall.position_m.x());
      extent.high.x() = std::max(extent.high.x(), wall.position_m.x());
    }
    if (std::abs(n.y()) > 0.99) {
      extent.low.y() = std::min(extent.low.y(), wall.position_m.y());
      extent.high.y() = std::max(extent.high.y(), wall.position_m.y());
    }
  }
  return extent;
}

class FramingTest : public ::testing::TestWithParam<test::PictureSize> {};

TEST_P(FramingTest, EveryPlanePresetFillsItsDrawingArea) {
  const auto [width_px, height_px] = GetParam();
  int checked = 0;
  for (const scene::PresetInfo& preset : scene::presetList()) {
    const scene::SceneDesc scene = scene::loadPreset(preset.name);
    if (scene.dimensions != 2 || !scene.view.panel_values.empty()) continue;
    ASSERT_FALSE(scene.view.center_of_momentum_frame) << preset.name << ": lab-frame extents only";
    SCOPED_TRACE(preset.name + " at " + std::to_string(width_px) + "x" + std::to_string(height_px));
    ++checked;
    const app::Animation animation = app::animate(scene, {width_px, height_px});
    const frame::FrameModel frame = animation.frames.frameAtSimulated(0.0);
    render::TextMetrics metrics;
    const frame::FrameLayout layout = test::layoutMeasured(frame, width_px, height_px, metrics);
    const frame::PanelModel& panel = frame.panels.front();
    const frame::PanelLayout& where = layout.panels.front();
    const frame::WorldToPixel to_px = frame::panelMapping(panel, where, layout);

    const Extent world = sceneExtent(scene, animation.frames.timeline());
    const core::Vec2 a = to_px.toPixel(world.low), b = to_px.toPixel(world.high);
    const double x0 = std::min(a.x(), b.x()), x1 = std::max(a.x(), b.x());
    const double y0 = std::min(a.y(), b.y()), y1 = std::max(a.y(), b.y());
    // The drawing area: the panel's scene, between the heading line and the energy bar.
    const frame::PixelRect& area = where.scene;
    EXPECT_GE(x0, area.x0 - 0.5);
    EXPECT_LE(x1, area.x1 + 0.5);
    EXPECT_GE(y0, area.y0 - 0.5);
    EXPECT_LE(y1, area.y1 + 0.5);
    const double fill = std::max((x1 - x0) / area.width(), (y1 - y0) / area.height());
    EXPECT_GE(fill, kLeastFill) << "spans " << (x1 - x0) << " x " << (y1 - y0) << " px of "
                                << area.width() << " x " << area.height() << " px";
  }
  EXPECT_GE(checked, 4) << "the plane presets were not found";
}

using test::overlaps;

// A plane scene in a wide frame keeps the whole height: its readouts go in a column beside it,
// which never reaches into the scene, and its bodies are drawn larger than the stacked layout
// (readouts under the scene, each text at its fewest lines: the stacked world at its largest)
// could draw them, unless the stacked world already spans the whole width. The scale is the
// same at every instant, so a video's world never jumps.
TEST_P(FramingTest, PlaneScenesGrowBesideAColumnOfReadouts) {
  constexpr double kLeastGain = 1.05;
  const auto [width_px, height_px] = GetParam();
  render::TextMetrics metrics;
  int grown = 0;
  for (const scene::PresetInfo& preset : scene::presetList()) {
    const scene::SceneDesc scene = scene::loadPreset(preset.name);
    if (scene.dimensions != 2 || !scene.view.panel_values.empty() || scene.view.chart) continue;
    SCOPED_TRACE(preset.name + " at " + std::to_string(width_px) + "x" + std::to_string(height_px));
    const app::Animation animation = app::animate(scene, {width_px, height_px});
    const double end = animation.frames.simulatedDuration_s();
    double first_px_per_m = 0.0;
    for (double t : {0.0, 0.25 * end, 0.5 * end, end}) {
      const frame::FrameModel frame = animation.frames.frameAtSimulated(t);
      const frame::PanelModel& panel = frame.panels.front();
      const frame::FrameLayout layout = test::layoutMeasured(frame, width_px, height_px, metrics);
      const frame::PanelLayout& where = layout.panels.front();
      const double px_per_m = frame::panelMapping(panel, where, layout).px_per_m;
      if (first_px_per_m == 0.0) first_px_per_m = px_per_m;
      EXPECT_NEAR(px_per_m, first_px_per_m, 1e-9 * first_px_per_m) << "t = " << t;

      const frame::FrameLayout stacked =
          frame::computeFrameLayout(width_px, height_px, frame::shapeOf(frame));
      const frame::PixelRect stacked_area = frame::worldArea(panel, stacked.panel(), stacked);
      const double stacked_px_per_m = frame::fitView(panel.view, stacked_area).px_per_m;
      const double view_w = panel.view.max_m.x() - panel.view.min_m.x();
      const bool spans_width = view_w * stacked_px_per_m >= stacked_area.width() - 1e-6;
      if (spans_width) {
        EXPECT_GE(px_per_m, stacked_px_per_m * (1.0 - 1e-9));
        continue;
      }
      EXPECT_GE(px_per_m, kLeastGain * stacked_px_per_m)
          << "a disk of 0.1 m: " << 0.1 * px_per_m << " px, stacked " << 0.1 * stacked_px_per_m;
      EXPECT_DOUBLE_EQ(where.scene.y0, where.cell.y0) << "the scene lost height";
      EXPECT_DOUBLE_EQ(where.scene.y1, where.cell.y1) << "the scene lost height";
      std::vector<frame::PixelRect> column{where.info, where.bar_outer, where.bar_labels,
                                           where.caption, where.scale_row};
      if (const auto box = frame::momentumBox(panel, where, layout)) column.push_back(*box);
      for (const frame::PixelRect& part : column) {
        EXPECT_FALSE(overlaps(part, where.world_clip))
            << "[" << part.x0 << ", " << part.y0 << "]-[" << part.x1 << ", " << part.y1
            << "] reaches into the scene";
        EXPECT_LE(part.y1, height_px);
        EXPECT_LE(part.x1, width_px);
      }
      if (t == 0.0) ++grown;
    }
  }
  // billiards-glancing, billiards-break, bouncing-ball, ballistic-pendulum, newtons-cradle at
  // least: the test must not pass by finding only scenes that span the width.
  EXPECT_GE(grown, 5);
}

// Whether every body of the run only ever moves along x, read from the timeline's samples.
bool movesAlongXOnly(const physics::Timeline& timeline) {
  const double end = timeline.duration_s();
  for (int s = 0; s <= kSamples; ++s) {
    for (const physics::BodyState& body : timeline.sample(end * s / kSamples).bodies) {
      if (body.velocity_mps.y() != 0.0) return false;
    }
  }
  return true;
}

// A plane scene whose bodies only move along x (a head-on shot along the table) keeps its
// velocity arrows inside its world's clip at every frame, as a 1D track does: billiards-follow's
// object ball ends at the far side, where its arrow ran off the frame.
TEST_P(FramingTest, HeadOnPlaneShotsKeepTheirArrowsInTheScene) {
  const auto [width_px, height_px] = GetParam();
  render::TextMetrics metrics;
  int checked = 0;
  for (const scene::PresetInfo& preset : scene::presetList()) {
    const scene::SceneDesc scene = scene::loadPreset(preset.name);
    if (scene.dimensions != 2 || !scene.view.panel_values.empty()) continue;
    const app::Animation animation = app::animate(scene, {width_px, height_px});
    if (!movesAlongXOnly(animation.frames.timeline())) continue;
    SCOPED_TRACE(preset.name + " at " + std::to_string(width_px) + "x" + std::to_string(height_px));
    ++checked;
    const double end = animation.frames.simulatedDuration_s();
    for (int k = 0; k <= 20; ++k) {
      const frame::FrameModel frame = animation.frames.frameAtSimulated(end * k / 20);
      const frame::FrameLayout layout = test::layoutMeasured(frame, width_px, height_px, metrics);
      const frame::PanelModel& panel = frame.panels.front();
      const frame::PanelLayout& where = layout.panels.front();
      const frame::WorldToPixel to_px = frame::panelMapping(panel, where, layout);
      for (const compose_test::PaintedArrow& arrow :
           compose_test::paintedArrows(panel, layout, to_px)) {
        for (const core::Vec2& end_px : {arrow.tail, arrow.tip}) {
          EXPECT_GE(end_px.x() - arrow.half_width, where.world_clip.x0) << "t = " << end * k / 20;
          EXPECT_LE(end_px.x() + arrow.half_width, where.world_clip.x1) << "t = " << end * k / 20;
        }
      }
    }
  }
  EXPECT_GE(checked, 2) << "billiards-follow and billiards-draw were not found";
}

INSTANTIATE_TEST_SUITE_P(Sizes, FramingTest, test::videoSizes(), test::sizeName);

}  // namespace
}  // namespace collide
