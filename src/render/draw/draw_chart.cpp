// A line chart with fixed axes, nice ticks, a light grid, direct labels at the line ends and an
// optional cursor (the current time).
#include <algorithm>
#include <cmath>

#include "render/draw/frame_drawing.hpp"

namespace collide::render {
namespace {

constexpr double kMinTickSpacing = 0.09;  // frame heights between ticks, at least
constexpr double kTick = 0.012;           // tick length, frame heights
constexpr double kMaxChartTicks = 200;    // per axis; guards against a degenerate range
constexpr double kDash = 0.02;            // dash length of dashed series, frame heights
constexpr double kLegendSwatch = 0.6;     // colour swatch beside a legend entry, em
constexpr int kMaxChartTitleLines = 4;    // a title wraps onto at most this many lines
constexpr double kMinPlotLines = 2.0;     // the plot's least height, small text lines (two
                                          // tick labels apart), before the header gives way

// The visible part of a series: points up to `cursor` with the crossing point interpolated.
std::vector<core::Vec2> visiblePart(const frame::ChartSeries& series,
                                    std::optional<double> cursor) {
  if (!cursor) return series.points;
  std::vector<core::Vec2> out;
  for (std::size_t i = 0; i < series.points.size(); ++i) {
    const core::Vec2& p = series.points[i];
    if (p.x() <= *cursor) {
      out.push_back(p);
      continue;
    }
    if (i > 0 && series.points[i - 1].x() < *cursor) {
      const core::Vec2& q = series.points[i - 1];
      const double f = (*cursor - q.x()) / (p.x() - q.x());
      out.push_back(q + f * (p - q));
    }
    break;
  }
  return out;
}

// Whether wrapped lines lost part of their text (the last ends with an ellipsis).
bool wrapShortened(const std::vector<std::string>& lines, const std::string& text) {
  static const std::string kEllipsis = "\u2026";
  return !lines.empty() && lines.back().ends_with(kEllipsis) && !text.ends_with(kEllipsis);
}

}  // namespace

void drawChart(const frame::ChartModel& chart, const frame::FrameStyle& style,
               const frame::PixelRect& where, const frame::FrameLayout& layout, Canvas& canvas) {
  ShapeSink& mesh = canvas.shapes();
  TextPainter& painter = canvas.painter();
  const double h = layout.scale_px, small = layout.small_px, text = layout.text_px;
  const double line = std::round(1.3 * small), tick = kTick * h, thin = 0.4 * layout.line_px;
  const double x_span = chart.max.x() - chart.min.x(), y_span = chart.max.y() - chart.min.y();
  if (!(x_span > 0.0) || !(y_span > 0.0)) return;

  // Under the plot: the tick numbers' line, then the axis name's whole line (its descender too).
  const double name_h = painter.ascender(small) + painter.descender(small);
  const double plot_bottom = where.y1 - tick - 0.2 * small - line - name_h;

  // Above the plot: the title, its notes, the y axis's name; tick labels left and below; line
  // labels right. The header is as tall as its text, while the plot keeps kMinPlotLines small
  // lines (more where more line labels stand beside it: all must fit). The title wraps onto as many
  // lines as the chart's width needs, in small text where the large would not fit whole; only what
  // still does not fit is cut (with an ellipsis). Each note then takes up to two small lines;
  // the notes that do not fit give way, the last first.
  const double y_label_step = line + 0.5 * small;
  // The line labels beside the plot reach down to the tick numbers' line, one line below it.
  const double least_plot = std::max(kMinPlotLines, double(chart.series.size()) - 1.0) * line;
  const double header_room = plot_bottom - where.y0 - y_label_step - least_plot;
  const auto titleIn = [&](double size_px) {
    const double step = std::round(frame::kLineSpacing * size_px);
    const int most = std::clamp(int(std::floor(header_room / step + 1e-9)), 1, kMaxChartTitleLines);
    return painter.wrap(chart.title, size_px, where.width(), most);
  };
  double title_px = text;
  std::vector<std::string> title_lines = titleIn(title_px);
  if (wrapShortened(title_lines, chart.title)) {
    title_px = small;
    title_lines = titleIn(title_px);
  }
  const double title_step = std::round(frame::kLineSpacing * title_px);
  double header_h = double(title_lines.size()) * title_step;
  std::vector<std::string> note_lines;
  for (const std::string& note : chart.notes) {
    const std::vector<std::string> lines = painter.wrap(note, small, where.width(), 2);
    if (header_h + double(lines.size()) * line > header_room) break;
    note_lines.insert(note_lines.end(), lines.begin(), lines.end());
    header_h += double(lines.size()) * line;
  }
  double y = where.y0;
  // The title and notes from the edge the language starts reading at.
  const double title_x = style.right_to_left ? where.x1 : where.x0;
  const HAlign title_side = style.right_to_left ? HAlign::kRight : HAlign::kLeft;
  for (const std::string& title_line : title_lines) {
    canvas.text(title_line, {title_x, y}, title_px, style.text, title_side, VAlign::kTop);
    y += title_step;
  }
  for (const std::string& note_line : note_lines) {
    canvas.text(note_line, {title_x, y}, small, style.text, title_side, VAlign::kTop);
    y += line;
  }
  canvas.text(painter.fitWhole(chart.y_label, small, where.width()), {where.x0, y}, small,
              style.muted_text, HAlign::kLeft, VAlign::kTop);
  y += y_label_step;

  const double swatch = kLegendSwatch * small, pad = 0.3 * small;
  double labels_w = 0.0;
  for (const frame::ChartSeries& s : chart.series) {
    labels_w = std::max(labels_w, swatch + pad + painter.width(s.label, small));
  }
  frame::PixelRect plot{where.x0, y, where.x1 - labels_w - 1.5 * small, plot_bottom};
  const double y_step = niceStep(y_span * kMinTickSpacing * h / std::max(1.0, plot.height()));
  const double y_first = std::ceil(chart.min.y() / y_step - 1e-9);
  double y_label_w = 0.0;
  for (double k = y_first;
       k * y_step <= chart.max.y() + 1e-9 * y_step && k < y_first + kMaxChartTicks; k += 1.0) {
    y_label_w = std::max(y_label_w, painter.width(tickLabel(k * y_step, style.numbers), small));
  }
  plot.x0 += y_label_w + tick + 0.4 * small;
  if (plot.width() < 4.0 || plot.height() < 4.0) return;

  const auto toPx = [&](const core::Vec2& p) {
    return core::Vec2{plot.x0 + (p.x() - chart.min.x()) / x_span * plot.width(),
                      plot.y1 - (p.y() - chart.min.y()) / y_span * plot.height()};
  };

  // Grid and ticks.
  for (double k = y_first;
       k * y_step <= chart.max.y() + 1e-9 * y_step && k < y_first + kMaxChartTicks; k += 1.0) {
    const double py = toPx({chart.min.x(), k * y_step}).y();
    mesh.addLine({plot.x0, py}, {plot.x1, py}, thin, style.bar_frame);
    mesh.addLine({plot.x0 - tick, py}, {plot.x0, py}, thin, style.track);
    canvas.text(tickLabel(k * y_step, style.numbers), {plot.x0 - tick - 0.4 * small, py}, small,
                style.muted_text, HAlign::kRight, VAlign::kMiddle);
  }
  const double x_step = niceStep(x_span * kMinTickSpacing * 1.6 * h / plot.width());
  const double x_first = std::ceil(chart.min.x() / x_step - 1e-9);
  for (double k = x_first;
       k * x_step <= chart.max.x() + 1e-9 * x_step && k < x_first + kMaxChartTicks; k += 1.0) {
    const double px = toPx({k * x_step, chart.min.y()}).x();
    mesh.addLine({px, plot.y0}, {px, plot.y1}, thin, style.bar_frame);
    mesh.addLine({px, plot.y1}, {px, plot.y1 + tick}, thin, style.track);
    canvas.text(tickLabel(k * x_step, style.numbers), {px, plot.y1 + tick + 0.2 * small}, small,
                style.muted_text, HAlign::kCenter, VAlign::kTop);
  }
  // Right-aligned under the plot's end, but never out of the chart's own box.
  const std::string x_label = painter.fitWhole(chart.x_label, small, where.width());
  const double x_label_x0 = std::max(where.x0, plot.x1 - painter.width(x_label, small));
  canvas.text(x_label, {x_label_x0, plot.y1 + tick + 0.2 * small + line}, small, style.muted_text,
              HAlign::kLeft, VAlign::kTop);
  mesh.addLine({plot.x0, plot.y0}, {plot.x0, plot.y1}, layout.line_px * 0.6, style.track);
  mesh.addLine({plot.x0, plot.y1}, {plot.x1, plot.y1}, layout.line_px * 0.6, style.track);

  if (chart.cursor_x) {
    const double px = toPx({std::clamp(*chart.cursor_x, chart.min.x(), chart.max.x()), 0.0}).x();
    mesh.addLine({px, plot.y0}, {px, plot.y1}, thin, style.muted_text);
  }

  // Lines, then their labels at the right, spread vertically so none overlap.
  std::vector<double> wanted, heights;
  std::vector<std::size_t> labelled;
  for (std::size_t i = 0; i < chart.series.size(); ++i) {
    const frame::ChartSeries& s = chart.series[i];
    std::vector<core::Vec2> points = visiblePart(s, chart.cursor_x);
    for (core::Vec2& p : points) {
      p = toPx({p.x(), std::clamp(p.y(), chart.min.y(), chart.max.y())});
    }
    mesh.addPolyline(points, layout.line_px, s.color, s.dashed ? kDash * h : 0.0);
    if (points.empty() || s.label.empty()) continue;
    wanted.push_back(points.back().y());
    heights.push_back(line);
    labelled.push_back(i);
  }
  // Beside the plot, down to the tick numbers' line at most: the axis name is under that.
  const std::vector<double> tops =
      frame::spreadIntervals(wanted, heights, 0.0, plot.y0, plot.y1 + tick + 0.2 * small + line);
  for (std::size_t k = 0; k < labelled.size(); ++k) {
    const frame::ChartSeries& s = chart.series[labelled[k]];
    const double x0 = plot.x1 + 0.8 * small, mid = tops[k] + 0.5 * line;
    if (s.dashed) {
      // A dashed line's swatch is two dashes, as the line is drawn.
      const double dash = 0.4 * swatch, half = 0.5 * std::max(layout.line_px, 0.2 * swatch);
      mesh.addRect({x0, mid - half, x0 + dash, mid + half}, s.color);
      mesh.addRect({x0 + swatch - dash, mid - half, x0 + swatch, mid + half}, s.color);
    } else {
      mesh.addRect({x0, mid - 0.5 * swatch, x0 + swatch, mid + 0.5 * swatch}, s.color);
    }
    canvas.text(s.label, {x0 + swatch + pad, mid}, small, style.text, HAlign::kLeft,
                VAlign::kMiddle);
  }
}

}  // namespace collide::render
