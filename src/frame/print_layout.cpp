#include "frame/print_layout.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "frame/layout.hpp"

namespace collide::frame {
namespace {

constexpr double kCmPerInch = 2.54;

// The texts of `panel`'s labels, mass labels and readouts alike, wherever compose put them, so the
// layout is the same before and after placement.
std::vector<std::string> labelTexts(const PanelModel& panel) {
  std::vector<std::string> texts;
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    // Each body's mass before its readout, the order of compose's legend.
    for (const bool mass : {true, false}) {
      std::string text = statedLabel(panel, i, mass);
      if (!text.empty()) texts.push_back(std::move(text));
    }
  }
  return texts;
}

}  // namespace

std::string statedLabel(const PanelModel& panel, std::size_t body, bool mass) {
  const BodyModel& by_body = panel.bodies.at(body);
  std::string text = mass ? by_body.label : by_body.velocity_label;
  if (!text.empty()) return text;
  for (const ReadoutLegend::Entry& entry : panel.legend.entries) {
    if (entry.body != static_cast<int>(body) || entry.mass != mass) continue;
    text += (text.empty() ? "" : " ") + entry.text;
  }
  return text;
}

std::vector<double> legendColumnWidths(const std::vector<double>& widths, std::size_t columns) {
  std::vector<double> column_w(std::max<std::size_t>(columns, 1), 0.0);
  for (std::size_t k = 0; k < widths.size(); ++k) {
    column_w[k % column_w.size()] = std::max(column_w[k % column_w.size()], widths[k]);
  }
  return column_w;
}

PrintFrame rasterPrintFrame(const PrintSize& print) {
  return {print.width_px, print.height_px, print.dots_per_inch,
          printTextFloorPx(print.dots_per_inch)};
}

PrintFrame vectorPrintFrame(const PrintSize& print) {
  if (print.dots_per_inch >= kVectorLayoutPpi) {
    return {print.width_px, print.height_px, print.px_per_inch,
            printTextFloorPx(print.px_per_inch)};
  }
  const int width_px =
      static_cast<int>(std::lround(print.width_cm / kCmPerInch * kVectorLayoutPpi));
  const int height_px =
      static_cast<int>(std::lround(print.height_cm / kCmPerInch * kVectorLayoutPpi));
  // The page is width_cm wide exactly, and height_cm to within half a pixel.
  const double px_per_inch = width_px / (print.width_cm / kCmPerInch);
  return {width_px, height_px, px_per_inch, printTextFloorPx(px_per_inch)};
}

int printLabelLines(const FrameModel& frame, const FrameLayout& l, const text::TextWidth& width) {
  int lines = 0;
  for (std::size_t p = 0; p < frame.panels.size() && p < l.panels.size(); ++p) {
    const PanelModel& panel = frame.panels[p];
    if (panel.two_d) continue;
    if (panel.placed_label_lines >= 0) {
      lines = std::max(lines, panel.placed_label_lines);
      continue;
    }
    std::vector<double> widths;
    for (const std::string& text : labelTexts(panel)) widths.push_back(width(text, l.text_px));
    if (widths.empty()) continue;
    // The most columns that fit across the scene, each as wide as its own widest text.
    std::size_t columns = 1;
    for (std::size_t c = widths.size(); c > 1 && columns == 1; --c) {
      const std::vector<double> column_w = legendColumnWidths(widths, c);
      const double across = std::accumulate(column_w.begin(), column_w.end(), 0.0) +
                            l.text_px * static_cast<double>(c - 1);
      if (across <= l.panels[p].scene.width()) columns = c;
    }
    lines = std::max(lines, static_cast<int>((widths.size() + columns - 1) / columns));
  }
  return lines;
}

void givePrintValuesRoom(const FrameModel& frame, FrameShape& shape, int width_px, int height_px,
                         const text::TextWidth& width) {
  // The caption keeps one line only where at least half of it is left beside the scale
  // arrow, as long as the world it gains draws it (a long scale arrow across a narrow
  // figure would leave it no word).
  const int room = frame.panels.front().print_values_room;
  shape.print_caption_one_line = room >= 1;
  shape.print_info_gives_way = room >= 2;
  const FrameLayout one = computeFrameLayout(width_px, height_px, shape);
  if (captionScaleRoomPx(frame.panels.front(), one.panel(), one, width) >
      0.5 * one.panel().caption.width()) {
    shape.print_caption_one_line = false;
  }
}

}  // namespace collide::frame
