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

// The ticks along one axis: k * step for k from `first`, up to the axis's end (at most
// kMaxChartTicks).
struct Ticks {
  double step = 0.0, first = 0.0;
  template <class Visit>
  void forEach(double max, Visit&& visit) const {
    for (double k = first; k * step <= max + 1e-9 * step && k < first + kMaxChartTicks; k += 1.0) {
      visit(k * step);
    }
  }
};

// One chart drawn into `where`: the header (title, notes, the y axis's name), the axes with their
// grid, ticks and names, then the lines with their labels at the right.
class ChartDrawing {
 public:
  ChartDrawing(const frame::ChartModel& chart, const frame::FrameStyle& style,
               const frame::PixelRect& where, const frame::FrameLayout& layout, Canvas& canvas)
      : chart_(chart),
        style_(style),
        where_(where),
        layout_(layout),
        canvas_(canvas),
        mesh_(canvas.shapes()),
        painter_(canvas.painter()),
        h_(layout.scale_px),
        small_(layout.small_px),
        line_(std::round(1.3 * small_)),
        tick_(kTick * h_),
        thin_(0.4 * layout.line_px),
        swatch_(kLegendSwatch * small_),
        pad_(0.3 * small_) {}

  void draw() {
    // Under the plot: the tick numbers' line, then the axis name's whole line (its descender too).
    const double name_h = painter_.ascender(small_) + painter_.descender(small_);
    const double plot_bottom = where_.y1 - tick_ - 0.2 * small_ - line_ - name_h;
    const double y = drawHeader(plot_bottom);
    plot_ = {where_.x0, y, where_.x1 - labelsWidth() - 1.5 * small_, plot_bottom};
    y_ticks_.step = niceStep(ySpan() * kMinTickSpacing * h_ / std::max(1.0, plot_.height()));
    y_ticks_.first = std::ceil(chart_.min.y() / y_ticks_.step - 1e-9);
    double y_label_w = 0.0;
    y_ticks_.forEach(chart_.max.y(), [&](double value) {
      y_label_w = std::max(y_label_w, painter_.width(tickLabel(value, style_.numbers), small_));
    });
    plot_.x0 += y_label_w + tick_ + 0.4 * small_;
    if (plot_.width() < 4.0 || plot_.height() < 4.0) return;
    drawAxes();
    drawSeries();
  }

 private:
  double xSpan() const { return chart_.max.x() - chart_.min.x(); }
  double ySpan() const { return chart_.max.y() - chart_.min.y(); }
  core::Vec2 toPx(const core::Vec2& p) const {
    return core::Vec2{plot_.x0 + (p.x() - chart_.min.x()) / xSpan() * plot_.width(),
                      plot_.y1 - (p.y() - chart_.min.y()) / ySpan() * plot_.height()};
  }

  // The title wrapped at size_px onto as many lines as `header_room` holds (up to
  // kMaxChartTitleLines).
  std::vector<std::string> titleIn(double size_px, double header_room) const {
    const double step = std::round(frame::kLineSpacing * size_px);
    const int most = std::clamp(int(std::floor(header_room / step + 1e-9)), 1, kMaxChartTitleLines);
    return painter_.wrap(chart_.title, size_px, where_.width(), most);
  }

