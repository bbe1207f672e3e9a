// SPDX-License-Identifier: MIT
// Velocity arrows that read as their bodies' and as their speeds (issue 37 item 3), checked as
// the painters lay them out (render::drawnItems, `collide layout`'s items; no GL, no pixels):
// - an arrow drawn beside its body, where straight on has no room, stands near the body, no
//   label between them: stick-2d at 4 s drew ball 1's arrow with its tail 46 px off the ball
//   (1280x720), farther than a line of text; one drawn back from what stops it runs past the
//   ball as near;
// - "below scale" marks only an arrow whose true length would not read (shorter than a head),
//   and one that reads is drawn on its scale: newtons-cradle at 1.333 s marked ball 1's
//   0.52 m/s (55 px at 1280x720) "below scale", as less than a head of it stood beyond the ball;
// - a moving ball with room around it keeps its arrow by a cushion: billiards-break's pink ball
//   had none at 0.217-0.233 s;
// - an arrow nearing what stops it changes its form once: billiards-break's cue ball was drawn
//   with a break for one frame (0.117 s) before it went beside the ball.
// Each check lays out a few dozen frames per size (about a second in all).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "frame/layout.hpp"
#include "frame_layouts.hpp"
#include "render/frame_layout.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

class ArrowReadingTest : public ::testing::TestWithParam<test::PictureSize> {};

core::Vec2 middle(const frame::PixelRect& box) {
  return {0.5 * (box.x0 + box.x1), 0.5 * (box.y0 + box.y1)};
}

// The item of `kind` for body `body`, or null.
const frame::DrawnItem* itemOf(const std::vector<frame::DrawnItem>& items, const std::string& kind,
                               int body) {
  for (const frame::DrawnItem& item : items) {
    if (item.kind == kind && item.body == body) return &item;
  }
  return nullptr;
}

// Whether the segment ab passes through `box` (sampled every half pixel).
bool segmentThroughBox(const core::Vec2& a, const core::Vec2& b, const frame::PixelRect& box) {
  const int samples = std::max(2, static_cast<int>(2.0 * (b - a).norm()));
  for (int k = 0; k <= samples; ++k) {
    const core::Vec2 p = a + (b - a) * (static_cast<double>(k) / samples);
    if (p.x() > box.x0 && p.x() < box.x1 && p.y() > box.y0 && p.y() < box.y1) return true;
  }
  return false;
}

// The frames of `preset` every `step_s` of playback, laid out at the test's size.
std::vector<std::vector<frame::DrawnItem>> framesOf(const std::string& preset, double step_s,
                                                    int width_px, int height_px) {
  const app::Animation animation = app::animate(scene::loadPreset(preset), {width_px, height_px});
  std::vector<std::vector<frame::DrawnItem>> frames;
  for (double playback_s = 0.0; playback_s <= animation.frames.duration_s(); playback_s += step_s) {
    frames.push_back(render::drawnItems(animation.frames.frameAt(playback_s), width_px, height_px));
  }
  return frames;
}

// The point of segment ab nearest to p, as its share of the way from a to b (0 to 1).
double nearestShare(const core::Vec2& a, const core::Vec2& b, const core::Vec2& p) {
  const core::Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  return length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
}

// Beside its body, an arrow's line stands nearer the ball than a line of label text (the
// layout's text size at its line spacing), so it reads as that ball's and no label fits between
// them; nothing written stands between the arrow and the ball. Its nearest point to the ball is
// its tail, or, drawn back from what stops it, a point of its shaft beside the ball's centre,
// never its tip: the arrow runs past the ball, not behind it. The balls of stick-2d and
// newtons-cradle are disks: each is the circle its box holds.
TEST_P(ArrowReadingTest, AnArrowBesideItsBodyStandsNearIt) {
  const auto [width_px, height_px] = GetParam();
  const double line_px =
      frame::kLineSpacing * frame::computeFrameLayout(width_px, height_px).text_px;
  int beside = 0;
  for (const std::string preset : {"stick-2d", "newtons-cradle"}) {
    for (const std::vector<frame::DrawnItem>& items : framesOf(preset, 0.1, width_px, height_px)) {
      for (const frame::DrawnItem& arrow : items) {
        if (arrow.kind != "arrow" || !arrow.arrow || arrow.body < 0) continue;
        const frame::DrawnItem* body = itemOf(items, "body", arrow.body);
        ASSERT_NE(body, nullptr);
        const core::Vec2 centre = middle(body->box);
        const double radius = 0.5 * (body->box.x1 - body->box.x0);
        const core::Vec2 tail = arrow.arrow->from_px, tip = arrow.arrow->to_px;
        const double share = nearestShare(tail, tip, centre);
        const core::Vec2 nearest = tail + share * (tip - tail);
        const double off_px = (nearest - centre).norm() - radius;
        if (off_px <= 1.0) continue;  // from the centre or the edge
        ++beside;
        SCOPED_TRACE(preset + ": " + arrow.id + " from (" + std::to_string(tail.x()) + ", " +
                     std::to_string(tail.y()) + "), " + std::to_string(off_px) + " px off");
        EXPECT_LT(off_px, line_px) << "the arrow stands off the ball";
        EXPECT_LT(share, 1.0) << "the arrow ends behind the ball";
        const core::Vec2 edge = centre + radius * (nearest - centre).normalized();
        for (const frame::DrawnItem& text : items) {
          if (text.kind != "label" && text.kind != "readout" && text.kind != "legend") continue;
          EXPECT_FALSE(segmentThroughBox(nearest, edge, text.box)) << text.id << " stands between";
        }
      }
    }
  }
  EXPECT_GT(beside, 3) << "arrows beside their bodies were checked";
}

