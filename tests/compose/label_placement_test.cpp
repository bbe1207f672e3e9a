// Label placement and framing, checked on the frame description (no pixels read): every preset at
// five instants (start, just before and just after the first collision, middle, end) and its
// strobe, at 1280x720 and 640x360, also with every label 40 % longer (translations often are),
// and as a figure printed 8 cm wide at 300 dpi.
// The geometry of bodies and arrows is recomputed here from the FrameModel and render's layout,
// independently of compose's own obstacle list.
#include "compose/label_placement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "render/layout.hpp"
#include "render/text_metrics.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

struct Box {
  double x0, y0, x1, y1;
};

struct Size {
  int width_px, height_px;
  double text_floor_px = 0.0;  // a printed figure's (render::printTextFloorPx)
};

bool intersects(const Box& a, const Box& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

double pointToBox(const core::Vec2& p, const Box& box) {
  const double dx = std::max({box.x0 - p.x(), 0.0, p.x() - box.x1});
  const double dy = std::max({box.y0 - p.y(), 0.0, p.y() - box.y1});
  return std::hypot(dx, dy);
}

// Distance from a segment to a box, by dense sampling (slow but obviously right).
double segmentToBox(const core::Vec2& a, const core::Vec2& b, const Box& box) {
  const int steps = std::max(1, static_cast<int>((b - a).norm() / 0.25));
  double best = INFINITY;
  for (int i = 0; i <= steps; ++i)
    best = std::min(best, pointToBox(a + (b - a) * (double(i) / steps), box));
  return best;
}

// A body in pixels: its outline's distance to a box (0 when they touch or overlap).
struct PixelBody {
  bool disk;
  core::Vec2 center;
  core::Vec2 half;
  double distanceTo(const Box& box) const {
    if (disk) return std::max(0.0, pointToBox(center, box) - half.x());
    const Box own{center.x() - half.x(), center.y() - half.y(), center.x() + half.x(),
                  center.y() + half.y()};
    const double dx = std::max({own.x0 - box.x1, 0.0, box.x0 - own.x1});
    const double dy = std::max({own.y0 - box.y1, 0.0, box.y0 - own.y1});
    return std::hypot(dx, dy);
  }
};

struct Arrow {
  core::Vec2 tail, tip;
  double half_width;
};

std::string lengthened(const std::string& text) {
  if (text.empty()) return text;
  const std::size_t extra = (text.size() * 4 + 9) / 10;  // bytes: at least 40 % more characters
  return text + std::string(extra, 'x');
}

// Checks one frame; `where` names it in failures.
void checkFrame(const render::FrameModel& frame, Size size, render::TextMetrics& metrics,
                const std::string& where) {
  SCOPED_TRACE(where);
  const render::FrameLayout layout = render::layoutFrame(
      frame, size.width_px, size.height_px, size.text_floor_px,
      [&metrics](std::string_view text, double px) { return metrics.width(text, px); });
  std::vector<Box> texts;
  for (std::size_t p = 0; p < frame.panels.size(); ++p) {
    const render::PanelModel& panel = frame.panels[p];
    ASSERT_EQ(panel.placed_for_width_px, size.width_px);
    ASSERT_EQ(panel.placed_for_height_px, size.height_px);
    ASSERT_EQ(panel.placed_for_scale_px, layout.scale_px);
    const render::WorldToPixel to_px = render::panelMapping(panel, layout.panels[p], layout);
    std::vector<PixelBody> bodies;
    std::vector<Arrow> arrows;
    for (const render::BodyModel& body : panel.bodies) {
      const core::Vec2 c = to_px.toPixel(body.center_m);
      const double hx = to_px.px_per_m * body.half_extent_m.x();
      const bool disk = body.shape == render::BodyShape::kDisk;
      const double hy = disk ? hx : to_px.px_per_m * body.half_extent_m.y();
      bodies.push_back({disk, c, {hx, hy}});
      const double speed = body.velocity_mps.norm();
      if (speed > 1e-6 && panel.arrow_m_per_mps > 0.0 && body.moves_with < 0) {
        const core::Vec2 d{body.velocity_mps.x() / speed, -body.velocity_mps.y() / speed};
        // 1D: above the body; a lifted arrow (arrow_row r) r rows of a head's width and a gap
        // above the tallest body's arrow line.
        double line_y = c.y() - hy - layout.arrow_gap_px;
        if (body.arrow_row > 0) {
          for (const render::BodyModel& other : panel.bodies) {
            line_y = std::min(line_y, to_px.toPixel(other.center_m).y() -
                                          to_px.px_per_m * other.half_extent_m.y() -
                                          layout.arrow_gap_px);
          }
          line_y -= body.arrow_row * (layout.arrow_head_width_px + layout.gap_px);
        }
        const core::Vec2 tail = panel.two_d ? c : core::Vec2{c.x(), line_y};
        // To scale, but never shorter than the painter's minimum (0.4 head lengths) nor longer than
        // the panel's off-scale limit.
        const double length = std::clamp(
            speed * panel.arrow_m_per_mps * to_px.px_per_m, 0.4 * layout.arrow_head_length_px,
            panel.arrow_max_length_m > 0.0 ? std::max(panel.arrow_max_length_m * to_px.px_per_m,
                                                      0.4 * layout.arrow_head_length_px)
                                           : INFINITY);
        arrows.push_back({tail, tail + length * d, 0.5 * layout.arrow_head_width_px});
      }
    }
    for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
      const render::BodyModel& body = panel.bodies[i];
      for (const auto& [text, at] : {std::pair{&body.label, &body.label_at},
                                     std::pair{&body.velocity_label, &body.velocity_label_at}}) {
        if (text->empty()) continue;
        SCOPED_TRACE(*text);
        ASSERT_TRUE(at->has_value()) << "a label without a place";
        const render::PlacedText& placed = **at;
        const Box box{placed.top_left_px.x(), placed.top_left_px.y(),
                      placed.top_left_px.x() + placed.size_px.x(),
                      placed.top_left_px.y() + placed.size_px.y()};
        // The box is the text's real extent.
        EXPECT_NEAR(placed.size_px.x(), metrics.width(*text, layout.text_px), 0.5);
        EXPECT_NEAR(placed.size_px.y(),
                    metrics.ascender(layout.text_px) + metrics.descender(layout.text_px), 0.5);
        EXPECT_TRUE(box.x0 >= 0 && box.y0 >= 0 && box.x1 <= size.width_px &&
                    box.y1 <= size.height_px)
            << "outside the frame";
        const double own = bodies[i].distanceTo(box);
        for (std::size_t k = 0; k < bodies.size(); ++k) {
          const double d = bodies[k].distanceTo(box);
          EXPECT_GT(d, 0.0) << "covers body " << k + 1;
          // A body riding on this one (a bullet in its block) is drawn and labelled as part of it.
          const bool rider = panel.bodies[k].moves_with == static_cast<int>(i);
          if (k != i && !rider) {
            EXPECT_LT(own, d) << "nearer body " << k + 1 << " than its own";
          }
        }
        for (const Arrow& arrow : arrows) {
          EXPECT_GT(segmentToBox(arrow.tail, arrow.tip, box), arrow.half_width)
              << "covers an arrow";
        }
        texts.push_back(box);
      }
    }
  }
  for (std::size_t a = 0; a < texts.size(); ++a) {
    for (std::size_t b = a + 1; b < texts.size(); ++b) {
      EXPECT_FALSE(intersects(texts[a], texts[b])) << "two labels overlap";
    }
  }
}

