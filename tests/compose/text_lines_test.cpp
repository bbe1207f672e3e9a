// SPDX-License-Identifier: MIT
// Text wrapped once per shot (issue 37, compose/text_patterns.hpp): read frame by frame as
// `collide layout --fps 60` writes them (render::drawnItems), no text item changes its number of
// lines between two consecutive frames with no collision between them. Every preset at 1280x720
// and 640x360, over its first kSpan_s of playback (its first impacts and the shots after them).
// About 7 s of one core for each size in Release.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "app/animation.hpp"
#include "render/frame_layout.hpp"
#include "scene/scene_desc.hpp"
#include "scene/scene_io.hpp"

namespace collide {
namespace {

constexpr int kFps = 60;
constexpr double kSpan_s = 2.0;  // of playback, from the start

// Each text item's number of lines, by id. A chart's texts are its ticks and its series' names,
// not the lines of one text, and come as its curves do.
std::map<std::string, std::size_t> lineCounts(const frame::FrameModel& frame, int width_px,
                                              int height_px) {
  std::map<std::string, std::size_t> lines;
  for (const frame::DrawnItem& item : render::drawnItems(frame, width_px, height_px)) {
    if (!item.lines.empty() && item.kind != "chart") lines[item.id] = item.lines.size();
  }
  return lines;
}

// Every panel's collision times, simulated seconds, in order.
std::vector<double> eventTimes(const compose::FrameSource& source) {
  std::vector<double> events;
  for (std::size_t p = 0; p < source.panelCount(); ++p) {
    for (const physics::CollisionEvent& event : source.panelTimeline(p).collisions()) {
      events.push_back(event.time_s);
    }
  }
  std::sort(events.begin(), events.end());
  return events;
}

// Whether an event falls in (from_s, to_s].
bool eventBetween(const std::vector<double>& events, double from_s, double to_s) {
  const auto next = std::upper_bound(events.begin(), events.end(), from_s);
  return next != events.end() && *next <= to_s;
}

void checkVideo(const std::string& preset, int width_px, int height_px) {
  SCOPED_TRACE(preset + " at " + std::to_string(width_px) + "x" + std::to_string(height_px));
  const app::Animation animation = app::animate(scene::loadPreset(preset), {width_px, height_px});
  const compose::FrameSource& source = animation.frames;
  const std::vector<double> events = eventTimes(source);
  const int frames = static_cast<int>(std::min(source.duration_s(), kSpan_s) * kFps);
  std::map<std::string, std::size_t> before;
  double before_s = 0.0;
  int changes = 0;
  for (int k = 0; k <= frames; ++k) {
    const double playback_s = static_cast<double>(k) / kFps;
    const double t_s = source.simulatedAt(playback_s);
    std::map<std::string, std::size_t> now =
        lineCounts(source.frameAt(playback_s), width_px, height_px);
    if (k > 0 && !eventBetween(events, before_s, t_s)) {
      for (const auto& [id, lines] : now) {
        const auto was = before.find(id);
        if (was == before.end() || was->second == lines) continue;
        if (++changes <= 3) {
          ADD_FAILURE() << id << " goes from " << was->second << " to " << lines
                        << " lines at t = " << t_s << " s with no event since " << before_s << " s";
        }
      }
    }
    before = std::move(now);
    before_s = t_s;
  }
}

class TextLinesTest : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(TextLinesTest, EveryTextKeepsItsLinesBetweenEvents) {
  for (const scene::PresetInfo& preset : scene::presetList()) {
    checkVideo(preset.name, GetParam().first, GetParam().second);
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, TextLinesTest,
                         ::testing::Values(std::pair{1280, 720}, std::pair{640, 360}),
                         [](const ::testing::TestParamInfo<std::pair<int, int>>& info) {
                           return std::to_string(info.param.first) + "x" +
                                  std::to_string(info.param.second);
                         });

}  // namespace
}  // namespace collide
