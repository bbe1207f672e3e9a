// Velocity arrows in 1D pictures, checked on the frame description (no pixels read): the arrows of
// two bodies never cross (approaching bodies' arrows point into the same gap; one is lifted into
// a row above), and every arrow lies whole inside its panel's scene (the camera fits the arrow
// tips, not only the bodies). Every 1D preset, at 24 instants and just before and after its first
// collision, at 1280x720 and 640x360. Arrow geometry is recomputed here from the FrameModel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "compose/label_candidates.hpp"
#include "frame/layout.hpp"
#include "frame_layouts.hpp"
#include "render/text/text_metrics.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

struct Rect {
  double x0, y0, x1, y1;
};

bool intersects(const Rect& a, const Rect& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

// Written with a stream: GCC 12 warns (-Wrestrict, a known false positive) on "[" + std::string&&.
std::string describe(const Rect& r) {
  std::ostringstream text;
  text << '[' << int(r.x0) << ',' << int(r.y0) << "]-[" << int(r.x1) << ',' << int(r.y1) << ']';
  return text.str();
}

// The box each moving body's arrow covers: from its tail above the body to its tip, one
// arrowhead wide. One that would reach the face of a wall it moves towards is drawn back, whole,
// its tip a gap short of the face.
std::vector<Rect> arrowBoxes(const frame::PanelModel& panel, const frame::PanelLayout& where,
                             const frame::FrameLayout& layout) {
  const frame::WorldToPixel to_px = frame::panelMapping(panel, where, layout);
  std::vector<Rect> boxes;
  for (const frame::BodyModel& body : panel.bodies) {
    const double speed = std::abs(body.velocity_mps.x());
    if (speed <= 1e-6 || panel.arrow_m_per_mps <= 0.0 || body.moves_with >= 0) continue;
    const core::Vec2 c = to_px.toPixel(body.center_m);
    const double top = c.y() - to_px.px_per_m * body.half_extent_m.y();
    double length = speed * panel.arrow_m_per_mps * to_px.px_per_m;
    if (panel.arrow_max_length_m > 0.0) {
      length = std::min(length, panel.arrow_max_length_m * to_px.px_per_m);
    }
    length = std::max(length, 1.0 * layout.arrow_head_length_px);  // the painter's minimum
    // Row 0 just above the body; a lifted row above the tallest body's row-0 line.
    double highest = top;
    for (const frame::BodyModel& other : panel.bodies) {
      highest = std::min(
          highest, to_px.toPixel(other.center_m).y() - to_px.px_per_m * other.half_extent_m.y());
    }
    const double row_height = layout.arrow_head_width_px + layout.gap_px;
    const double y = body.arrow_row == 0
                         ? top - layout.arrow_gap_px
                         : highest - layout.arrow_gap_px - body.arrow_row * row_height;
    const double dir = body.velocity_mps.x() > 0.0 ? 1.0 : -1.0;
    double room = INFINITY;
    for (const frame::WallModel& wall : panel.walls) {
      const double ahead = (to_px.toPixel(wall.point_m).x() - c.x()) * dir;
      if (wall.normal.x() * dir < 0.0 && ahead >= 0.0) room = std::min(room, ahead - layout.gap_px);
    }
    const double tail = c.x() - dir * std::max(0.0, length - room);
    const double tip = tail + dir * length;
    const double half = 0.5 * layout.arrow_head_width_px;
    boxes.push_back({std::min(tail, tip), y - half, std::max(tail, tip), y + half});
  }
  return boxes;
}

// 25 instants evenly over the run, and a millisecond either side of each of its first
// `collisions_around` collisions.
std::vector<double> instantsToCheck(const compose::FrameSource& source,
                                    std::size_t collisions_around) {
  const double end = source.simulatedDuration_s();
  std::vector<double> instants;
  for (int k = 0; k <= 24; ++k) instants.push_back(end * k / 24.0);
  const auto& hits = source.timeline().collisions();
  for (std::size_t c = 0; c < hits.size() && c < collisions_around; ++c) {
    instants.insert(instants.end(),
                    {std::max(0.0, hits[c].time_s - 1e-3), std::min(end, hits[c].time_s + 1e-3)});
  }
  return instants;
}

class ArrowLayoutTest : public ::testing::TestWithParam<test::PictureSize> {};

// Calls check(frame, layout) on every 1D preset's frame at instantsToCheck(source,
// collisions_around), at width_px x height_px, with the preset and instant traced.
template <typename Check>
void checkEvery1DFrame(int width_px, int height_px, std::size_t collisions_around,
                       const Check& check) {
  render::TextMetrics metrics;
  for (const scene::PresetInfo& preset : scene::presetList()) {
    const scene::SceneDesc scene = scene::loadPreset(preset.name);
    if (scene.dimensions != 1) continue;
    const app::Animation animation = app::animate(scene, {width_px, height_px});
    const compose::FrameSource& source = animation.frames;
    for (double t : instantsToCheck(source, collisions_around)) {
      SCOPED_TRACE(preset.name + " at t = " + std::to_string(t) + " s, " +
                   std::to_string(width_px) + "x" + std::to_string(height_px));
      const frame::FrameModel frame = source.frameAtSimulated(t);
      check(frame, test::layoutMeasured(frame, width_px, height_px, metrics));
    }
  }
}

TEST_P(ArrowLayoutTest, ArrowsNeverCrossAndStayInTheScene) {
  const auto [width_px, height_px] = GetParam();
  checkEvery1DFrame(
      width_px, height_px, 1, [](const frame::FrameModel& frame, const frame::FrameLayout& layout) {
        for (std::size_t p = 0; p < frame.panels.size(); ++p) {
          const frame::PixelRect& clip = layout.panels[p].world_clip;
          const std::vector<Rect> boxes = arrowBoxes(frame.panels[p], layout.panels[p], layout);
          for (std::size_t a = 0; a < boxes.size(); ++a) {
            // Half a pixel: the arrowhead's anti-aliased edge.
            EXPECT_TRUE(boxes[a].x0 >= clip.x0 - 0.5 && boxes[a].x1 <= clip.x1 + 0.5 &&
                        boxes[a].y0 >= clip.y0 - 0.5)
                << "arrow " << describe(boxes[a]) << " leaves the scene "
                << describe({clip.x0, clip.y0, clip.x1, clip.y1});
            for (std::size_t b = a + 1; b < boxes.size(); ++b) {
              EXPECT_FALSE(intersects(boxes[a], boxes[b]))
                  << "arrows " << describe(boxes[a]) << " and " << describe(boxes[b]) << " cross";
            }
          }
        }
      });
}

// An arrow never hides a body and never strikes through a wall: in 1D pictures no arrow, as the
// painter draws it (frame::bodyArrowShape, frame::bodyArrowTailPx), passes over or under
// another body (the bullet's off-scale arrow over the block it flies at: it goes up into a row
// above every body) nor reaches past the face of a wall it moves towards (pi-blocks' blocks
// heading for the wall: drawn back from it, whole). Every 1D preset at 24 instants and around its
// collisions, at 1280x720 and 640x360.
TEST_P(ArrowLayoutTest, ArrowsNeitherCrossABodyNorAWall) {
  const auto [width_px, height_px] = GetParam();
  checkEvery1DFrame(
      width_px, height_px, 8, [](const frame::FrameModel& frame, const frame::FrameLayout& layout) {
        for (std::size_t p = 0; p < frame.panels.size(); ++p) {
          const frame::PanelModel& panel = frame.panels[p];
          const frame::WorldToPixel to_px = frame::panelMapping(panel, layout.panels[p], layout);
          for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
            const frame::BodyModel& body = panel.bodies[i];
            const double speed = std::abs(body.velocity_mps.x());
            if (speed <= 1e-6 || panel.arrow_m_per_mps <= 0.0 || body.moves_with >= 0) continue;
            const frame::ArrowShape shape = frame::bodyArrowShape(body, panel, layout, to_px);
            const core::Vec2 tail = frame::bodyArrowTailPx(body, panel, layout, to_px, shape);
            const double tip =
                tail.x() + (body.velocity_mps.x() > 0.0 ? 1.0 : -1.0) * shape.length_px;
            const double half = 0.5 * shape.head_width_px;
            const Rect a{std::min(tail.x(), tip), tail.y() - half, std::max(tail.x(), tip),
                         tail.y() + half};
            for (std::size_t k = 0; k < panel.bodies.size(); ++k) {
              const frame::BodyModel& other = panel.bodies[k];
              // Its own body, and a body riding on it (a bullet in its block), it speaks for.
              if (k == i || other.moves_with == static_cast<int>(i)) continue;
              const core::Vec2 c = to_px.toPixel(other.center_m);
              const core::Vec2 extent = to_px.px_per_m * other.half_extent_m;
              const Rect outline{c.x() - extent.x(), c.y() - extent.y(), c.x() + extent.x(),
                                 c.y() + extent.y()};
              EXPECT_FALSE(intersects(a, outline))
                  << "the arrow of body " << i + 1 << " " << describe(a) << " crosses body "
                  << k + 1 << " " << describe(outline);
            }
            for (const frame::WallModel& wall : panel.walls) {
              // The wall's face; its line and hatching are drawn on the solid side beyond it.
              const double face = to_px.toPixel(wall.point_m).x();
              const bool through = wall.normal.x() > 0.0 ? a.x0 < face : a.x1 > face;
              EXPECT_FALSE(through) << "the arrow of body " << i + 1 << " " << describe(a)
                                    << " reaches through the wall at x = " << face << " px";
            }
          }
        }
      });
}

