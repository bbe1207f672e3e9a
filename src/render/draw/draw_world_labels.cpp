// SPDX-License-Identifier: MIT
// The bodies' labels of a panel's scene: where compose placed them, or placed here for a frame
// composed without a picture size.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "frame/mark_sizes.hpp"
#include "render/draw/draw_world_parts.hpp"
#include "render/draw/frame_drawing.hpp"

namespace collide::render {
namespace {

// 1D: a row of labels centred on the bodies, spread so they never overlap.
void drawLabelRow(const std::vector<std::string>& texts, const std::vector<double>& centers,
                  const std::vector<double>& ys, VAlign v, const frame::FrameStyle& style,
                  const frame::FrameLayout& layout, const frame::PixelRect& clip, Canvas& canvas,
                  bool mass) {
  std::vector<double> wanted, widths;
  std::vector<std::size_t> which;
  for (std::size_t i = 0; i < texts.size(); ++i) {
    if (texts[i].empty()) continue;
    wanted.push_back(centers[i]);
    widths.push_back(canvas.painter().width(texts[i], layout.text_px));
    which.push_back(i);
  }
  const std::vector<double> x0s =
      frame::spreadIntervals(wanted, widths, 0.8 * layout.text_px, clip.x0, clip.x1);
  for (std::size_t k = 0; k < which.size(); ++k) {
    const DrawnItemScope item(canvas.shapes(), bodyId(mass ? "mass" : "velocity", which[k]),
                              mass ? "label" : "readout", static_cast<int>(which[k]));
    canvas.text(texts[which[k]], {x0s[k], ys[which[k]]}, layout.text_px, style.text, HAlign::kLeft,
                v);
  }
}

}  // namespace

// Labels where compose placed them (PlacedText), with their leader lines.
void drawPlacedLabels(const frame::PanelModel& panel, const frame::FrameStyle& style,
                      const frame::FrameLayout& layout, Canvas& canvas) {
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    const frame::BodyModel& body = panel.bodies[i];
    for (const auto& [text, at] : {std::pair{&body.label, &body.label_at},
                                   std::pair{&body.velocity_label, &body.velocity_label_at}}) {
      if (text->empty() || !*at || !seen((*at)->opacity)) continue;
      const bool mass = text == &body.label;
      const frame::PlacedText& placed = **at;
      if (placed.leader_to_px) {
        const DrawnItemScope leader(canvas.shapes(),
                                    bodyId(mass ? "leader.mass" : "leader.velocity", i), "leader",
                                    static_cast<int>(i));
        canvas.shapes().describeOpacity(placed.opacity);
        // From the box edge nearest the body.
        const core::Vec2& to = *placed.leader_to_px;
        const core::Vec2 from{
            std::clamp(to.x(), placed.top_left_px.x(), placed.top_left_px.x() + placed.size_px.x()),
            std::clamp(to.y(), placed.top_left_px.y(),
                       placed.top_left_px.y() + placed.size_px.y())};
        canvas.shapes().addLine(from, to, 0.5 * layout.line_px,
                                faded(style.muted_text, placed.opacity));
      }
      const DrawnItemScope item(canvas.shapes(), bodyId(mass ? "mass" : "velocity", i),
                                mass ? "label" : "readout", static_cast<int>(i));
      canvas.shapes().describeOpacity(placed.opacity);
      canvas.text(*text, placed.top_left_px, layout.text_px, faded(style.text, placed.opacity),
                  HAlign::kLeft, VAlign::kTop);
    }
  }
  for (const frame::ReadoutLegend::Entry& entry : panel.legend.entries) {
    if (!seen(entry.opacity)) continue;
    const auto body = static_cast<std::size_t>(std::max(0, entry.body));
    const DrawnItemScope item(canvas.shapes(),
                              bodyId(entry.mass ? "legend.mass" : "legend.velocity", body),
                              "legend", entry.body);
    canvas.shapes().describeOpacity(entry.opacity);
    canvas.text(entry.text, entry.top_left_px, layout.text_px, faded(style.text, entry.opacity),
                HAlign::kLeft, VAlign::kTop);
  }
  // The numbers of bodies too small to carry them inside, beside them, and at the tails of
  // lifted arrows.
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    const frame::BodyModel& body = panel.bodies[i];
    if (body.tag.empty()) continue;
    for (const auto& [id, at] :
         {std::pair{"tag", &body.tag_at}, std::pair{"arrow_tag", &body.arrow_tag_at}}) {
      if (!*at || !seen((*at)->opacity)) continue;
      const DrawnItemScope item(canvas.shapes(), bodyId(id, i), "label", static_cast<int>(i));
      canvas.shapes().describeOpacity((*at)->opacity);
      canvas.text(body.tag, (*at)->top_left_px, layout.small_px, faded(style.text, (*at)->opacity),
                  HAlign::kLeft, VAlign::kTop);
    }
  }
}