  // Above the plot: the title, its notes, the y axis's name; tick labels left and below; line
  // labels right. The header is as tall as its text, while the plot keeps kMinPlotLines small
  // lines (more where more line labels stand beside it: all must fit). The title wraps onto as
  // many lines as the chart's width needs, in small text where the large would not fit whole;
  // only what still does not fit is cut (with an ellipsis). Each note then takes up to two small
  // lines; the notes that do not fit give way, the last first. Returns the plot's top.
  double drawHeader(double plot_bottom) {
    const double y_label_step = line_ + 0.5 * small_;
    // The line labels beside the plot reach down to the tick numbers' line, one line below it.
    const double least_plot = std::max(kMinPlotLines, double(chart_.series.size()) - 1.0) * line_;
    const double header_room = plot_bottom - where_.y0 - y_label_step - least_plot;
    double title_px = layout_.text_px;
    std::vector<std::string> title_lines = titleIn(title_px, header_room);
    if (wrapShortened(title_lines, chart_.title)) {
      title_px = small_;
      title_lines = titleIn(title_px, header_room);
    }
    const double title_step = std::round(frame::kLineSpacing * title_px);
    double header_h = double(title_lines.size()) * title_step;
    std::vector<std::string> note_lines;
    for (const std::string& note : chart_.notes) {
      const std::vector<std::string> lines = painter_.wrap(note, small_, where_.width(), 2);
      if (header_h + double(lines.size()) * line_ > header_room) break;
      note_lines.insert(note_lines.end(), lines.begin(), lines.end());
      header_h += double(lines.size()) * line_;
    }
    double y = where_.y0;
    // The title and notes from the edge the language starts reading at.
    const double title_x = style_.right_to_left ? where_.x1 : where_.x0;
    const HAlign title_side = style_.right_to_left ? HAlign::kRight : HAlign::kLeft;
    for (const std::string& title_line : title_lines) {
      canvas_.text(title_line, {title_x, y}, title_px, style_.text, title_side, VAlign::kTop);
      y += title_step;
    }
    for (const std::string& note_line : note_lines) {
      canvas_.text(note_line, {title_x, y}, small_, style_.text, title_side, VAlign::kTop);
      y += line_;
    }
    canvas_.text(painter_.fitWhole(chart_.y_label, small_, where_.width()), {where_.x0, y}, small_,
                 style_.muted_text, HAlign::kLeft, VAlign::kTop);
    return y + y_label_step;
  }

  // The width of the line labels beside the plot, swatch included.
  double labelsWidth() const {
    double labels_w = 0.0;
    for (const frame::ChartSeries& s : chart_.series) {
      labels_w = std::max(labels_w, swatch_ + pad_ + painter_.width(s.label, small_));
    }
    return labels_w;
  }

  // Grid and ticks, the x axis's name, the axes and the cursor.
  void drawAxes() {
    y_ticks_.forEach(chart_.max.y(), [&](double value) {
      const double py = toPx({chart_.min.x(), value}).y();
      mesh_.addLine({plot_.x0, py}, {plot_.x1, py}, thin_, style_.bar_frame);
      mesh_.addLine({plot_.x0 - tick_, py}, {plot_.x0, py}, thin_, style_.track);
      canvas_.text(tickLabel(value, style_.numbers), {plot_.x0 - tick_ - 0.4 * small_, py}, small_,
                   style_.muted_text, HAlign::kRight, VAlign::kMiddle);
    });
    Ticks x_ticks;
    x_ticks.step = niceStep(xSpan() * kMinTickSpacing * 1.6 * h_ / plot_.width());
    x_ticks.first = std::ceil(chart_.min.x() / x_ticks.step - 1e-9);
    x_ticks.forEach(chart_.max.x(), [&](double value) {
      const double px = toPx({value, chart_.min.y()}).x();
      mesh_.addLine({px, plot_.y0}, {px, plot_.y1}, thin_, style_.bar_frame);
      mesh_.addLine({px, plot_.y1}, {px, plot_.y1 + tick_}, thin_, style_.track);
      canvas_.text(tickLabel(value, style_.numbers), {px, plot_.y1 + tick_ + 0.2 * small_}, small_,
                   style_.muted_text, HAlign::kCenter, VAlign::kTop);
    });
    // Right-aligned under the plot's end, but never out of the chart's own box.
    const std::string x_label = painter_.fitWhole(chart_.x_label, small_, where_.width());
    const double x_label_x0 = std::max(where_.x0, plot_.x1 - painter_.width(x_label, small_));
    canvas_.text(x_label, {x_label_x0, plot_.y1 + tick_ + 0.2 * small_ + line_}, small_,
                 style_.muted_text, HAlign::kLeft, VAlign::kTop);
    mesh_.addLine({plot_.x0, plot_.y0}, {plot_.x0, plot_.y1}, layout_.line_px * 0.6, style_.track);
    mesh_.addLine({plot_.x0, plot_.y1}, {plot_.x1, plot_.y1}, layout_.line_px * 0.6, style_.track);
    if (chart_.cursor_x) {
      const double px =
          toPx({std::clamp(*chart_.cursor_x, chart_.min.x(), chart_.max.x()), 0.0}).x();
      mesh_.addLine({px, plot_.y0}, {px, plot_.y1}, thin_, style_.muted_text);
    }
  }

