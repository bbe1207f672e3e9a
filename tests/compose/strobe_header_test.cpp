// A strobe's header: its title on one line beside the time span at 1280x720, in every preset, as
// a still's title stands beside its time. (ballistic-pendulum's "t = 0 to 0.517 s" left its title
// 4 px short of one line, so its last word wrapped alone onto a second line.) Measured with the
// real text metrics through the layout the painters use; no GL.
#include <gtest/gtest.h>

#include <string>

#include "app/animation.hpp"
#include "frame_layouts.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

TEST(StrobeHeaderTest, TitleStaysOnOneLineBesideTheTimeSpanAt1280x720) {
  render::TextMetrics metrics;
  int checked = 0;
  for (const scene::PresetInfo& preset : scene::presetList()) {
    const scene::SceneDesc scene = scene::loadPreset(preset.name);
    // The gas's title is short and it alone takes seconds to simulate.
    if (scene.bodies.size() > 40) continue;
    SCOPED_TRACE(preset.name);
    const app::Animation animation = app::animate(scene, {1280, 720});
    const frame::FrameModel frame = animation.frames.strobeFrame(0.0);
    ASSERT_FALSE(frame.title.empty());
    ASSERT_FALSE(frame.time_readout.empty()) << "a strobe states its time span";
    const frame::FrameLayout layout = test::layoutMeasured(frame, 1280, 720, metrics);
    EXPECT_EQ(layout.title_lines, 1)
        << "\"" << frame.title << "\" (" << metrics.width(frame.title, layout.title_px)
        << " px) beside \"" << frame.time_readout << "\" ("
        << metrics.width(frame.time_readout, layout.title_px) << " px) in a header "
        << layout.header.width() << " px wide";
    ++checked;
  }
  EXPECT_GE(checked, 15) << "the presets were not found";
}

}  // namespace
}  // namespace collide