// Labels placed here, for a frame composed without a picture size: 1D in rows, 2D beside bodies.
void drawOwnLabels(const frame::PanelModel& panel, const frame::FrameStyle& style,
                   const frame::PanelLayout& where, const frame::FrameLayout& layout,
                   const frame::WorldToPixel& to_px, const frame::PixelRect& area,
                   const std::vector<Placed>& placed, Canvas& canvas) {
  const std::size_t n = panel.bodies.size();
  std::vector<std::string> labels(n), velocities(n);
  std::vector<double> centers(n), label_y(n), velocity_y(n);
  const double track_bottom =
      to_px.toPixel({0.0, panel.track_y_m}).y() + layout.track_px + layout.gap_px;
  for (std::size_t i = 0; i < n; ++i) {
    const frame::BodyModel& body = panel.bodies[i];
    labels[i] = body.label;
    velocities[i] = body.velocity_label;
    centers[i] = placed[i].center.x();
    label_y[i] = panel.two_d ? placed[i].bottom + layout.gap_px : track_bottom;
    velocity_y[i] = (panel.two_d ? placed[i].top - layout.arrow_gap_px
                                 : frame::arrowLineYPx(panel, body, layout, to_px)) -
                    0.5 * layout.arrow_head_width_px - 0.5 * layout.gap_px;
  }
  if (!panel.two_d) {
    drawLabelRow(labels, centers, label_y, VAlign::kTop, style, layout, where.world_clip, canvas,
                 true);
    drawLabelRow(velocities, centers, velocity_y, VAlign::kBottom, style, layout, where.world_clip,
                 canvas, false);
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      const frame::BodyModel& body = panel.bodies[i];
      if (!labels[i].empty()) {
        const DrawnItemScope item(canvas.shapes(), bodyId("mass", i), "label", static_cast<int>(i));
        // Below the disk, unless its arrow points down or the label would leave the scene.
        const bool arrow_down = body.velocity_mps.y() < -kRestSpeed_mps;
        const bool room_below = label_y[i] + 1.3 * layout.text_px <= area.y1 + layout.gap_px;
        if (arrow_down || !room_below) {
          canvas.text(labels[i], {centers[i], placed[i].top - layout.gap_px}, layout.text_px,
                      style.text, HAlign::kCenter, VAlign::kBottom);
        } else {
          canvas.text(labels[i], {centers[i], label_y[i]}, layout.text_px, style.text,
                      HAlign::kCenter, VAlign::kTop);
        }
      }
      if (velocities[i].empty()) continue;
      const DrawnItemScope item(canvas.shapes(), bodyId("velocity", i), "readout",
                                static_cast<int>(i));
      // Beside the arrow's tip, on the side it points to; above the disk when at rest.
      const double speed = body.velocity_mps.norm();
      if (speed <= kRestSpeed_mps || panel.arrow_m_per_mps <= 0.0) {
        canvas.text(velocities[i], {centers[i], placed[i].top - layout.gap_px}, layout.text_px,
                    style.text, HAlign::kCenter, VAlign::kBottom);
        continue;
      }
      const core::Vec2 d = pixelDirection(body.velocity_mps) / speed;
      const frame::ArrowShape arrow = frame::bodyArrowShape(body, panel, layout, to_px);
      const double reach = arrow.tail_ahead_px + arrow.length_px;  // from the edge: past it
      const core::Vec2 tip =
          placed[i].center + std::max(reach, placed[i].radius) * d + layout.gap_px * d;
      canvas.text(velocities[i], tip, layout.text_px, style.text,
                  d.x() >= 0.0 ? HAlign::kLeft : HAlign::kRight, VAlign::kMiddle);
    }
  }
}

}  // namespace collide::render