void checkPreset(const scene::PresetInfo& preset, Size size, bool longer) {
  const scene::SceneDesc scene = scene::loadPreset(preset.name);
  const app::Animation animation =
      app::animate(scene, {size.width_px, size.height_px, size.text_floor_px});
  const compose::FrameSource& source = animation.frames;
  render::TextMetrics metrics;
  const double end = source.simulatedDuration_s();
  const double first = source.timeline().collisions().empty()
                           ? 0.5 * end
                           : source.timeline().collisions().front().time_s;
  std::vector<std::pair<std::string, render::FrameModel>> frames;
  for (const auto& [name, t] :
       {std::pair{"start", 0.0}, std::pair{"before", first - 1e-3},
        std::pair{"after", first + 1e-3}, std::pair{"middle", 0.5 * end}, std::pair{"end", end}}) {
    frames.emplace_back(name, source.frameAtSimulated(std::clamp(t, 0.0, end)));
  }
  frames.emplace_back("strobe", source.strobeFrame(scene.view.strobe_rate_hz));
  for (auto& [name, frame] : frames) {
    if (longer) {
      for (render::PanelModel& panel : frame.panels) {
        for (render::BodyModel& body : panel.bodies) {
          body.label = lengthened(body.label);
          body.velocity_label = lengthened(body.velocity_label);
        }
      }
      compose::placeLabels(frame, size.width_px, size.height_px, metrics, size.text_floor_px);
    }
    checkFrame(frame, size, metrics,
               preset.name + " " + name + " at " + std::to_string(size.width_px) + "x" +
                   std::to_string(size.height_px) + (longer ? ", 40 % longer" : ""));
  }
}

std::string sizeName(const ::testing::TestParamInfo<std::tuple<Size, bool>>& info) {
  const Size size = std::get<0>(info.param);
  return std::to_string(size.width_px) + "x" + std::to_string(size.height_px) +
         (size.text_floor_px > 0.0 ? "Print" : "") + (std::get<1>(info.param) ? "Longer" : "");
}

const double kPrintFloor_px = render::printTextFloorPx(300.0);

class LabelPlacementTest : public ::testing::TestWithParam<std::tuple<Size, bool>> {};

TEST_P(LabelPlacementTest, NoLabelOverlapsOrWandersInAnyPreset) {
  const auto [size, longer] = GetParam();
  for (const scene::PresetInfo& preset : scene::presetList()) checkPreset(preset, size, longer);
}

INSTANTIATE_TEST_SUITE_P(Sizes, LabelPlacementTest,
                         ::testing::Values(std::tuple{Size{1280, 720}, false},
                                           std::tuple{Size{640, 360}, false},
                                           std::tuple{Size{1280, 720}, true},
                                           std::tuple{Size{640, 360}, true},
                                           // 8 cm at 300 dpi (--print 8cm@300): 8.5 pt text.
                                           std::tuple{Size{945, 630, kPrintFloor_px}, false}),
                         sizeName);

// Labels that fit keep their text: in a scene of two bodies with room to spare none gives way.
TEST(LabelPlacementRoomTest, RoomyScenesKeepEveryLabel) {
  for (const char* name : {"worked-example", "elastic", "billiards-glancing", "stick-2d"}) {
    SCOPED_TRACE(name);
    const app::Animation animation = app::animate(scene::loadPreset(name), {1280, 720});
    for (double t : {0.0, 0.5 * animation.frames.simulatedDuration_s()}) {
      const render::FrameModel frame = animation.frames.frameAtSimulated(t);
      for (const render::BodyModel& body : frame.panels.front().bodies) {
        EXPECT_FALSE(body.label.empty()) << "t = " << t;
        EXPECT_FALSE(body.velocity_label.empty()) << "t = " << t;
      }
    }
  }
}

}  // namespace
}  // namespace collide