// newtons-cradle at 1.333 s (ball 1 swinging back at 0.52 m/s), and the frames of stick-2d and
// newtons-cradle every 0.1 s: an arrow is marked "below scale" only where its true length (its
// value at its scale) is shorter than a head, the least that reads as an arrow; one at least a
// head long is drawn on its scale, its length its value's within 2 px.
TEST_P(ArrowReadingTest, BelowScaleOnlyWhereTheTrueLengthWouldNotRead) {
  const auto [width_px, height_px] = GetParam();
  const double head_px = frame::computeFrameLayout(width_px, height_px).arrow_head_length_px;
  const app::Animation cradle =
      app::animate(scene::loadPreset("newtons-cradle"), {width_px, height_px});
  const std::vector<frame::DrawnItem> at_swing =
      render::drawnItems(cradle.frames.frameAtSimulated(1.333), width_px, height_px);
  const frame::DrawnItem* swing = itemOf(at_swing, "arrow", 0);
  ASSERT_NE(swing, nullptr) << "ball 1's velocity is not shown";
  const double swing_px = swing->arrow->value_mps * swing->arrow->scale_px_per_mps;
  ASSERT_GT(swing_px, head_px) << "its true length reads";
  EXPECT_EQ(swing->arrow->drawn, frame::ArrowDrawn::kOnScale);
  EXPECT_NEAR((swing->arrow->to_px - swing->arrow->from_px).norm(), swing_px, 2.0);
  int marked = 0, read = 0;
  for (const std::string preset : {"stick-2d", "newtons-cradle"}) {
    for (const std::vector<frame::DrawnItem>& items : framesOf(preset, 0.1, width_px, height_px)) {
      for (const frame::DrawnItem& arrow : items) {
        if (arrow.kind != "arrow" || !arrow.arrow || arrow.body < 0) continue;
        const double true_px = arrow.arrow->value_mps * arrow.arrow->scale_px_per_mps;
        SCOPED_TRACE(preset + ": " + arrow.id + ", " + std::to_string(true_px) + " px");
        if (true_px < head_px) {
          EXPECT_EQ(arrow.arrow->drawn, frame::ArrowDrawn::kBelowScale);
          ++marked;
          continue;
        }
        EXPECT_NE(arrow.arrow->drawn, frame::ArrowDrawn::kBelowScale);
        if (arrow.arrow->drawn != frame::ArrowDrawn::kOnScale) continue;
        EXPECT_NEAR((arrow.arrow->to_px - arrow.arrow->from_px).norm(), true_px, 2.0);
        ++read;
      }
    }
  }
  EXPECT_GT(read, 10);
  std::printf("arrows marked below scale: %d, drawn on scale: %d\n", marked, read);
}

// The gap between two drawn boxes, pixels (0 where they touch or overlap).
double boxGapPx(const frame::PixelRect& a, const frame::PixelRect& b) {
  const double dx = std::max({b.x0 - a.x1, a.x0 - b.x1, 0.0});
  const double dy = std::max({b.y0 - a.y1, a.y0 - b.y1, 0.0});
  return std::hypot(dx, dy);
}

