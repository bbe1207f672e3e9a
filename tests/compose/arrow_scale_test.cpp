// Velocity arrows that can be read: one scale per picture, stated once by a scale arrow of a
// round speed, and a body far faster than the rest (a bullet beside its block) drawn off scale
// with a break, so the slow body's arrow is not a sliver. Checked on the frame description.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "frame/arrow_room.hpp"
#include "frame/layout.hpp"
#include "frame_layouts.hpp"
#include "render/text/text_metrics.hpp"
#include "round_numbers.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

struct Drawn {
  frame::FrameLayout layout;
  frame::WorldToPixel to_px;
};

Drawn drawnAt(const frame::FrameModel& frame, int width_px, int height_px) {
  const frame::FrameLayout layout =
      frame::computeFrameLayout(width_px, height_px, frame::shapeOf(frame));
  return {layout, frame::panelMapping(frame.panels.front(), layout.panels.front(), layout)};
}

using test::isRound;

TEST(ArrowScaleTest, BulletIsOffScaleAndTheBlockArrowReads) {
  const scene::SceneDesc scene = scene::loadPreset("bullet-block");
  ASSERT_EQ(scene.bodies.size(), 2u);
  const double m1 = scene.bodies[0].mass_kg, m2 = scene.bodies[1].mass_kg;
  const double v1 = scene.bodies[0].velocity_mps.x(), v2 = scene.bodies[1].velocity_mps.x();
  // e = 0: they move on together at the common velocity (conservation of momentum).
  const double common = (m1 * v1 + m2 * v2) / (m1 + m2);
  ASSERT_GT(std::abs(v1), 50.0 * std::abs(common));  // the case this test is about

  const app::Animation animation = app::animate(scene, {1280, 720});
  const double hit = animation.frames.timeline().collisions().front().time_s;
  const frame::FrameModel before = animation.frames.frameAtSimulated(0.5 * hit);
  const frame::FrameModel after =
      animation.frames.frameAtSimulated(0.5 * (hit + animation.frames.simulatedDuration_s()));
  const Drawn d = drawnAt(after, 1280, 720);
  const frame::PanelModel& panel_before = before.panels.front();
  const frame::PanelModel& panel_after = after.panels.front();
  const double scene_width_px = d.layout.panel().scene.width();

  // One scale for the picture: the same before and after the impact.
  EXPECT_EQ(panel_before.arrow_m_per_mps, panel_after.arrow_m_per_mps);
  EXPECT_EQ(panel_before.scale_arrow_mps, panel_after.scale_arrow_mps);

  // The bullet: off scale, drawn no longer than a quarter of the scene, with a break.
  const frame::ArrowShape bullet = frame::arrowShape(std::abs(v1), panel_before, d.layout, d.to_px);
  EXPECT_TRUE(bullet.off_scale);
  EXPECT_LT(bullet.length_px, 0.25 * scene_width_px);
  const frame::ArrowBreak cut = frame::arrowBreak(bullet);
  EXPECT_GT(cut.break_end_px, cut.break_start_px);
  EXPECT_LT(cut.break_end_px, bullet.length_px - bullet.head_length_px);

  // The joined block's arrow is drawn to scale and long enough to read: at least a tenth of the
  // scene's width (it was a 1-pixel sliver when the bullet set the scale).
  const frame::ArrowShape block =
      frame::arrowShape(std::abs(common), panel_after, d.layout, d.to_px);
  EXPECT_FALSE(block.off_scale);
  EXPECT_NEAR(block.length_px, std::abs(common) * panel_after.arrow_m_per_mps * d.to_px.px_per_m,
              1e-9);
  EXPECT_GT(block.length_px, 0.1 * scene_width_px);

  // The scale arrow: a round speed no faster than the block, with its value written.
  EXPECT_TRUE(isRound(panel_after.scale_arrow_mps));
  EXPECT_LE(panel_after.scale_arrow_mps, std::abs(common));
  EXPECT_NE(panel_after.scale_arrow_label.find(" m/s"), std::string::npos);
}

