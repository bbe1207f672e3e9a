// The frame as a whole: header, panels (world clipped to its area, then readouts), charts.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "render/draw/frame_drawing.hpp"
#include "text/number_format.hpp"

namespace collide::render {
namespace {

// Where a video's slow-motion subtitle goes and how large the title is beside it. The subtitle
// never changes the layout (a still at t is the video's frame at t, and a still shows no
// subtitle): it takes room the title leaves, sized by the widest subtitle its stretch of slow
// motion shows (FrameModel::subtitle_room), so it keeps its place while the factor ramps.
struct SubtitleFit {
  double size_px = 0.0;   // the subtitle's size
  int line = 0;           // the header line it is on: 0 beside the time readout, 1 under it
  double title_px = 0.0;  // the title's size: smaller only where nothing else leaves room
};

// The width of the title's line k at size_px and the gap after it; 0 where it has no such line.
double titleLineWidth(const std::vector<std::string>& title_lines, std::size_t k, double size_px,
                      double gap_px, TextPainter& painter) {
  return k < title_lines.size() ? painter.width(title_lines[k], size_px) + gap_px : 0.0;
}

SubtitleFit fitSubtitle(const frame::FrameModel& frame, const frame::FrameLayout& layout,
                        const std::vector<std::string>& title_lines, double across_px,
                        TextPainter& painter) {
  const std::string& widest = frame.subtitle_room.empty() ? frame.subtitle : frame.subtitle_room;
  const double gap = layout.text_px;
  // Beside the time readout, right of the title's first line.
  for (const double size_px : {layout.text_px, layout.small_px}) {
    if (titleLineWidth(title_lines, 0, layout.title_px, gap, painter) + gap +
            painter.width(widest, size_px) <=
        across_px) {
      return {size_px, 0, layout.title_px};
    }
  }
  // Under the time readout, right of the title's second line.
  if (layout.title_lines > 1) {
    for (const double size_px : {layout.text_px, layout.small_px}) {
      if (titleLineWidth(title_lines, 1, layout.title_px, gap, painter) +
              painter.width(widest, size_px) <=
          layout.header.width()) {
        return {size_px, 1, layout.title_px};
      }
    }
  }
  // Beside the title's first line drawn smaller, broken where it was (no smaller than captions).
  const double beside = across_px - gap - painter.width(widest, layout.small_px);
  double title_px = layout.title_px;
  while (title_px > layout.small_px &&
         titleLineWidth(title_lines, 0, title_px, gap, painter) > beside) {
    title_px = std::max(layout.small_px, 0.95 * title_px);
  }
  return {layout.small_px, 0, title_px};
}

void drawHeader(const frame::FrameModel& frame, const frame::FrameLayout& layout, Canvas& canvas) {
  const frame::PixelRect& header = layout.header;
  // The time readout and subtitle on the first line; a long title wraps to the second.
  const double line_h = header.height() / std::max(1, layout.title_lines);
  const double mid = header.y0 + 0.5 * line_h;
  const frame::FrameStyle& style = frame.style;
  // Left to right: the title from the left edge, the time readout at the right; a language
  // read from the right swaps them.
  const bool rtl = style.right_to_left;
  const HAlign title_side = rtl ? HAlign::kRight : HAlign::kLeft;
  const HAlign readout_side = rtl ? HAlign::kLeft : HAlign::kRight;
  const double title_edge = rtl ? header.x1 : header.x0;
  double readout_edge = rtl ? header.x0 : header.x1;  // where the readouts end, inwards
  const auto inner_edge = [rtl](const frame::PixelRect& box) { return rtl ? box.x1 : box.x0; };
  ShapeSink& items = canvas.shapes();
  if (!frame.time_readout.empty()) {
    const DrawnItemScope item(items, "time", "readout");
    readout_edge = inner_edge(canvas.text(frame.time_readout, {readout_edge, mid}, layout.title_px,
                                          style.text, readout_side, VAlign::kMiddle));
  }
  // The title's lines as the layout counted them, whether a subtitle shows or not.
  const double across_px = std::abs(readout_edge - title_edge);
  const std::vector<std::string> lines =
      frame.title.empty()
          ? std::vector<std::string>{}
          : canvas.painter().wrap(frame.title, layout.title_px,
                                  std::max(0.0, across_px - layout.text_px), layout.title_lines);
  SubtitleFit fit{0.0, 0, layout.title_px};
  if (!frame.subtitle.empty()) {
    fit = fitSubtitle(frame, layout, lines, across_px, canvas.painter());
    const DrawnItemScope item(items, "subtitle", "caption");
    const double gap = rtl ? layout.text_px : -layout.text_px;
    const core::Vec2 at = fit.line == 0 ? core::Vec2{readout_edge + gap, mid}
                                        : core::Vec2{rtl ? header.x0 : header.x1, mid + line_h};
    canvas.text(frame.subtitle, at, fit.size_px, style.muted_text, readout_side, VAlign::kMiddle);
  }
  if (!lines.empty()) {
    const DrawnItemScope item(items, "title", "title");
    for (std::size_t i = 0; i < lines.size(); ++i) {
      canvas.text(lines[i], {title_edge, mid + i * line_h}, fit.title_px, style.text, title_side,
                  VAlign::kMiddle);
    }
  }
}

}  // namespace

frame::DrawnArrow drawnArrow(const core::Vec2& tail_px, const core::Vec2& direction,
                             const frame::ArrowShape& shape, double value_mps,
                             double scale_px_per_mps) {
  frame::DrawnArrow arrow;
  arrow.from_px = tail_px;
  arrow.to_px = tail_px + shape.length_px * direction.normalized();
  arrow.value_mps = value_mps;
  arrow.scale_px_per_mps = scale_px_per_mps;
  arrow.drawn = shape.off_scale     ? frame::ArrowDrawn::kOffScale
                : shape.under_scale ? frame::ArrowDrawn::kBelowScale
                                    : frame::ArrowDrawn::kOnScale;
  return arrow;
}

frame::Rgba withAlpha(const frame::Rgba& c, double alpha_factor) {
  return {c.r, c.g, c.b, static_cast<float>(c.a * std::clamp(alpha_factor, 0.0, 1.0))};
}

frame::Rgba contrastingText(const frame::Rgba& fill) {
  const double luminance = 0.2126 * fill.r + 0.7152 * fill.g + 0.0722 * fill.b;
  return luminance > 0.5 ? frame::Rgba{0.0f, 0.0f, 0.0f, 1.0f}
                         : frame::Rgba{1.0f, 1.0f, 1.0f, 1.0f};
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

void drawFrame(const frame::FrameModel& frame, const frame::FrameLayout& layout, Canvas& canvas) {
  canvas.clear();
  canvas.beginBatch();
  drawHeader(frame, layout, canvas);
  const std::size_t panels = std::min(frame.panels.size(), layout.panels.size());
  for (std::size_t i = 0; i < panels; ++i) {
    const frame::PanelModel& panel = frame.panels[i];
    const frame::PanelLayout& where = layout.panels[i];
    canvas.shapes().enterPanel(static_cast<int>(i));
    canvas.beginBatch(where.world_clip);
    drawPanelWorld(panel, frame.style, where, layout, canvas);
    if (const std::optional<frame::PixelRect> box = frame::momentumBox(panel, where, layout)) {
      // Clipped to its own box, which lies in the scene or in a side column.
      canvas.beginBatch(*box);
      const DrawnItemScope item(canvas.shapes(), "momentum", "inset");
      drawMomentumInset(panel, frame.style, where, layout, canvas);
    }
    canvas.beginBatch();
    drawPanelReadouts(panel, frame.style, where, layout, canvas);
  }
  canvas.shapes().enterPanel(-1);
  const std::size_t charts = std::min(frame.charts.size(), layout.charts.size());
  for (std::size_t i = 0; i < charts; ++i) {
    canvas.beginBatch(layout.charts[i]);
    const DrawnItemScope item(canvas.shapes(), "chart." + std::to_string(i + 1), "chart");
    drawChart(frame.charts[i], frame.style, layout.charts[i], layout, canvas);
  }
  if (frame.working && layout.charts.size() > frame.charts.size()) {
    canvas.beginBatch(layout.charts.back());
    const DrawnItemScope item(canvas.shapes(), "working", "working");
    drawWorking(*frame.working, frame.style, layout.charts.back(), layout, canvas);
  }
  canvas.finish();
}

}  // namespace collide::render
