// SPDX-License-Identifier: MIT
// Videos that hold still and arrows that never lie (issue 37), read frame by frame as `collide
// layout --fps 60` writes them (render::drawnItems): no text item changes its number of lines
// between two consecutive frames with no collision between them (compose/text_patterns.hpp), and
// no velocity arrow's segment crosses a wall or another body's box (frame/arrow_room.hpp). Every
// preset at 1280x720 and 640x360, over its first kSpan_s of playback (its first impacts and the
// shots after them). About 7 s of one core for each size in Release.
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
std::map<std::string, std::size_t> lineCounts(const std::vector<frame::DrawnItem>& items) {
  std::map<std::string, std::size_t> lines;
  for (const frame::DrawnItem& item : items) {
    if (!item.lines.empty() && item.kind != "chart") lines[item.id] = item.lines.size();
  }
  return lines;
}

// Whether the segment from `a` to `b` runs through the inside of `box` (Liang-Barsky clipping:
// a part of it of positive length lies inside).
bool crosses(const core::Vec2& a, const core::Vec2& b, const frame::PixelRect& box) {
  double enter = 0.0, leave = 1.0;
  const core::Vec2 d = b - a;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a.x() - box.x0, box.x1 - a.x(), a.y() - box.y0, box.y1 - a.y()};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0.0) {
      if (q[k] <= 0.0) return false;
    } else if (p[k] < 0.0) {
      enter = std::max(enter, q[k] / p[k]);
    } else {
      leave = std::min(leave, q[k] / p[k]);
    }
  }
  return leave - enter > 1e-9;
}

bool holds(const frame::PixelRect& box, const core::Vec2& point) {
  return point.x() > box.x0 && point.x() < box.x1 && point.y() > box.y0 && point.y() < box.y1;
}

// The first arrow of `items` whose segment crosses a wall or the box of another body of its
// panel (not one whose box holds its tail: the body itself, one it overlaps or is stuck to),
// described; empty where none does.
std::string arrowThroughSomething(const std::vector<frame::DrawnItem>& items) {
  for (const frame::DrawnItem& arrow : items) {
    if (arrow.kind != "arrow" || !arrow.arrow) continue;
    for (const frame::DrawnItem& other : items) {
      if (other.panel != arrow.panel || (other.kind != "wall" && other.kind != "body")) continue;
      if (other.kind == "body" &&
          (other.body == arrow.body || holds(other.box, arrow.arrow->from_px))) {
        continue;
      }
      if (crosses(arrow.arrow->from_px, arrow.arrow->to_px, other.box)) {
        return arrow.id + " crosses " + other.id;
      }
    }
  }
  return {};
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
  int changes = 0, crossings = 0;
  for (int k = 0; k <= frames; ++k) {
    const double playback_s = static_cast<double>(k) / kFps;
    const double t_s = source.simulatedAt(playback_s);
    const std::vector<frame::DrawnItem> items =
        render::drawnItems(source.frameAt(playback_s), width_px, height_px);
    if (const std::string through = arrowThroughSomething(items);
        !through.empty() && ++crossings <= 3) {
      ADD_FAILURE() << through << " at t = " << t_s << " s";
    }
    std::map<std::string, std::size_t> now = lineCounts(items);
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

class VideoFramesTest : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(VideoFramesTest, TextsKeepTheirLinesAndArrowsRunThroughNothing) {
  for (const scene::PresetInfo& preset : scene::presetList()) {
    checkVideo(preset.name, GetParam().first, GetParam().second);
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, VideoFramesTest,
                         ::testing::Values(std::pair{1280, 720}, std::pair{640, 360}),
                         [](const ::testing::TestParamInfo<std::pair<int, int>>& info) {
                           return std::to_string(info.param.first) + "x" +
                                  std::to_string(info.param.second);
                         });

}  // namespace
}  // namespace collide
