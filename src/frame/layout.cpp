// Which layout a frame gets (stacked, side column, grid) and the sizes of its rows and
// columns; the geometry inside a panel is in frame/panel_geometry.cpp.
#include "frame/layout.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "frame/bar_legend.hpp"
#include "frame/layout_parts.hpp"
#include "frame/mark_sizes.hpp"
#include "frame/print_layout.hpp"
#include "text/text_wrap.hpp"

namespace collide::frame {
namespace {

// Fractions of the frame height. Tuned at 360 px high: margin 11 px, title 18 px, text 15 px,
// small text 12 px, bar 22 px.
constexpr double kMargin = 0.03;  // frame edge to content, between panels
constexpr double kTitle = 0.05;   // title and time readout, em
constexpr double kText = 0.041;   // labels and readouts, em
constexpr double kSmall = 0.034;  // captions, axis numbers, em
constexpr double kGap = 0.012;    // text to what it labels
constexpr double kBarHeight = 0.06, kGridBarHeight = 0.045;  // the energy bar's outer height
constexpr double kBarTick = 0.015;        // bar edge to its labels (the leader ticks)
constexpr double kStairBandLines = 0.75;  // bar edge to a staircase of labels, small lines
// Share of the frame width for the chart column; less where a printed figure's text floor
// enlarged the text (its scene keeps room for its labels' columns).
constexpr double kChartWidth = 0.36, kPrintChartWidth = 0.34;
// The column's share with a long working panel in it (more rows than kShortWorkingRows): its math
// set readable in a classroom (about the captions' size, a worked example's title on one line)
// needs more than a chart; the scene keeps the rest. A short one (the ballistic pendulum's) keeps
// a chart's share, and the scene its labels.
constexpr double kWorkingColumnWidth = 0.47;
constexpr int kShortWorkingRows = 9;
constexpr double kBarFrame = 0.006;    // bar frame thickness
constexpr double kOutline = 0.005;     // body outline thickness
constexpr double kTrack = 0.006;       // track line thickness
constexpr double kLine = 0.005;        // chart lines, trails, ticks
constexpr double kArrowGap = 0.045;    // block top → arrow centre line
constexpr double kArrowShaft = 0.008;  // shaft thickness
constexpr double kArrowHeadLength = 0.035;
constexpr double kArrowHeadWidth = 0.04;

double px(double fraction, double h) {
  return std::max(1.0, std::round(fraction * h));
}

// Line heights of the frame's text and small text, in whole pixels.
double textLine(const FrameLayout& l) {
  return std::round(kLineSpacing * l.text_px);
}
double smallLine(const FrameLayout& l) {
  return std::round(kLineSpacing * l.small_px);
}

// The bar's labels under it: the leaders' ticks, then the rows. A staircase's leaders (more than
// one row: frame/bar_legend.hpp) slant across to their columns above the first row, in a band
// at least kStairBandLines of a line high, so that they stand apart: not in a comparison grid's
// column, whose height sets the grid, nor in a printed figure, whose text the floor enlarged
// (their leaders slant in the ticks' height).
double barLabelsHeight(double h, int rows, double small_line, const FrameShape& shape) {
  const double tick = px(kBarTick, h);
  const bool band = rows > 1 && !(shape.text_floor_px > 0.0);
  return (band ? std::max(tick, std::round(kStairBandLines * small_line)) : tick) +
         rows * small_line;
}

// What every panel layout starts from: its cell, and the rows its bar's labels need (at least one).
PanelLayout panelIn(const PixelRect& cell, const FrameShape& shape) {
  PanelLayout panel;
  panel.cell = cell;
  panel.bar_label_rows = std::max(1, shape.bar_label_rows);
  if (shape.print_label_lines > 0) {
    panel.label_lines_above = shape.print_label_lines;
    panel.label_lines_below = 0;
  }
  return panel;
}

// The energy bar with whole-pixel edges, from its outer top-left and size.
void placeBar(PanelLayout& panel, double x0, double y0, double x1, double height, double frame) {
  panel.bar_outer = {std::round(x0), std::round(y0), std::round(std::max(x1, x0 + 3.0)),
                     std::round(y0) + height};
  panel.bar_inner = {panel.bar_outer.x0 + frame, panel.bar_outer.y0 + frame,
                     panel.bar_outer.x1 - frame, panel.bar_outer.y1 - frame};
}

// Single panel: heading line, scene, bar, labels, caption stacked top to bottom.
PanelLayout stackedPanel(const PixelRect& cell, const FrameLayout& l, const FrameShape& shape,
                         double margin) {
  const double h = l.scale_px;
  PanelLayout panel = panelIn(cell, shape);
  // A grid's panels show no caption (the alt text describes each).
  panel.caption_lines = shape.panels > 1               ? 0
                        : shape.print_caption_one_line ? 1
                                                       : std::max(1, shape.caption_lines);
  const double text_line = textLine(l);
  const double small_line = smallLine(l);
  panel.info_lines = shape.print_info_gives_way ? 0 : std::clamp(shape.info_lines, 1, 2);
  panel.info_small = shape.panels == 1 && shape.print_label_lines > 0;
  if (panel.info_small) {
    // The heading's line if any, the info's small lines under it.
    panel.heading = {cell.x0, cell.y0, cell.x1, cell.y0 + (shape.headings ? text_line : 0.0)};
    panel.info = {cell.x0, panel.heading.y1, cell.x1,
                  panel.heading.y1 + panel.info_lines * small_line};
  } else if (shape.panels > 1 && !shape.grid_heading_one_line) {
    panel.heading = {cell.x0, cell.y0, cell.x1, cell.y0 + text_line};
    panel.info = {cell.x0, panel.heading.y1, cell.x1,
                  panel.heading.y1 + panel.info_lines * small_line};
  } else {
    // Heading and info on one line (the info's second line, if any, under it).
    panel.heading = {cell.x0, cell.y0, cell.x1, cell.y0 + panel.info_lines * text_line};
    panel.info = panel.heading;
  }
  panel.caption = {cell.x0, cell.y1 - panel.caption_lines * small_line, cell.x1, cell.y1};
  const double labels_h =
      shape.energy_bar ? barLabelsHeight(h, panel.bar_label_rows, small_line, shape) : 0.0;
  panel.bar_labels = {cell.x0, panel.caption.y0 - labels_h, cell.x1, panel.caption.y0};
  const double bar_h = shape.energy_bar ? std::max(3.0, px(kBarHeight, h)) : 0.0;
  placeBar(panel, cell.x0, panel.bar_labels.y0 - bar_h, cell.x1, bar_h, l.bar_frame_px);
  panel.scene = {cell.x0, panel.info.y1, cell.x1,
                 std::max(panel.info.y1, panel.bar_outer.y0 - margin)};
  return panel;
}

// A plane scene's single panel in a wide frame: the scene on the left at the whole height, the
// readouts top-down in a column on the right (heading if any, info lines, bar, label rows,
// caption, the scale arrow's row).
PanelLayout sidePanel(const PixelRect& cell, const FrameLayout& l, const FrameShape& shape,
                      double margin) {
  const double h = l.scale_px;
  PanelLayout panel = panelIn(cell, shape);
  panel.caption_lines = std::max(1, shape.caption_lines);
  panel.info_lines = std::clamp(shape.info_lines, 1, kSideMostInfoLines);
  const double column_x0 = std::round(cell.x1 - shape.side_column_share * cell.width());
  const double text_line = textLine(l);
  const double small_line = smallLine(l);
  // The info under the heading (a zero-height heading where there is none), in small lines.
  panel.heading = {column_x0, cell.y0, cell.x1, cell.y0 + (shape.headings ? text_line : 0.0)};
  panel.info = {column_x0, panel.heading.y1, cell.x1,
                panel.heading.y1 + panel.info_lines * small_line};
  const double bar_h = shape.energy_bar ? std::max(3.0, px(kBarHeight, h)) : 0.0;
  placeBar(panel, column_x0, panel.info.y1 + (shape.energy_bar ? l.gap_px : 0.0), cell.x1, bar_h,
           l.bar_frame_px);
  const double labels_h =
      shape.energy_bar ? barLabelsHeight(h, panel.bar_label_rows, small_line, shape) : 0.0;
  panel.bar_labels = {column_x0, panel.bar_outer.y1, cell.x1, panel.bar_outer.y1 + labels_h};
  const double caption_y0 = panel.bar_labels.y1 + l.gap_px;
  panel.caption = {column_x0, caption_y0, cell.x1, caption_y0 + panel.caption_lines * small_line};
  panel.scale_row = {column_x0, panel.caption.y1, cell.x1, panel.caption.y1 + small_line};
  if (shape.momentum) {
    // A square at the column's foot, as wide as the column (at most kInsetSize of the scale):
    // it stays put while the caption above it changes its number of lines.
    const double side = std::round(std::min(kInsetSize * h, cell.x1 - column_x0));
    panel.momentum = {cell.x1 - side, cell.y1 - side, cell.x1, cell.y1};
  }
  panel.scene = {cell.x0, cell.y0, std::max(cell.x0, column_x0 - margin), cell.y1};
  return panel;
}

// Comparison grid cell: scene on the left, readouts in a column on the right (heading, info
// line, bar, label rows; heading and info share a line where the cell is short).
PanelLayout gridPanel(const PixelRect& cell, const FrameLayout& l, const FrameShape& shape,
                      double margin) {
  const double h = l.scale_px;
  PanelLayout panel = panelIn(cell, shape);
  panel.caption_lines = 0;
  const double column_x0 = std::round(cell.x1 - shape.grid_column_share * cell.width());
  const double text_line = textLine(l);
  const double small_line = smallLine(l);
  panel.heading = {column_x0, cell.y0, cell.x1, cell.y0 + text_line};
  panel.info = shape.grid_heading_one_line
                   ? panel.heading
                   : PixelRect{column_x0, panel.heading.y1, cell.x1, panel.heading.y1 + small_line};
  const double bar_h = std::max(3.0, px(kGridBarHeight, h));
  placeBar(panel, column_x0, panel.info.y1 + l.gap_px, cell.x1, bar_h, l.bar_frame_px);
  panel.bar_labels = {column_x0, panel.bar_outer.y1, cell.x1,
                      panel.bar_outer.y1 + px(kBarTick, h) + panel.bar_label_rows * small_line};
  panel.caption = {column_x0, panel.bar_labels.y1, cell.x1, panel.bar_labels.y1};
  if (shape.grid_captions && !shape.energy_bar) {
    // No bar: the caption takes the whole lines left under the info.
    const double y0 = panel.info.y1 + l.gap_px;
    panel.caption_lines = std::max(0, static_cast<int>(std::floor((cell.y1 - y0) / small_line)));
    panel.caption = {column_x0, y0, cell.x1, y0 + panel.caption_lines * small_line};
  }
  panel.scene = {cell.x0, cell.y0, std::max(cell.x0, column_x0 - margin), cell.y1};
  return panel;
}

}  // namespace

// Height of a grid cell's readout column.
double gridColumnHeight(const FrameLayout& l, const FrameShape& shape) {
  const double text_line = textLine(l);
  const double small_line = smallLine(l);
  return text_line + (shape.grid_heading_one_line ? 0.0 : small_line) + l.gap_px +
         std::max(3.0, px(kGridBarHeight, l.scale_px)) + px(kBarTick, l.scale_px) +
         shape.bar_label_rows * small_line;
}

bool barLabelsInSlots(const std::vector<double>& widths, std::size_t slots, double size_px,
                      double row_width) {
  if (widths.empty() || slots == 0) return true;
  const double widest = *std::max_element(widths.begin(), widths.end()) + kBarGrowEm * size_px;
  const double count = static_cast<double>(slots);
  return count * widest + (count - 1.0) * kBarGapEm * size_px <= row_width;
}

int barLabelRows(const std::vector<double>& widths, std::size_t slots, double size_px,
                 double row_width, bool right_to_left) {
  if (barLabelsInSlots(widths, slots, size_px, row_width)) return 1;
  // A staircase in reading order: mirrored where read from the right (draw_bar.cpp).
  std::vector<double> reading = widths;
  if (right_to_left) std::reverse(reading.begin(), reading.end());
  return barStaircase(reading, size_px, kBarSwatchEm * size_px, 0.0, row_width).rows;
}

std::size_t barLabelSlots(const EnergyBar& bar) {
  return static_cast<std::size_t>(std::count_if(bar.segments.begin(), bar.segments.end(),
                                                [](const EnergySegment& s) { return s.has_slot; }));
}

std::size_t barLabelSlot(const EnergyBar& bar, std::size_t segment) {
  std::size_t slot = 0;
  for (std::size_t k = 0; k < segment && k < bar.segments.size(); ++k) {
    if (bar.segments[k].has_slot) ++slot;
  }
  return slot;
}

std::vector<double> barLabelWidths(const EnergyBar& bar, double size_px,
                                   const text::TextWidth& width) {
  std::vector<double> out;
  for (const EnergySegment& segment : bar.segments) {
    const std::string& room = barLabelRoom(segment);
    if (room.empty() || !segment.has_slot) continue;
    out.push_back((kBarSwatchEm + kBarPadEm) * size_px + width(room, size_px));
  }
  return out;
}

const std::string& barLabelRoom(const EnergySegment& segment) {
  return segment.label_room.empty() ? segment.label : segment.label_room;
}

namespace {

// About the rows a working panel sets (render/draw/draw_working.cpp): the given values two to a
// row, the results the lines above already end in left out, headings not counted. 0: a chart's.
double workingColumnShare(const WorkingModel& working) {
  int rows = 0, given = 0;
  for (const WorkingLine& line : working.lines) {
    if (line.sides.empty() || line.part == WorkingPart::kRepeatedResult) continue;
    if (line.part == WorkingPart::kGiven) {
      ++given;
    } else {
      ++rows;
    }
  }
  rows += (given + 1) / 2;
  return rows > kShortWorkingRows ? kWorkingColumnWidth : 0.0;
}

}  // namespace

FrameShape shapeOf(const FrameModel& frame, double text_floor_px) {
  FrameShape shape{static_cast<int>(frame.panels.size()), std::max(1, frame.panel_columns),
                   static_cast<int>(frame.charts.size() + (frame.working ? 1 : 0)),
                   std::max(1.0, frame.style.line_scale), std::max(0.0, text_floor_px)};
  shape.momentum = std::any_of(frame.panels.begin(), frame.panels.end(),
                               [](const PanelModel& panel) { return panel.momentum.has_value(); });
  shape.headings = std::any_of(frame.panels.begin(), frame.panels.end(),
                               [](const PanelModel& panel) { return !panel.heading.empty(); });
  if (frame.working) shape.working_share = workingColumnShare(*frame.working);
  shape.energy_bar = std::any_of(frame.panels.begin(), frame.panels.end(),
                                 [](const PanelModel& panel) { return panel.show_energy_bar; });
  shape.grid_captions =
      !shape.energy_bar &&
      std::any_of(frame.panels.begin(), frame.panels.end(), [](const PanelModel& panel) {
        return !panel.ghosts.empty() && !panel.caption.empty();
      });
  return shape;
}

double printTextFloorPx(double dots_per_inch) {
  return dots_per_inch > 0.0 ? kPrintTextFloor_pt / 72.0 * dots_per_inch : 0.0;
}

FrameLayout computeFrameLayout(int width_px, int height_px, const FrameShape& shape) {
  COLLIDE_ASSERT(width_px > 0 && height_px > 0, "frame size must be positive");
  COLLIDE_ASSERT(shape.panels >= 0 && shape.columns >= 1 && shape.charts >= 0, "bad frame shape");
  const double h = height_px, w = width_px;
  // Sizes are fractions of this length: the frame height, or more where text would fall below
  // the floor a printed figure asks for.
  const double unit = std::max(h, shape.text_floor_px / kText);
  const double s = std::max(1.0, shape.line_scale);
  FrameLayout l;
  l.width_px = width_px;
  l.height_px = height_px;
  l.scale_px = unit;
  l.title_px = shape.title_small ? px(kText, unit) : px(kTitle, unit);
  l.text_px = px(kText, unit);
  l.small_px = px(kSmall, unit);
  l.gap_px = px(kGap, unit);
  l.bar_frame_px = std::max(1.0, std::round(kBarFrame * unit));
  l.outline_px = s * kOutline * unit;
  l.track_px = s * kTrack * unit;
  l.line_px = s * kLine * unit;
  l.arrow_gap_px = kArrowGap * unit;
  l.arrow_shaft_px = s * kArrowShaft * unit;
  l.arrow_head_length_px = s * kArrowHeadLength * unit;
  l.arrow_head_width_px = s * kArrowHeadWidth * unit;

  const double margin = std::round(kMargin * unit);
  l.title_lines = std::clamp(shape.title_lines, 1, 2);
  l.header = {margin, margin, w - margin,
              margin + l.title_lines * std::round(kLineSpacing * l.title_px)};
  const PixelRect body{margin, l.header.y1, std::max(margin + 1.0, w - margin),
                       std::max(l.header.y1 + 1.0, h - margin)};

  // Charts take a column on the right, or everything when there is no panel.
  double panels_x1 = body.x1;
  if (shape.charts > 0) {
    const double share = shape.working_share > 0.0 ? shape.working_share
                         : unit > h                ? kPrintChartWidth
                                                   : kChartWidth;
    const double chart_x0 = shape.panels > 0 ? std::round(body.x1 - share * body.width()) : body.x0;
    panels_x1 = chart_x0 - margin;
    const double chart_h = (body.height() - margin * (shape.charts - 1)) / shape.charts;
    for (int i = 0; i < shape.charts; ++i) {
      const double y0 = std::round(body.y0 + i * (chart_h + margin));
      l.charts.push_back({chart_x0, y0, body.x1, std::round(y0 + chart_h)});
    }
  }
  if (shape.panels == 0) return l;

  const int columns = shape.grid_stacked ? shape.panels : std::min(shape.columns, shape.panels);
  const int rows = (shape.panels + columns - 1) / columns;
  const double cell_w = (panels_x1 - body.x0 - margin * (columns - 1)) / columns;
  const double cell_h = (body.height() - margin * (rows - 1)) / rows;
  for (int i = 0; i < shape.panels; ++i) {
    const int row = i / columns, column = i % columns;
    const double x0 = std::round(body.x0 + column * (cell_w + margin));
    const double y0 = std::round(body.y0 + row * (cell_h + margin));
    const PixelRect cell{x0, y0, std::round(x0 + cell_w), std::round(y0 + cell_h)};
    PanelLayout panel =
        shape.panels == 1 && shape.side_column_share > 0.0 ? sidePanel(cell, l, shape, margin)
        : shape.panels == 1 || shape.grid_stacked          ? stackedPanel(cell, l, shape, margin)
                                                           : gridPanel(cell, l, shape, margin);
    // World things may stray into the margins (an arrow above a tall body) but never onto the
    // readouts or a neighbouring panel.
    const double half = 0.5 * margin;
    panel.world_clip = {panel.scene.x0 - half, panel.scene.y0, panel.scene.x1 + half,
                        std::round(panel.scene.y1 + (shape.panels == 1 ? half : 0.0))};
    l.panels.push_back(panel);
  }
  return l;
}

}  // namespace collide::frame
