// SPDX-License-Identifier: MIT
// The ruler of a panel's scene: its axes, ticks and numbers.
#include <algorithm>
#include <cmath>
#include <string>

#include "frame/mark_sizes.hpp"
#include "render/draw/draw_world_parts.hpp"
#include "render/draw/frame_drawing.hpp"

namespace collide::render {

void drawRuler(const frame::PanelModel& panel, const frame::FrameStyle& style,
               const frame::PanelLayout& where, const frame::FrameLayout& layout,
               const frame::WorldToPixel& to_px, const frame::PixelRect& area, Canvas& canvas) {
  ShapeSink& mesh = canvas.shapes();
  const double tick = frame::kRulerTickLength * layout.scale_px, thin = 0.5 * layout.line_px;
  const frame::RulerPlacement ruler = frame::rulerPlacement(panel, where, layout, to_px, area);
  const frame::RulerAxis& along_x = ruler.along_x;
  if (!along_x.ticks_m.empty()) {
    const double y = ruler.x_axis_y_px;
    mesh.addLine({to_px.toPixel({along_x.from_m, 0.0}).x(), y},
                 {to_px.toPixel({along_x.to_m, 0.0}).x(), y}, thin, style.track);
    for (std::size_t k = 0; k < along_x.ticks_m.size(); ++k) {
      const double x = to_px.toPixel({along_x.ticks_m[k], 0.0}).x();
      mesh.addLine({x, y}, {x, y + tick}, thin, style.track);
      const bool last = k + 1 == along_x.ticks_m.size();
      const std::string number = tickLabel(along_x.ticks_m[k], style.numbers) + (last ? " m" : "");
      // Centred under its tick, but never out of the scene's clip (the first number at the
      // frame's left edge).
      const double number_w = canvas.painter().width(number, layout.small_px);
      const double left = last ? x - number_w : std::max(x - 0.5 * number_w, where.world_clip.x0);
      canvas.text(number, {left, y + tick + 0.2 * layout.small_px}, layout.small_px,
                  style.muted_text, HAlign::kLeft, VAlign::kTop);
    }
  }
  if (!panel.two_d) return;
  const frame::RulerAxis& along_y = ruler.along_y;
  if (along_y.ticks_m.empty()) return;
  const double x = ruler.y_axis_x_px;
  mesh.addLine({x, to_px.toPixel({0.0, along_y.to_m}).y()},
               {x, to_px.toPixel({0.0, along_y.from_m}).y()}, thin, style.track);
  for (double tick_m : along_y.ticks_m) {
    const double yy = to_px.toPixel({0.0, tick_m}).y();
    mesh.addLine({x - tick, yy}, {x, yy}, thin, style.track);
    // A floor or ceiling at this height would strike through the number: it goes on the free
    // side of the wall instead.
    VAlign v = VAlign::kMiddle;
    double number_y = yy;
    for (const frame::WallModel& wall : panel.walls) {
      const core::Vec2 n = wall.normal.normalized();
      if (std::abs(n.y()) < 0.99 || std::abs(wall.point_m.y() - tick_m) > 1e-6 * along_y.step_m)
        continue;
      v = n.y() > 0.0 ? VAlign::kBottom : VAlign::kTop;
      number_y = yy + (n.y() > 0.0 ? -1.0 : 1.0) * (layout.track_px + 0.15 * layout.small_px);
    }
    // Never out of the scene's clip either (a wide "−0.5" at 480x270 reached past it).
    const std::string number = tickLabel(tick_m, style.numbers);
    const double right =
        std::max(x - tick - 0.3 * layout.small_px,
                 where.world_clip.x0 + canvas.painter().width(number, layout.small_px));
    canvas.text(number, {right, number_y}, layout.small_px, style.muted_text, HAlign::kRight, v);
  }
}

}  // namespace collide::render