// Every preset: a scale arrow wherever arrows are drawn, one scale for all its frames, and no
// arrow off scale where the speeds are within a factor of ten of each other.
TEST(ArrowScaleTest, OneStatedScalePerPicture) {
  for (const scene::PresetInfo& preset : scene::presetList()) {
    SCOPED_TRACE(preset.name);
    const app::Animation animation = app::animate(scene::loadPreset(preset.name), {640, 360});
    const double end = animation.frames.simulatedDuration_s();
    const frame::FrameModel first = animation.frames.frameAtSimulated(0.0);
    for (double t : {0.25 * end, 0.5 * end, end}) {
      const frame::FrameModel frame = animation.frames.frameAtSimulated(t);
      for (std::size_t p = 0; p < frame.panels.size(); ++p) {
        EXPECT_EQ(frame.panels[p].arrow_m_per_mps, first.panels.front().arrow_m_per_mps);
        // Stated once: in the first panel only.
        EXPECT_EQ(frame.panels[p].scale_arrow_mps > 0.0,
                  p == 0 && frame.panels[p].arrow_m_per_mps > 0.0);
      }
      if (frame.panels.front().scale_arrow_mps > 0.0) {
        EXPECT_TRUE(isRound(frame.panels.front().scale_arrow_mps));
      }
    }
  }
}

TEST(ArrowScaleTest, ShortArrowsKeepAShaftAndLongOnesAFullHead) {
  frame::PanelModel panel;
  panel.arrow_m_per_mps = 0.1;
  const frame::FrameLayout layout = frame::computeFrameLayout(1280, 720);
  const frame::WorldToPixel to_px{100.0, {0.0, 0.0}};  // 100 px per metre
  // 0.01 m/s would be 0.1 px: drawn at the minimum, a head with a shaft behind it.
  const frame::ArrowShape slow = frame::arrowShape(0.01, panel, layout, to_px);
  EXPECT_GT(slow.length_px, slow.head_length_px);
  EXPECT_LT(slow.head_length_px, layout.arrow_head_length_px);
  // 10 m/s: 100 px, to scale, with the layout's full head.
  const frame::ArrowShape fast = frame::arrowShape(10.0, panel, layout, to_px);
  EXPECT_DOUBLE_EQ(fast.length_px, 100.0);
  EXPECT_DOUBLE_EQ(fast.head_length_px, layout.arrow_head_length_px);
  EXPECT_FALSE(fast.off_scale);
  // A limit of 0.5 m: 20 m/s (200 px) is drawn 50 px long, off scale.
  panel.arrow_max_length_m = 0.5;
  const frame::ArrowShape capped = frame::arrowShape(20.0, panel, layout, to_px);
  EXPECT_TRUE(capped.off_scale);
  EXPECT_DOUBLE_EQ(capped.length_px, 50.0);
}

// The scale arrow states the scale, so it is drawn exactly to scale, and it is chosen long enough
// to read: at least a head length (billiards-glancing's 0.5 m/s was a 10 px speck at 640x360).
TEST(ArrowScaleTest, TheScaleArrowIsLongEnoughToRead) {
  render::TextMetrics metrics;
  for (const scene::PresetInfo& preset : scene::presetList()) {
    for (const auto& [width_px, height_px] : {std::pair{640, 360}, std::pair{1280, 720}}) {
      SCOPED_TRACE(preset.name + " at " + std::to_string(width_px) + "x" +
                   std::to_string(height_px));
      const app::Animation animation =
          app::animate(scene::loadPreset(preset.name), {width_px, height_px});
      const frame::FrameModel frame = animation.frames.frameAtSimulated(0.0);
      const frame::PanelModel& panel = frame.panels.front();
      if (frame.panels.size() != 1 || !(panel.scale_arrow_mps > 0.0)) continue;
      const frame::FrameLayout layout = test::layoutMeasured(frame, width_px, height_px, metrics);
      const frame::WorldToPixel to_px = frame::panelMapping(panel, layout.panels.front(), layout);
      const frame::ArrowShape arrow =
          frame::scaleArrowShape(panel.scale_arrow_mps, panel, layout, to_px);
      EXPECT_NEAR(arrow.length_px, panel.scale_arrow_mps * panel.arrow_m_per_mps * to_px.px_per_m,
                  1e-9 * arrow.length_px);
      EXPECT_GE(arrow.length_px, layout.arrow_head_length_px)
          << panel.scale_arrow_label << " is " << arrow.length_px << " px";
      EXPECT_TRUE(isRound(panel.scale_arrow_mps));
      EXPECT_EQ(panel.scale_arrow_label.substr(panel.scale_arrow_label.size() - 4), " m/s");
    }
  }
}

