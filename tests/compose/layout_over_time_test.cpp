// SPDX-License-Identifier: MIT
// Layout planned over time (compose/label_timeline.hpp): where a label stands at t is a function
// of t alone, so a still at t is the video's frame at t, whatever was asked for before. Every
// preset at 640x360: one picture asked for its video's frames in order, another for the same
// instants backwards (the last first, as `collide still` would), each label and legend line at the
// same place in both. About 0.5 s a preset on one core. And a video's last frame, at its very
// end, keeps its labels where the frame before had them; a frame between two steps of the plan
// stands each label between its places there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/animation.hpp"
#include "render/frame_layout.hpp"
#include "scene/scene_desc.hpp"
#include "scene/scene_io.hpp"
#include "video_frame_checks.hpp"

namespace collide {
namespace {

constexpr int kFps = 60;

// What moved, among the texts by their bodies (test::TextsOf::kBodies), more than `limit_px`
// beyond its body between two consecutive frames at kFps whose simulated time is in
// [from_s, to_s] (`jumps`), and how many frames were walked (`frames`).
struct BodyTextWatch {
  std::vector<std::string> jumps;
  int frames = 0;
};

BodyTextWatch watchBodyTexts(const compose::FrameSource& source, double from_s, double to_s,
                             double limit_px, int width_px, int height_px) {
  BodyTextWatch watch;
  std::optional<test::FrameItems> was;
  for (int k = static_cast<int>(from_s * kFps); source.simulatedAt(double(k) / kFps) <= to_s; ++k) {
    const double t_s = source.simulatedAt(double(k) / kFps);
    test::FrameItems now = test::frameItems(
        t_s, render::drawnItems(source.frameAt(double(k) / kFps), width_px, height_px));
    if (was) {
      for (std::string& jump : test::textsThatJump(*was, now, limit_px, test::TextsOf::kBodies)) {
        watch.jumps.push_back(std::move(jump));
      }
    }
    was = std::move(now);
    ++watch.frames;
  }
  return watch;
}

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

// car-crash at 640x360 ends at 4 s with its readouts flush with the frame's right edge, riding
// with their cars. The plan's last step stood a microsecond before the end; carried on from
// there the readouts stood a hair past the edge in the last frame, were refused and placed
// elsewhere (60 and 39 px off). Its last two frames, with VideoFramesTest's bound
// (video_frame_checks.hpp); the whole video's labels are planned first, about 0.3 s in a
// Release build.
TEST(LayoutOverTimeTest, TheLastFrameKeepsItsLabelsWhereTheyWere) {
  const int width_px = 640, height_px = 360;
  const app::Animation video = app::animate(scene::loadPreset("car-crash"), {width_px, height_px});
  const compose::FrameSource& source = video.frames;
  const int last = static_cast<int>(source.duration_s() * kFps);
  std::vector<test::FrameItems> frames;
  for (const int k : {last - 1, last}) {
    const double playback_s = static_cast<double>(k) / kFps;
    frames.push_back(
        test::frameItems(source.simulatedAt(playback_s),
                         render::drawnItems(source.frameAt(playback_s), width_px, height_px)));
  }
  ASSERT_DOUBLE_EQ(static_cast<double>(last) / kFps, source.duration_s()) << "its very end";
  for (const char* readout : {"velocity.1", "velocity.2"}) {
    ASSERT_NO_THROW(static_cast<void>(frames.back().texts.at(readout))) << readout << " shown";
  }
  EXPECT_EQ(test::textsThatJump(frames[0], frames[1], test::kCalmPx, test::TextsOf::kBodies),
            std::vector<std::string>{});
}

// air-drag-throw at 1280x720: ball 2 lands at 1.41 s. m₂'s way stands still from 1.33 s while
// the ball comes down under it, and the 1.4 s step lists m₂ in the legend. The frame at 1.383 s,
// between the two steps, carried m₂ off with its ball instead, where it ran into something, and
// it was placed 6 px off. From 1.35 s to the last frame before 1.4 s (no event) no mass label or
// readout by its ball moves more than kCalmPx between two consecutive frames at 60 fps. (At 1.4
// s m₂ leaves for its legend: VideoFramesTest counts that jump.)
TEST(LayoutOverTimeTest, AStandingLabelListedAtTheNextStepStandsOn) {
  constexpr int kWidthPx = 1280, kHeightPx = 720;
  const app::Animation animation =
      app::animate(scene::loadPreset("air-drag-throw"), {kWidthPx, kHeightPx});
  const compose::FrameSource& source = animation.frames;
  const std::vector<physics::CollisionEvent>& events = source.panelTimeline(0).collisions();
  ASSERT_TRUE(std::none_of(events.begin(), events.end(), [](const physics::CollisionEvent& e) {
    return e.time_s > 1.35 && e.time_s < 1.4;
  })) << "no event watched";
  const BodyTextWatch watch =
      watchBodyTexts(source, 1.35, 1.39, test::kCalmPx, kWidthPx, kHeightPx);
  for (const std::string& jump : watch.jumps) ADD_FAILURE() << jump;
  EXPECT_GE(watch.frames, 3);
}

// air-track at 640x360: cart 2 bounces off the right wall at 5.56 s. Its readout's text widens
// a step after the event (v₂′ through zero, 4 digits), too wide there for its row by the wall;
// priced only at the event, its place ended the shot there and it went up a row at once at the
// event (20 px in one frame). From 5.5 to 5.65 s no mass label or readout by its body moves
// more than kEventPx between two consecutive frames at 60 fps.
TEST(LayoutOverTimeTest, AReadoutLeavesBeforeItsTextWidensAfterTheEvent) {
  constexpr int kWidthPx = 640, kHeightPx = 360;
  const app::Animation animation =
      app::animate(scene::loadPreset("air-track"), {kWidthPx, kHeightPx});
  const compose::FrameSource& source = animation.frames;
  const std::vector<physics::CollisionEvent>& events = source.panelTimeline(0).collisions();
  ASSERT_TRUE(std::any_of(events.begin(), events.end(), [](const physics::CollisionEvent& e) {
    return e.time_s > 5.5 && e.time_s < 5.6;
  })) << "the wall bounce watched";
  const BodyTextWatch watch =
      watchBodyTexts(source, 5.5, 5.65, test::kEventPx, kWidthPx, kHeightPx);
  for (const std::string& jump : watch.jumps) ADD_FAILURE() << jump;
  EXPECT_GE(watch.frames, 8);
}

// worked-example: carts 0.5 m wide at -2 m (+2 m/s) and +2 m (-1 m/s) meet when the 3.5 m
// between them has closed at 3 m/s, at 7/6 s. v₁'s readout stands over the track in arrow 2's
// row, its leader down to arrow 1, while cart 1 runs on under it; arrow 2's tip closes in on it
// until at the shot's last step it reads as cart 2's. The plan kept it there, and the frame at
// 1.15 s placed it beyond arrow 1's tip, 538 px off at 1280x720 (46 px at 640x360), and back at
// the event. From 1 s to the event no mass label or readout by its body moves more than kCalmPx
// between two consecutive frames at 60 fps, nor more than kEventPx from the last frame before
// the event to kShortestShot_s after it, at both sizes. About 0.4 s in a Release build.
TEST(LayoutOverTimeTest, AReadoutGetsOutOfTheWayOfAnArrowTipBeforeTheEvent) {
  const double meet_s = (2.0 - (-2.0) - 0.5) / (2.0 - (-1.0));
  for (const auto& [width_px, height_px] : {std::pair{1280, 720}, std::pair{640, 360}}) {
    SCOPED_TRACE(std::to_string(width_px) + "x" + std::to_string(height_px));
    const app::Animation animation =
        app::animate(scene::loadPreset("worked-example"), {width_px, height_px});
    const compose::FrameSource& source = animation.frames;
    const std::vector<physics::CollisionEvent>& events = source.panelTimeline(0).collisions();
    ASSERT_FALSE(events.empty());
    ASSERT_NEAR(events.front().time_s, meet_s, 1e-9) << "the impact watched";
    const double last_before_s = std::ceil(meet_s * kFps - 1.0) / kFps;
    const BodyTextWatch calm =
        watchBodyTexts(source, 1.0, last_before_s, test::kCalmPx, width_px, height_px);
    for (const std::string& jump : calm.jumps) ADD_FAILURE() << jump;
    const BodyTextWatch event =
        watchBodyTexts(source, last_before_s, meet_s + 0.3, test::kEventPx, width_px, height_px);
    for (const std::string& jump : event.jumps) ADD_FAILURE() << jump;
    EXPECT_GE(calm.frames, 9);
    EXPECT_GE(event.frames, 19);
  }
}

}  // namespace
}  // namespace collide
