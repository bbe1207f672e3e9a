// The frame as a whole: header, panels (world clipped to its area, then readouts), charts.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/frame_drawing.hpp"
#include "text/number_format.hpp"

namespace collide::render {
namespace {

void drawHeader(const FrameModel& frame, const FrameLayout& layout, Canvas& canvas) {
  const PixelRect& header = layout.header;
  // The time readout and subtitle on the first line; a long title wraps to the second.
  const double line_h = header.height() / std::max(1, layout.title_lines);
  const double mid = header.y0 + 0.5 * line_h;
  const FrameStyle& style = frame.style;
  double right = header.x1;
  if (!frame.time_readout.empty()) {
    right = canvas
                .text(frame.time_readout, {header.x1, mid}, layout.title_px, style.text,
                      HAlign::kRight, VAlign::kMiddle)
                .x0;
  }
  if (!frame.subtitle.empty()) {
    right = canvas
                .text(frame.subtitle, {right - layout.text_px, mid}, layout.text_px,
                      style.muted_text, HAlign::kRight, VAlign::kMiddle)
                .x0;
  }
  if (!frame.title.empty()) {
    const std::vector<std::string> lines = canvas.painter().wrap(
        frame.title, layout.title_px, std::max(0.0, right - layout.text_px - header.x0),
        layout.title_lines);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      canvas.text(lines[i], {header.x0, mid + i * line_h}, layout.title_px, style.text,
                  HAlign::kLeft, VAlign::kMiddle);
    }
  }
}

}  // namespace

Rgba withAlpha(const Rgba& c, double alpha_factor) {
  return {c.r, c.g, c.b, static_cast<float>(c.a * std::clamp(alpha_factor, 0.0, 1.0))};
}

Rgba contrastingText(const Rgba& fill) {
  const double luminance = 0.2126 * fill.r + 0.7152 * fill.g + 0.0722 * fill.b;
  return luminance > 0.5 ? Rgba{0.0f, 0.0f, 0.0f, 1.0f} : Rgba{1.0f, 1.0f, 1.0f, 1.0f};
}

double niceStep(double min_step) {
  if (!(min_step > 0.0) || !std::isfinite(min_step)) return 1.0;
  const double power = std::pow(10.0, std::floor(std::log10(min_step)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * power >= min_step * (1.0 - 1e-9)) return m * power;
  }
  return 10.0 * power;
}

std::string tickLabel(double value, const text::NumberStyle& numbers) {
  if (std::abs(value) < 1e-12) value = 0.0;  // round-off of k * step: no "-0"
  // Ticks are multiples of 1, 2 or 5 times a power of ten: four figures show any of them.
  return text::formatPlain(value, numbers, 4);
}

void drawFrame(const FrameModel& frame, const FrameLayout& layout, Canvas& canvas) {
  canvas.clear();
  canvas.beginBatch();
  drawHeader(frame, layout, canvas);
  const std::size_t panels = std::min(frame.panels.size(), layout.panels.size());
  for (std::size_t i = 0; i < panels; ++i) {
    const PanelModel& panel = frame.panels[i];
    const PanelLayout& where = layout.panels[i];
    canvas.beginBatch(where.world_clip);
    drawPanelWorld(panel, frame.style, where, layout, canvas);
    if (panel.momentum) {
      canvas.beginBatch(where.world_clip);
      drawMomentumInset(panel, frame.style, where, layout, canvas);
    }
    canvas.beginBatch();
    drawPanelReadouts(panel, frame.style, where, layout, canvas);
  }
  const std::size_t charts = std::min(frame.charts.size(), layout.charts.size());
  for (std::size_t i = 0; i < charts; ++i) {
    canvas.beginBatch(layout.charts[i]);
    drawChart(frame.charts[i], frame.style, layout.charts[i], layout, canvas);
  }
  canvas.finish();
}

}  // namespace collide::render
