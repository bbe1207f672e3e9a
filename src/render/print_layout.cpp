#include "render/print_layout.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "render/layout.hpp"

namespace collide::render {
namespace {

constexpr double kCmPerInch = 2.54;

// The texts of `panel`'s labels, mass labels and readouts alike, wherever compose put them, so the
// layout is the same before and after placement.
std::vector<std::string> labelTexts(const PanelModel& panel) {
  std::vector<std::string> texts;
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
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
    const std::vector<std::string> texts = labelTexts(panel);
    if (texts.empty()) continue;
    double widest = 0.0;
    for (const std::string& text : texts) widest = std::max(widest, width(text, l.text_px));
    const double scene_w = l.panels[p].scene.width();
    const std::size_t columns = std::clamp<std::size_t>(
        static_cast<std::size_t>((scene_w + l.text_px) / (widest + l.text_px)), 1, texts.size());
    lines = std::max(lines, static_cast<int>((texts.size() + columns - 1) / columns));
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

}  // namespace collide::render