  // Lines, then their labels at the right, spread vertically so none overlap.
  void drawSeries() {
    std::vector<double> wanted, heights;
    std::vector<std::size_t> labelled;
    for (std::size_t i = 0; i < chart_.series.size(); ++i) {
      const frame::ChartSeries& s = chart_.series[i];
      std::vector<core::Vec2> points = visiblePart(s, chart_.cursor_x);
      for (core::Vec2& p : points) {
        p = toPx({p.x(), std::clamp(p.y(), chart_.min.y(), chart_.max.y())});
      }
      mesh_.addPolyline(points, layout_.line_px, s.color, s.dashed ? kDash * h_ : 0.0);
      if (points.empty() || s.label.empty()) continue;
      wanted.push_back(points.back().y());
      heights.push_back(line_);
      labelled.push_back(i);
    }
    // Beside the plot, down to the tick numbers' line at most: the axis name is under that.
    const std::vector<double> tops = frame::spreadIntervals(
        wanted, heights, 0.0, plot_.y0, plot_.y1 + tick_ + 0.2 * small_ + line_);
    for (std::size_t k = 0; k < labelled.size(); ++k) {
      drawSeriesLabel(chart_.series[labelled[k]], tops[k] + 0.5 * line_);
    }
  }

  // A line's label with its swatch, centred on `mid`.
  void drawSeriesLabel(const frame::ChartSeries& s, double mid) {
    const double x0 = plot_.x1 + 0.8 * small_;
    if (s.dashed) {
      // A dashed line's swatch is two dashes, as the line is drawn.
      const double dash = 0.4 * swatch_, half = 0.5 * std::max(layout_.line_px, 0.2 * swatch_);
      mesh_.addRect({x0, mid - half, x0 + dash, mid + half}, s.color);
      mesh_.addRect({x0 + swatch_ - dash, mid - half, x0 + swatch_, mid + half}, s.color);
    } else {
      mesh_.addRect({x0, mid - 0.5 * swatch_, x0 + swatch_, mid + 0.5 * swatch_}, s.color);
    }
    canvas_.text(s.label, {x0 + swatch_ + pad_, mid}, small_, style_.text, HAlign::kLeft,
                 VAlign::kMiddle);
  }

  const frame::ChartModel& chart_;
  const frame::FrameStyle& style_;
  const frame::PixelRect& where_;
  const frame::FrameLayout& layout_;
  Canvas& canvas_;
  ShapeSink& mesh_;
  TextPainter& painter_;
  // The marks' scale, the small text's size and line, a tick's length, a thin line's width, and
  // a line label's swatch and the pad after it, in pixels.
  const double h_, small_, line_, tick_, thin_, swatch_, pad_;
  frame::PixelRect plot_;
  Ticks y_ticks_;
};

}  // namespace

void drawChart(const frame::ChartModel& chart, const frame::FrameStyle& style,
               const frame::PixelRect& where, const frame::FrameLayout& layout, Canvas& canvas) {
  const double x_span = chart.max.x() - chart.min.x(), y_span = chart.max.y() - chart.min.y();
  if (!(x_span > 0.0) || !(y_span > 0.0)) return;
  ChartDrawing(chart, style, where, layout, canvas).draw();
}

}  // namespace collide::render