// Speck arrows (the air-track gliders while their bumpers turn them round, slow balls of a
// break): every moving body's arrow shows a full head length beyond the body it starts in (2D:
// from the centre, past the edge), whatever its speed. One drawn longer than its scale says so
// (under_scale: a below-scale mark); one drawn to scale has exactly its scaled length. Every
// preset, at 25 instants and through its first collisions (mid-contact for soft ones), at 640x360.
TEST(ArrowScaleTest, EveryMovingBodysArrowIsVisibleBeyondItsBody) {
  render::TextMetrics metrics;
  int under = 0, left_out = 0;
  for (const scene::PresetInfo& preset : scene::presetList()) {
    const app::Animation animation = app::animate(scene::loadPreset(preset.name), {640, 360});
    const compose::FrameSource& source = animation.frames;
    const double end = source.simulatedDuration_s();
    std::vector<double> instants;
    for (int k = 0; k <= 24; ++k) instants.push_back(end * k / 24.0);
    const auto& hits = source.timeline().collisions();
    for (std::size_t c = 0; c < hits.size() && c < 3; ++c) {
      for (double after : {0.001, 0.01, 0.025, 0.04}) {
        instants.push_back(std::min(end, hits[c].time_s + after));
      }
    }
    for (double t : instants) {
      SCOPED_TRACE(preset.name + " at t = " + std::to_string(t) + " s");
      const frame::FrameModel frame = source.frameAtSimulated(t);
      const frame::FrameLayout layout = test::layoutMeasured(frame, 640, 360, metrics);
      for (std::size_t p = 0; p < frame.panels.size(); ++p) {
        const frame::PanelModel& panel = frame.panels[p];
        const frame::WorldToPixel to_px = frame::panelMapping(panel, layout.panels[p], layout);
        for (const frame::BodyModel& body : panel.bodies) {
          const double speed = body.velocity_mps.norm();
          if (speed <= 1e-6 || panel.arrow_m_per_mps <= 0.0 || body.moves_with >= 0) continue;
          const frame::ArrowShape arrow = frame::bodyArrowShape(body, panel, layout, to_px);
          // 2D arrows start at the centre: the body's half size of them is under it.
          // One drawn beside its body (no room straight on: frame::arrowBesideOrInRoom) or from
          // its edge (frame::arrowReadingOrMark) has none.
          const double hidden = panel.two_d && arrow.beside_px == 0.0 && arrow.tail_ahead_px == 0.0
                                    ? to_px.px_per_m * body.half_extent_m.cwiseAbs().maxCoeff()
                                    : 0.0;
          const double to_scale = speed * panel.arrow_m_per_mps * to_px.px_per_m;
          // A 2D arrow with no room for a head beyond its body before a wall or another body
          // (a ball in the rack) is left out, its value in its readout: never drawn through
          // them (VideoFramesTest checks the drawn ones).
          if (panel.two_d && arrow.length_px == 0.0) {
            ++left_out;
            // Too little room for a head and a break past the body; or, for an arrow that reads
            // at its true length (a head or more), for that length from the body's edge.
            const double room = frame::arrowRoomPx(body, panel, layout, to_px);
            if (to_scale >= layout.arrow_head_length_px) {
              EXPECT_LT(room, hidden + to_scale);
            } else {
              EXPECT_LT(room,
                        hidden + layout.arrow_head_length_px + 0.6 * layout.arrow_head_width_px);
            }
            continue;
          }
          EXPECT_GE(arrow.length_px - hidden, layout.arrow_head_length_px * (1.0 - 1e-9))
              << "speed " << speed << " m/s: " << arrow.length_px << " px from its tail, " << hidden
              << " px under its body";
          if (arrow.off_scale) continue;
          if (arrow.under_scale) {
            ++under;
            EXPECT_GT(arrow.length_px, to_scale);
          } else {
            EXPECT_NEAR(arrow.length_px, to_scale, 1e-9 * to_scale);
          }
        }
      }
    }
  }
  EXPECT_GT(under, 0) << "no arrow was short enough to need the visible minimum";
  std::printf("2D arrows left out for want of room: %d\n", left_out);
}