// A readout with no room over the arrows may stand on its arrow's line beyond the tip: beyond the
// tip the painter draws, also where the arrow is drawn back from a wall ahead (pi-blocks' small
// block heading for the wall: its tip a gap short of the wall, its tail behind the block), never
// on the arrow nor beyond the wall. Checked on the candidate places compose tries.
TEST(ArrowLayoutTest, AReadoutBeyondTheTipStandsBeyondTheDrawnTip) {
  constexpr int kWidth = 1280, kHeight = 720;
  render::TextMetrics metrics;
  const app::Animation animation = app::animate(scene::loadPreset("pi-blocks"), {kWidth, kHeight});
  const compose::FrameSource& source = animation.frames;
  int drawn_back = 0;
  for (double t : instantsToCheck(source, 8)) {
    const frame::FrameModel frame = source.frameAtSimulated(t);
    const frame::FrameLayout layout = test::layoutMeasured(frame, kWidth, kHeight, metrics);
    const frame::PanelModel& panel = frame.panels.front();
    const frame::WorldToPixel to_px = frame::panelMapping(panel, layout.panel(), layout);
    const frame::PixelRect& clip = layout.panel().world_clip;
    compose::LabelScene scene{
        compose::Obstacles({clip.x0, clip.y0, clip.x1, clip.y1}, 0, 0, 0), {}, {}};
    for (const frame::BodyModel& body : panel.bodies) {
      const core::Vec2 c = to_px.toPixel(body.center_m);
      const core::Vec2 half = to_px.px_per_m * body.half_extent_m;
      scene.obstacles.addBody(
          {false, {c.x() - half.x(), c.y() - half.y(), c.x() + half.x(), c.y() + half.y()}});
    }
    for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
      const frame::BodyModel& body = panel.bodies[i];
      if (std::abs(body.velocity_mps.x()) <= 1e-6 || body.moves_with >= 0) continue;
      const frame::ArrowShape shape = frame::bodyArrowShape(body, panel, layout, to_px);
      if (!(shape.tail_back_px > 0.0)) continue;
      ++drawn_back;
      SCOPED_TRACE("body " + std::to_string(i + 1) + " at t = " + std::to_string(t) + " s");
      const double direction = body.velocity_mps.x() > 0.0 ? 1.0 : -1.0;
      const core::Vec2 tail = frame::bodyArrowTailPx(body, panel, layout, to_px, shape);
      const double tip = tail.x() + direction * shape.length_px;
      std::string text = "v = 1.00 m/s";
      compose::Label label{i, true, &text, {metrics.width(text, layout.text_px), 30.0}, {}, {}, {}};
      compose::addCandidates(label, panel, scene, layout, to_px);
      // The candidate centred on the arrow's line, ahead of the arrow.
      bool found = false;
      for (const compose::Box& box : label.candidates) {
        if (std::abs(box.center().y() - tail.y()) > 0.5) continue;
        const double near_edge = direction > 0.0 ? box.x0 : box.x1;
        if ((near_edge - tail.x()) * direction <= 0.0) continue;
        found = true;
        const double clear = 0.5 * layout.arrow_head_width_px + layout.gap_px;
        EXPECT_NEAR((near_edge - tip) * direction, clear, 0.5)
            << "its readout's place beyond the tip starts " << (near_edge - tip) * direction
            << " px past the drawn tip, not " << clear << " px";
      }
      EXPECT_TRUE(found) << "no place on the arrow's line beyond its tip";
    }
  }
  EXPECT_GT(drawn_back, 0) << "no arrow drawn back from the wall at the instants checked";
}

INSTANTIATE_TEST_SUITE_P(Sizes, ArrowLayoutTest, test::videoSizes(), test::sizeName);

}  // namespace
}  // namespace collide
