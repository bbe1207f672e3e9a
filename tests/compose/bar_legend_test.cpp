// The energy bar's legend names only segments that have a width: no "lost 0 J" pointing at
// nothing in an elastic scene. Checked on the frame description of every preset.
#include <gtest/gtest.h>

#include <string>

#include "app/animation.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

TEST(BarLegendTest, ZeroWidthSegmentsHaveNoLegendEntry) {
  for (const scene::PresetInfo& preset : scene::presetList()) {
    SCOPED_TRACE(preset.name);
    const app::Animation animation = app::animate(scene::loadPreset(preset.name), {640, 360});
    const double end = animation.frames.simulatedDuration_s();
    for (double t : {0.0, 0.5 * end, end}) {
      for (const frame::PanelModel& panel : animation.frames.frameAtSimulated(t).panels) {
        for (const frame::EnergySegment& segment : panel.energy_bar.segments) {
          if (segment.energy_J == 0.0) {
            EXPECT_TRUE(segment.label.empty()) << "t = " << t << ": " << segment.label;
          }
        }
      }
    }
  }
}

TEST(BarLegendTest, ElasticScenesNameNoLossAndLossyOnesDoAfterTheHit) {
  // e = 1 loses nothing (½·μ·(1 − e²)·u² = 0); e = 0.5 loses energy at its collision.
  const auto lossLabelled = [](const char* preset, double t_s) {
    const app::Animation animation = app::animate(scene::loadPreset(preset), {1280, 720});
    const frame::FrameModel frame = animation.frames.frameAtSimulated(t_s);
    for (const frame::EnergySegment& segment : frame.panels.front().energy_bar.segments) {
      if (segment.label.rfind("lost", 0) == 0) return true;
    }
    return false;
  };
  for (double t : {0.0, 1.0, 2.0, 3.0}) EXPECT_FALSE(lossLabelled("elastic", t)) << "t = " << t;
  EXPECT_FALSE(lossLabelled("worked-example", 0.0));  // nothing lost before the collision
  EXPECT_TRUE(lossLabelled("worked-example", 2.5));
}

}  // namespace
}  // namespace collide