TEST(ArrowScaleTest, AnArrowDrawnLongerThanItsScaleIsMarked) {
  frame::PanelModel panel;
  panel.arrow_m_per_mps = 0.1;
  const frame::FrameLayout layout = frame::computeFrameLayout(1280, 720);
  const frame::WorldToPixel to_px{100.0, {0.0, 0.0}};  // 100 px per metre: 10 px per m/s
  // 0.2 m/s would be 2 px: drawn at the visible minimum (a head and a shaft), marked.
  const frame::ArrowShape speck = frame::arrowShape(0.2, panel, layout, to_px);
  EXPECT_TRUE(speck.under_scale);
  EXPECT_FALSE(speck.off_scale);
  EXPECT_GT(speck.length_px, speck.head_length_px);
  EXPECT_GE(speck.length_px, layout.arrow_head_length_px * (1.0 - 1e-9));
  // A disk of radius 0.5 m (50 px) at 6 m/s (60 px, to scale): only 10 px of it would show
  // beyond the edge from its centre, less than a head; but 60 px reads as an arrow (more than a
  // head), so it is drawn that long from the disk's edge, on its scale, unmarked.
  panel.two_d = true;
  panel.view = {{-10.0, -10.0}, {10.0, 10.0}};  // room around the disk for its arrow
  frame::BodyModel disk;
  disk.shape = frame::BodyShape::kDisk;
  disk.half_extent_m = {0.5, 0.5};
  disk.velocity_mps = {6.0, 0.0};
  ASSERT_GT(60.0, layout.arrow_head_length_px);
  const frame::ArrowShape covered = frame::bodyArrowShape(disk, panel, layout, to_px);
  EXPECT_FALSE(covered.under_scale);
  EXPECT_DOUBLE_EQ(covered.length_px, 60.0);
  EXPECT_DOUBLE_EQ(covered.tail_ahead_px, 50.0);
  // At 1 m/s (10 px, under a head) it would not read at its length: drawn longer, marked.
  ASSERT_LT(10.0, layout.arrow_head_length_px);
  disk.velocity_mps = {1.0, 0.0};
  const frame::ArrowShape speck_2d = frame::bodyArrowShape(disk, panel, layout, to_px);
  EXPECT_TRUE(speck_2d.under_scale);
  EXPECT_GE(speck_2d.length_px - 50.0, layout.arrow_head_length_px * (1.0 - 1e-9));
  // At 20 m/s (200 px) it reads beyond the disk: to scale, unmarked.
  disk.velocity_mps = {0.0, -20.0};
  const frame::ArrowShape clear = frame::bodyArrowShape(disk, panel, layout, to_px);
  EXPECT_FALSE(clear.under_scale);
  EXPECT_DOUBLE_EQ(clear.length_px, 200.0);
}

}  // namespace
}  // namespace collide