// billiards-break from its last impact in the rack (0.191 s) through the pink ball's bounces off
// the right cushion (0.234 s) and the bottom one (0.324 s), every 1/240 s: every moving ball with
// room around it (its box a head length and a gap clear of every other ball's) has its arrow. The
// pink ball, running at 5.8 m/s into the right cushion, had none at 0.217-0.233 s (1280x720): too
// long for the room before the cushion, and beside it only where it fitted from beside its centre
// on; it is drawn beside it, back from the cushion, whole and on its scale.
TEST_P(ArrowReadingTest, AMovingBallWithRoomKeepsItsArrowByACushion) {
  const auto [width_px, height_px] = GetParam();
  const frame::FrameLayout layout = frame::computeFrameLayout(width_px, height_px);
  const double room_px = layout.arrow_head_length_px + layout.gap_px;
  const app::Animation breaking =
      app::animate(scene::loadPreset("billiards-break"), {width_px, height_px});
  int checked = 0;
  for (int k = 0; k <= 32; ++k) {
    const double t_s = 0.192 + k / 240.0;
    const frame::FrameModel model = breaking.frames.frameAtSimulated(t_s);
    const std::vector<frame::DrawnItem> items = render::drawnItems(model, width_px, height_px);
    const std::vector<frame::BodyModel>& bodies = model.panels.front().bodies;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (!(bodies[i].velocity_mps.norm() > 0.0)) continue;
      const frame::DrawnItem* body = itemOf(items, "body", static_cast<int>(i));
      ASSERT_NE(body, nullptr);
      double clear_px = std::numeric_limits<double>::infinity();
      for (const frame::DrawnItem& other : items) {
        if (other.kind == "body" && other.body != body->body)
          clear_px = std::min(clear_px, boxGapPx(body->box, other.box));
      }
      if (clear_px < room_px) continue;
      ++checked;
      EXPECT_NE(itemOf(items, "arrow", static_cast<int>(i)), nullptr)
          << "t = " << t_s << " s: ball " << i << " moves at " << bodies[i].velocity_mps.norm()
          << " m/s, " << clear_px << " px clear of the others, and has no arrow";
    }
  }
  EXPECT_GT(checked, 30) << "balls with room were checked";
}

// How an arrow is drawn, as a reader tells it apart: straight on from its ball (from the centre
// or the edge), straight on with a break, or beside the ball (its line off the ball's outline).
enum class Form { kStraight, kBreak, kBeside };

Form formOf(const frame::DrawnItem& arrow, const frame::DrawnItem& body) {
  const core::Vec2 centre = middle(body.box);
  const double radius = 0.5 * (body.box.x1 - body.box.x0);
  const core::Vec2 tail = arrow.arrow->from_px, tip = arrow.arrow->to_px;
  const core::Vec2 nearest = tail + nearestShare(tail, tip, centre) * (tip - tail);
  if ((nearest - centre).norm() - radius > 1.0) return Form::kBeside;
  return arrow.arrow->drawn == frame::ArrowDrawn::kOffScale ? Form::kBreak : Form::kStraight;
}

// Every frame at 60 fps before their first impacts, billiards-break's cue ball (running into the
// rack) and newtons-cradle's ball 1 (swinging into the row): where the arrow on its scale loses
// its room straight on, it goes beside its ball at once, and stays there to the impact: one
// change of form, never a break for a frame or two between (the cue ball's at 0.117 s, ball 1's
// at 0.267-0.283 s). Frames where the arrow is below its scale or not drawn do not count.
TEST_P(ArrowReadingTest, AnArrowNearingWhatStopsItChangesItsFormOnce) {
  const auto [width_px, height_px] = GetParam();
  for (const std::string preset : {"billiards-break", "newtons-cradle"}) {
    const app::Animation animation = app::animate(scene::loadPreset(preset), {width_px, height_px});
    const double impact_s = animation.frames.timeline().collisions().front().time_s;
    std::vector<Form> forms;
    for (int k = 0; animation.frames.simulatedAt(k / 60.0) < impact_s; ++k) {
      const std::vector<frame::DrawnItem> items =
          render::drawnItems(animation.frames.frameAt(k / 60.0), width_px, height_px);
      const frame::DrawnItem* arrow = itemOf(items, "arrow", 0);
      const frame::DrawnItem* body = itemOf(items, "body", 0);
      ASSERT_NE(body, nullptr);
      if (arrow == nullptr || !arrow->arrow ||
          arrow->arrow->drawn == frame::ArrowDrawn::kBelowScale) {
        continue;
      }
      const Form form = formOf(*arrow, *body);
      if (forms.empty() || forms.back() != form) forms.push_back(form);
    }
    SCOPED_TRACE(preset + ": ball 1's arrow before its impact");
    EXPECT_EQ(forms, (std::vector<Form>{Form::kStraight, Form::kBeside}))
        << forms.size() << " forms in turn";
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, ArrowReadingTest, test::videoSizes(), test::sizeName);

}  // namespace
}  // namespace collide
