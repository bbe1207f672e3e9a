// SPDX-License-Identifier: MIT
// Videos that hold still and arrows that never lie (issue 37), read frame by frame as `collide
// layout --fps 60` writes them (render::drawnItems). Between two consecutive frames with no
// collision between them no label, readout or legend entry moves more than kCalmPx beyond its
// body's own motion, and within kEventSpan_s after a collision no more than kEventPx
// (compose/label_timeline.hpp), counted apart for texts attached to a body ("labels jump") and
// the frame's own readouts, placed by its layout ("readouts jump"), a label that leaves its body
// for its legend or comes back from it counted as moving there (unless it fades from one place to
// the other, shown at both: then no text's opacity changes faster than a 0.3 s fade allows,
// compose/label_fades.hpp); no text item changes its number of lines between two frames with
// no collision between them (compose/text_patterns.hpp); every arrow drawn on the scale is as
// long as its value says; no velocity arrow's segment crosses a wall or another body's box
// (frame/arrow_room.hpp); no velocity arrow's form lasts fewer than kFewestFormFrames frames
// between two changes with no event between them unless its speed says so
// (arrow_form_checks.hpp, "arrow form flickers"); no energy-bar leader meets another, runs
// through another entry or ends off its own, and no legend entry comes or goes between two
// frames with no collision between them while its segment has energy (legend_checks.hpp). Every
// preset at 1280x720 and 640x360, every frame from the first to the last (a jump between two
// frames that a sparser walk skipped is still a jump). And every frame's texts stand clear as a
// still's do (label_clearance_checks.hpp: inside the frame, over nothing, near what they name,
// leaders through nothing, apart), faint ones in the middle of a fade too.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "app/animation.hpp"
#include "arrow_form_checks.hpp"
#include "label_clearance_checks.hpp"
#include "legend_checks.hpp"
#include "render/frame_layout.hpp"
#include "render/text/text_metrics.hpp"
#include "scene/scene_desc.hpp"
#include "scene/scene_io.hpp"
#include "video_frame_checks.hpp"

namespace collide {
namespace {

constexpr int kFps = 60;
constexpr std::size_t kShownPerRule = 3;

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

// The frames walked: every frame of the video.
std::vector<int> framesWalked(const compose::FrameSource& source) {
  const int last = static_cast<int>(source.duration_s() * kFps);
  std::vector<int> frames;
  for (int k = 0; k <= last; ++k) frames.push_back(k);
  return frames;
}

// What broke, by rule, in the order found.
using Breaches = std::map<std::string, std::vector<std::string>>;

void note(Breaches& breaches, const std::string& rule, std::vector<std::string> found) {
  std::vector<std::string>& list = breaches[rule];
  list.insert(list.end(), found.begin(), found.end());
}

void compareFrames(const test::FrameItems& was, const test::FrameItems& now,
                   const std::vector<double>& events, Breaches& breaches) {
  const bool across_event = eventBetween(events, was.t_s, now.t_s);
  const bool after_event = eventBetween(events, now.t_s - test::kEventSpan_s, now.t_s);
  const bool near_event = across_event || after_event;
  const double limit_px = near_event ? test::kEventPx : test::kCalmPx;
  const std::string suffix = near_event ? " jump near an event" : " jump";
  note(breaches, "labels" + suffix,
       test::textsThatJump(was, now, limit_px, test::TextsOf::kBodies));
  note(breaches, "readouts" + suffix,
       test::textsThatJump(was, now, limit_px, test::TextsOf::kFrame));
  if (!across_event) note(breaches, "re-wraps", test::textsThatRewrap(was, now));
  note(breaches, "texts fade too fast", test::textsThatFadeTooFast(was, now));
}

Breaches checkVideo(const std::string& preset, int width_px, int height_px) {
  const app::Animation animation = app::animate(scene::loadPreset(preset), {width_px, height_px});
  const compose::FrameSource& source = animation.frames;
  const std::vector<double> events = eventTimes(source);
  render::TextMetrics metrics;
  Breaches breaches;
  test::FrameItems before;
  frame::FrameModel before_model;
  int before_k = -2;
  test::ArrowFormWatch forms;
  for (const int k : framesWalked(source)) {
    const double playback_s = static_cast<double>(k) / kFps;
    const double t_s =
        std::clamp(source.simulatedAt(playback_s), 0.0, source.simulatedDuration_s());
    frame::FrameModel model = source.frameAt(playback_s);
    const std::vector<frame::DrawnItem> items = render::drawnItems(model, width_px, height_px);
    const std::string at = " at t = " + std::to_string(t_s) + " s";
    {
      SCOPED_TRACE(preset + at);
      compose_test::expectFrameClear(model, width_px, height_px, 0.0, metrics, true);
    }
    if (std::string tangled = test::tangledLeader(items); !tangled.empty()) {
      note(breaches, "legend leaders tangle", {tangled + at});
    }
    if (std::string through = test::arrowThroughSomething(items); !through.empty()) {
      note(breaches, "arrow through", {through + at});
    }
    if (std::string off = test::arrowOffItsValue(items); !off.empty()) {
      note(breaches, "arrow off its value", {off + at});
    }
    forms.add(t_s, test::arrowFormsAt(model, items),
              k != before_k + 1 || eventBetween(events, before.t_s, t_s));
    test::FrameItems now = test::frameItems(t_s, items);
    if (k == before_k + 1) {
      compareFrames(before, now, events, breaches);
      if (!eventBetween(events, before.t_s, now.t_s)) {
        for (const std::string& found : test::entriesThatComeAndGo(before_model, model)) {
          note(breaches, "legend entries come and go", {found + at});
        }
      }
    }
    before = std::move(now);
    before_model = std::move(model);
    before_k = k;
  }
  note(breaches, "arrow form flickers", forms.finish());
  return breaches;
}

// The rules a preset is known to break at a size (none now): the test fails where a preset
// breaks a rule not listed for it, and where it keeps one listed (take it off the list).
using Known = std::map<std::string, std::set<std::string>>;  // by "preset WxH"
const Known& knownBreaches() {
  static const Known known = {};
  return known;
}

void expectOnlyKnown(const Breaches& breaches, const std::string& where) {
  const auto listed = knownBreaches().find(where);
  const std::set<std::string> known =
      listed != knownBreaches().end() ? listed->second : std::set<std::string>{};
  for (const auto& [rule, found] : breaches) {
    if (found.empty() || known.count(rule) > 0) continue;
    for (std::size_t i = 0; i < found.size() && i < kShownPerRule; ++i) {
      ADD_FAILURE() << where << ": " << rule << ": " << found[i];
    }
    if (found.size() > kShownPerRule) {
      ADD_FAILURE() << where << ": " << rule << ": " << found.size() - kShownPerRule << " more";
    }
  }
  for (const std::string& rule : known) {
    const auto found = breaches.find(rule);
    if (found == breaches.end() || found->second.empty()) {
      ADD_FAILURE() << where << " keeps \"" << rule << "\" now: take it off knownBreaches()";
    }
  }
}

class VideoFramesTest : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(VideoFramesTest, TextsHoldStillAndArrowsTellTheTruth) {
  const auto [width_px, height_px] = GetParam();
  for (const scene::PresetInfo& preset : scene::presetList()) {
    expectOnlyKnown(checkVideo(preset.name, width_px, height_px),
                    preset.name + " " + std::to_string(width_px) + "x" + std::to_string(height_px));
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
