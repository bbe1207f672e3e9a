#include "label_clearance_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string_view>

#include "frame/layout.hpp"

namespace collide::compose_test {
namespace {

bool apart(const Box& a, const Box& b, double em) {
  const double across = std::max(a.x0 - b.x1, b.x0 - a.x1);
  const double along = std::max(a.y0 - b.y1, b.y0 - a.y1);
  return across >= kLeastGapAcrossEm * em || along >= kLeastGapAlongEm * em;
}

}  // namespace

void expectTextsClear(const frame::PanelModel& panel, const std::vector<SceneText>& texts,
                      const std::vector<PixelBody>& bodies, const std::vector<PaintedArrow>& arrows,
                      const std::vector<PaintedMark>& marks, int width_px, int height_px,
                      double margin_px, double line_box_px) {
  for (const SceneText& t : texts) {
    SCOPED_TRACE(t.text);
    const Box& box = t.box;
    // As far from every frame edge as the title stands from the frame's corner: a label nearer
    // the edge than the title looks cut off or pushed out (bullet-block at 640x360, "m₁" 6 px
    // from the left edge, the title 11 px).
    EXPECT_GE(box.x0, margin_px) << "nearer the left edge than the title's margin";
    EXPECT_GE(box.y0, margin_px) << "nearer the top edge than the title's margin";
    EXPECT_LE(box.x1, width_px - margin_px) << "nearer the right edge than the title's margin";
    EXPECT_LE(box.y1, height_px - margin_px) << "nearer the bottom edge than the title's margin";
    for (std::size_t k = 0; k < bodies.size(); ++k) {
      EXPECT_GT(bodies[k].distanceTo(box), 0.0) << "covers body " << k + 1;
    }
    for (const PaintedArrow& arrow : arrows) {
      EXPECT_GT(segmentToBox(arrow.tail, arrow.tip, box), arrow.half_width) << "covers an arrow";
    }
    for (const PaintedMark& mark : marks) {
      EXPECT_GT(segmentToBox(mark.a, mark.b, box), mark.half_width) << mark.what << " crosses it";
    }
    if (t.body) {
      // Nearer what it names than anything it could be read as naming: a mass label its body,
      // a readout its body or its arrow; never another body or another body's arrow.
      const std::size_t i = *t.body;
      const auto arrowDistance = [&](std::size_t k) {
        double d = std::numeric_limits<double>::infinity();
        for (const PaintedArrow& arrow : arrows) {
          if (arrow.body == k) d = std::min(d, segmentToBox(arrow.tail, arrow.tip, box));
        }
        return d;
      };
      const double own = t.velocity ? std::min(bodies[i].distanceTo(box), arrowDistance(i))
                                    : bodies[i].distanceTo(box);
      for (std::size_t k = 0; k < bodies.size(); ++k) {
        // A body riding on this one (a bullet in its block) is drawn and labelled as part of it.
        const bool rider = panel.bodies[k].moves_with == static_cast<int>(i);
        if (k != i && !rider) {
          EXPECT_LT(own, bodies[k].distanceTo(box)) << "nearer body " << k + 1 << " than its own";
          EXPECT_LT(own, arrowDistance(k)) << "nearer body " << k + 1 << "'s arrow than its own";
        }
      }
      // And near it: within two lines of text, or joined to it by a leader that ends on it.
      if (!t.leader_to) {
        EXPECT_LE(own, 2.0 * line_box_px) << "far from what it names, with no leader";
      } else {
        const core::Vec2& to = *t.leader_to;
        bool ends_on_it = bodies[i].distanceTo({to.x(), to.y(), to.x(), to.y()}) <= 1.0;
        for (const PaintedArrow& arrow : arrows) {
          ends_on_it = ends_on_it || (t.velocity && arrow.body == i &&
                                      pointToSegment(to, arrow.tail, arrow.tip) <= 1.0);
        }
        EXPECT_TRUE(ends_on_it) << "its leader ends away from what it names";
      }
    }
    if (!t.leader_to) continue;
    // The leader strikes through no other text, no arrow (but the readout's own, where it
    // ends), no wall or flash, and no body but its own.
    const core::Vec2 a = *t.leader_from, b = *t.leader_to;
    for (const SceneText& other : texts) {
      if (&other == &t) continue;
      EXPECT_GT(segmentToBox(a, b, other.box), 0.0) << "its leader crosses " << other.text;
      if (other.leader_to) {
        EXPECT_GT(segmentToSegment(a, b, *other.leader_from, *other.leader_to), 0.0)
            << "its leader crosses " << other.text << "'s";
      }
    }
    for (const PaintedArrow& arrow : arrows) {
      if (t.velocity && arrow.body == *t.body) continue;
      EXPECT_GT(segmentToSegment(a, b, arrow.tail, arrow.tip), arrow.half_width)
          << "its leader crosses the arrow of body " << arrow.body + 1;
    }
    for (const PaintedMark& mark : marks) {
      EXPECT_GT(segmentToSegment(a, b, mark.a, mark.b), mark.half_width)
          << "its leader crosses " << mark.what;
    }
    for (std::size_t k = 0; k < bodies.size(); ++k) {
      if (k == *t.body) continue;
      const Box outline{
          bodies[k].center.x() - bodies[k].half.x(), bodies[k].center.y() - bodies[k].half.y(),
          bodies[k].center.x() + bodies[k].half.x(), bodies[k].center.y() + bodies[k].half.y()};
      const double d = bodies[k].disk ? pointToSegment(bodies[k].center, a, b) - bodies[k].half.x()
                                      : segmentToBox(a, b, outline);
      EXPECT_GT(d, 0.0) << "its leader crosses body " << k + 1;
    }
  }
}

void expectTextsApart(const std::vector<Box>& boxes, double text_px) {
  for (std::size_t a = 0; a < boxes.size(); ++a) {
    for (std::size_t b = a + 1; b < boxes.size(); ++b) {
      EXPECT_FALSE(intersects(boxes[a], boxes[b])) << "two labels overlap";
      EXPECT_TRUE(apart(boxes[a], boxes[b], text_px))
          << "two labels nearer than a word space: they read as one";
    }
  }
}

void expectFrameClear(const frame::FrameModel& frame, int width_px, int height_px,
                      double text_floor_px, render::TextMetrics& metrics, bool margin_kept,
                      const PanelCheck& each_panel) {
  const frame::FrameLayout layout = frame::layoutFrame(
      frame, width_px, height_px, text_floor_px,
      [&metrics](std::string_view text, double px) { return metrics.width(text, px); });
  const double line_box = metrics.ascender(layout.text_px) + metrics.descender(layout.text_px);
  // The title's margin: where its first line starts, from the left and the top edge.
  ASSERT_EQ(layout.header.x0, layout.header.y0);
  const double margin = margin_kept ? layout.header.x0 : 0.0;
  std::vector<Box> all_texts;
  for (std::size_t p = 0; p < frame.panels.size(); ++p) {
    const frame::PanelModel& panel = frame.panels[p];
    ASSERT_EQ(panel.placed_for_width_px, width_px);
    ASSERT_EQ(panel.placed_for_height_px, height_px);
    ASSERT_EQ(panel.placed_for_scale_px, layout.scale_px);
    const frame::WorldToPixel to_px = frame::panelMapping(panel, layout.panels[p], layout);
    const frame::PixelRect area = frame::worldArea(panel, layout.panels[p], layout);
    const std::vector<PixelBody> bodies = paintedBodies(panel, to_px);
    const std::vector<PaintedArrow> arrows = paintedArrows(panel, layout, to_px);
    const std::vector<PaintedMark> marks =
        paintedMarks(panel, layout, to_px, area, width_px, height_px);
    std::vector<SceneText> texts;
    ASSERT_NO_FATAL_FAILURE(gatherSceneTexts(panel, layout, to_px, metrics, text_floor_px, texts));
    expectTextsClear(panel, texts, bodies, arrows, marks, width_px, height_px, margin, line_box);
    if (each_panel) each_panel(panel, p, arrows);
    for (const SceneText& t : texts) all_texts.push_back(t.box);
  }
  expectTextsApart(all_texts, layout.text_px);
}

}  // namespace collide::compose_test
