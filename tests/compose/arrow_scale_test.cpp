// Velocity arrows that can be read: one scale per picture, stated once by a scale arrow of a
// round speed, and a body far faster than the rest (a bullet beside its block) drawn off scale
// with a break, so the slow body's arrow is not a sliver. Checked on the frame description.
#include <gtest/gtest.h>

#include <cmath>

#include "app/animation.hpp"
#include "render/layout.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

struct Drawn {
  render::FrameLayout layout;
  render::WorldToPixel to_px;
};

Drawn drawnAt(const render::FrameModel& frame, int width_px, int height_px) {
  const render::FrameLayout layout =
      render::computeFrameLayout(width_px, height_px, render::shapeOf(frame));
  return {layout, render::panelMapping(frame.panels.front(), layout.panels.front(), layout)};
}

// A round speed: 1, 2 or 5 times a power of ten.
bool isRound(double speed_mps) {
  const double mantissa = speed_mps / std::pow(10.0, std::floor(std::log10(speed_mps)));
  return std::abs(mantissa - 1.0) < 1e-9 || std::abs(mantissa - 2.0) < 1e-9 ||
         std::abs(mantissa - 5.0) < 1e-9;
}

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
  const render::FrameModel before = animation.frames.frameAtSimulated(0.5 * hit);
  const render::FrameModel after =
      animation.frames.frameAtSimulated(0.5 * (hit + animation.frames.simulatedDuration_s()));
  const Drawn d = drawnAt(after, 1280, 720);
  const render::PanelModel& panel_before = before.panels.front();
  const render::PanelModel& panel_after = after.panels.front();
  const double scene_width_px = d.layout.panel().scene.width();

  // One scale for the picture: the same before and after the impact.
  EXPECT_EQ(panel_before.arrow_m_per_mps, panel_after.arrow_m_per_mps);
  EXPECT_EQ(panel_before.scale_arrow_mps, panel_after.scale_arrow_mps);

  // The bullet: off scale, drawn no longer than a quarter of the scene, with a break.
  const render::ArrowShape bullet =
      render::arrowShape(std::abs(v1), panel_before, d.layout, d.to_px);
  EXPECT_TRUE(bullet.off_scale);
  EXPECT_LT(bullet.length_px, 0.25 * scene_width_px);
  const render::ArrowBreak cut = render::arrowBreak(bullet);
  EXPECT_GT(cut.break_end_px, cut.break_start_px);
  EXPECT_LT(cut.break_end_px, bullet.length_px - bullet.head_length_px);

  // The joined block's arrow is drawn to scale and long enough to read: at least a tenth of the
  // scene's width (it was a 1-pixel sliver when the bullet set the scale).
  const render::ArrowShape block =
      render::arrowShape(std::abs(common), panel_after, d.layout, d.to_px);
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
    const render::FrameModel first = animation.frames.frameAtSimulated(0.0);
    for (double t : {0.25 * end, 0.5 * end, end}) {
      const render::FrameModel frame = animation.frames.frameAtSimulated(t);
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
  render::PanelModel panel;
  panel.arrow_m_per_mps = 0.1;
  const render::FrameLayout layout = render::computeFrameLayout(1280, 720);
  const render::WorldToPixel to_px{100.0, {0.0, 0.0}};  // 100 px per metre
  // 0.01 m/s would be 0.1 px: drawn at the minimum, a head with a shaft behind it.
  const render::ArrowShape slow = render::arrowShape(0.01, panel, layout, to_px);
  EXPECT_GT(slow.length_px, slow.head_length_px);
  EXPECT_LT(slow.head_length_px, layout.arrow_head_length_px);
  // 10 m/s: 100 px, to scale, with the layout's full head.
  const render::ArrowShape fast = render::arrowShape(10.0, panel, layout, to_px);
  EXPECT_DOUBLE_EQ(fast.length_px, 100.0);
  EXPECT_DOUBLE_EQ(fast.head_length_px, layout.arrow_head_length_px);
  EXPECT_FALSE(fast.off_scale);
  // A limit of 0.5 m: 20 m/s (200 px) is drawn 50 px long, off scale.
  panel.arrow_max_length_m = 0.5;
  const render::ArrowShape capped = render::arrowShape(20.0, panel, layout, to_px);
  EXPECT_TRUE(capped.off_scale);
  EXPECT_DOUBLE_EQ(capped.length_px, 50.0);
}

}  // namespace
}  // namespace collide
