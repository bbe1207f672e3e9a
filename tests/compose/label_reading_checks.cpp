#include "label_reading_checks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "frame/layout.hpp"
#include "pixel_distances.hpp"

namespace collide::compose_test {
namespace {

using Outline = PixelBody;

struct Arrow {
  core::Vec2 tail, tip;
};

// A text placed for a body: what it is, where, and how tall its line is.
struct BodyText {
  std::size_t body;
  enum Kind { kMass, kReadout, kTag, kArrowTag } kind;
  const std::string* text;
  Box box;
  double line_px;
  std::optional<core::Vec2> leader_to;
};

Box boxOf(const frame::PlacedText& placed) {
  return {placed.top_left_px.x(), placed.top_left_px.y(),
          placed.top_left_px.x() + placed.size_px.x(), placed.top_left_px.y() + placed.size_px.y()};
}

}  // namespace

void expectLabelsReadAsTheirOwn(const frame::FrameModel& frame, int width_px, int height_px,
                                double text_floor_px, render::TextMetrics& metrics,
                                const std::string& where) {
  SCOPED_TRACE(where);
  const frame::FrameLayout layout = frame::layoutFrame(
      frame, width_px, height_px, text_floor_px,
      [&metrics](std::string_view text, double px) { return metrics.width(text, px); });
  const auto lineOf = [&](double size) { return metrics.ascender(size) + metrics.descender(size); };
  for (std::size_t p = 0; p < frame.panels.size() && p < layout.panels.size(); ++p) {
    const frame::PanelModel& panel = frame.panels[p];
    const frame::WorldToPixel to_px = frame::panelMapping(panel, layout.panels[p], layout);
    std::vector<Outline> outlines;
    std::vector<std::optional<Arrow>> arrows;
    std::vector<bool> drawn_back;
    std::vector<BodyText> texts;
    for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
      const frame::BodyModel& body = panel.bodies[i];
      const bool disk = body.shape == frame::BodyShape::kDisk;
      const double hx = to_px.px_per_m * body.half_extent_m.x();
      outlines.push_back({disk,
                          to_px.toPixel(body.center_m),
                          {hx, disk ? hx : to_px.px_per_m * body.half_extent_m.y()}});
      arrows.emplace_back();
      drawn_back.push_back(false);
      const double speed = body.velocity_mps.norm();
      if (speed > 1e-6 && panel.arrow_m_per_mps > 0.0 && body.moves_with < 0) {
        const frame::ArrowShape shape = frame::bodyArrowShape(body, panel, layout, to_px);
        if (shape.length_px > 0.0) {
          const core::Vec2 d{body.velocity_mps.x() / speed, -body.velocity_mps.y() / speed};
          const core::Vec2 tail = frame::bodyArrowTailPx(body, panel, layout, to_px, shape);
          arrows.back() = Arrow{tail, tail + shape.length_px * d};
          drawn_back.back() = shape.tail_back_px > 0.0;
        }
      }
      const auto add = [&](const std::string& text, const std::optional<frame::PlacedText>& at,
                           BodyText::Kind kind, double size) {
        if (text.empty() || !at) return;
        texts.push_back({i, kind, &text, boxOf(*at), lineOf(size), at->leader_to_px});
      };
      add(body.label, body.label_at, BodyText::kMass, layout.text_px);
      add(body.velocity_label, body.velocity_label_at, BodyText::kReadout, layout.text_px);
      add(body.tag, body.tag_at, BodyText::kTag, layout.small_px);
      add(body.tag, body.arrow_tag_at, BodyText::kArrowTag, layout.small_px);
    }
    const auto arrowDistance = [&](std::size_t k, const Box& box) {
      return arrows[k] ? segmentToBox(arrows[k]->tail, arrows[k]->tip, box)
                       : std::numeric_limits<double>::infinity();
    };
    for (const BodyText& t : texts) {
      SCOPED_TRACE(*t.text);
      // Nearer its own body (a readout: or its own arrow) than any other body or arrow, clearly:
      // by a quarter of its line's height. (A tag at an arrow's tail: below.)
      if (t.kind != BodyText::kArrowTag) {
        double own = outlines[t.body].distanceTo(t.box);
        if (t.kind == BodyText::kReadout) own = std::min(own, arrowDistance(t.body, t.box));
        for (std::size_t k = 0; k < outlines.size(); ++k) {
          if (k == t.body || panel.bodies[k].moves_with == static_cast<int>(t.body)) continue;
          const double other = std::min(outlines[k].distanceTo(t.box), arrowDistance(k, t.box));
          EXPECT_GE(other - own, kNearerByLines * t.line_px)
              << "panel " << p + 1 << ": about as near body " << k + 1 << " (or its arrow), "
              << other << " px, as its own, " << own << " px: it reads as body " << k + 1 << "'s";
        }
      }
      // A number at an arrow's tail is within a line of that arrow and nearer it than any other
      // arrow or body.
      if (t.kind == BodyText::kArrowTag) {
        const double own = arrowDistance(t.body, t.box);
        EXPECT_LE(own, t.line_px) << "panel " << p + 1 << ": a number away from its arrow";
        for (std::size_t k = 0; k < outlines.size(); ++k) {
          if (k == t.body || panel.bodies[k].moves_with == static_cast<int>(t.body)) continue;
          EXPECT_LT(own, std::min(outlines[k].distanceTo(t.box), arrowDistance(k, t.box)))
              << "panel " << p + 1 << ": as near body " << k + 1 << " or its arrow as its own";
        }
      }
      // A leader bridges a short way only.
      if (t.leader_to) {
        const core::Vec2 from{std::clamp(t.leader_to->x(), t.box.x0, t.box.x1),
                              std::clamp(t.leader_to->y(), t.box.y0, t.box.y1)};
        EXPECT_LE((*t.leader_to - from).norm(), kLongestLeaderLines * t.line_px)
            << "panel " << p + 1 << ": a leader " << (*t.leader_to - from).norm() / t.line_px
            << " lines long";
      }
    }
    // Two labels of bodies (masses, readouts) on one line stand far enough apart to read as two.
    for (std::size_t a = 0; a < texts.size(); ++a) {
      for (std::size_t b = a + 1; b < texts.size(); ++b) {
        const BodyText &s = texts[a], &t = texts[b];
        const bool labels = (s.kind == BodyText::kMass || s.kind == BodyText::kReadout) &&
                            (t.kind == BodyText::kMass || t.kind == BodyText::kReadout);
        if (!labels) continue;
        const double line = std::max(s.line_px, t.line_px);
        if (std::abs(s.box.y1 - t.box.y1) >= kOneLineBaselineLines * line) continue;
        const double gap = std::max(s.box.x0 - t.box.x1, t.box.x0 - s.box.x1);
        EXPECT_GE(gap, kOneLineLeastGapEm * layout.text_px)
            << "panel " << p + 1 << ": \"" << *s.text << "\" and \"" << *t.text << "\" on one line "
            << gap / layout.text_px << " em apart read as one line";
      }
    }
    // An arrow lifted above the bodies (a row of its own) or drawn back from a wall (its tail
    // behind its body) no longer starts over its body: its value beside it, or its body's number,
    // says whose it is.
    if (!panel.two_d) {
      for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
        const frame::BodyModel& body = panel.bodies[i];
        if (!arrows[i] || (body.arrow_row == 0 && !drawn_back[i])) continue;
        const bool readout = !body.velocity_label.empty() && body.velocity_label_at;
        EXPECT_TRUE(readout || (!body.tag.empty() && body.arrow_tag_at))
            << "panel " << p + 1 << ": body " << i + 1
            << "'s arrow, lifted or drawn back from a wall, carries neither its value nor its "
               "body's number";
      }
    }
  }
}

}  // namespace collide::compose_test
