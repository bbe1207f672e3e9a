// SPDX-License-Identifier: MIT
// Layout planned over time (compose/label_timeline.hpp): where a label stands at t is a function
// of t alone, so a still at t is the video's frame at t, whatever was asked for before. Every
// preset at 640x360: one picture asked for its video's frames in order, another for the same
// instants backwards (the last first, as `collide still` would), each label and legend line at the
// same place in both. About 0.5 s a preset on one core.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/animation.hpp"
#include "scene/scene_desc.hpp"
#include "scene/scene_io.hpp"

namespace collide {
namespace {

// Every placed text of a frame, in a fixed order: "body 2 velocity (x, y)".
std::vector<std::string> placedTexts(const frame::FrameModel& frame) {
  std::vector<std::string> texts;
  const auto at = [](const std::optional<frame::PlacedText>& placed) {
    return placed ? "(" + std::to_string(placed->top_left_px.x()) + ", " +
                        std::to_string(placed->top_left_px.y()) + ")"
                  : std::string("none");
  };
  for (std::size_t p = 0; p < frame.panels.size(); ++p) {
    const frame::PanelModel& panel = frame.panels[p];
    for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
      const std::string body = "panel " + std::to_string(p + 1) + " body " + std::to_string(i + 1);
      texts.push_back(body + " mass " + panel.bodies[i].label + " " + at(panel.bodies[i].label_at));
      texts.push_back(body + " velocity " + panel.bodies[i].velocity_label + " " +
                      at(panel.bodies[i].velocity_label_at));
    }
    for (const frame::ReadoutLegend::Entry& entry : panel.legend.entries) {
      texts.push_back("legend " + entry.text + " (" + std::to_string(entry.top_left_px.x()) + ", " +
                      std::to_string(entry.top_left_px.y()) + ")");
    }
  }
  return texts;
}

TEST(LayoutOverTimeTest, AStillIsTheVideosFrameWhateverWasAskedBefore) {
  constexpr int kFps = 60;
  for (const scene::PresetInfo& preset : scene::presetList()) {
    SCOPED_TRACE(preset.name);
    const scene::SceneDesc scene = scene::loadPreset(preset.name);
    const app::Animation video = app::animate(scene, {640, 360});
    const app::Animation stills = app::animate(scene, {640, 360});
    // Instants over the first second and a half (the first impact of most presets, and the
    // labels gliding after it), frame by frame; the stills asked for last first.
    std::vector<int> frames;
    const int last = std::min(90, static_cast<int>(video.frames.duration_s() * kFps));
    for (int k = 0; k <= last; k += 3) frames.push_back(k);
    std::vector<std::vector<std::string>> in_order;
    for (int k : frames) in_order.push_back(placedTexts(video.frames.frameAt(double(k) / kFps)));
    for (std::size_t n = frames.size(); n-- > 0;) {
      const double t = stills.frames.simulatedAt(double(frames[n]) / kFps);
      EXPECT_EQ(placedTexts(stills.frames.frameAtSimulated(t)), in_order[n])
          << "frame " << frames[n];
    }
  }
}

}  // namespace
}  // namespace collide
