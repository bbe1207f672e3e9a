// SPDX-License-Identifier: MIT
// Fitting the frame's layout to its text: the title's room, the readouts across or in a side
// column, a grid's column share, the caption's lines (layoutFrame).
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "frame/layout.hpp"
#include "frame/layout_parts.hpp"
#include "frame/mark_sizes.hpp"
#include "frame/print_layout.hpp"
#include "text/text_wrap.hpp"

namespace collide::frame {

namespace {

// What a text's lines are counted from: its pattern for the shot (PanelModel::info_pattern),
// which the painter breaks it like, else the text itself.
std::string_view wrappedAs(std::string_view text, std::string_view pattern) {
  return pattern.empty() ? text : pattern;
}

// The lines the info takes at a size and width, counted from its pattern: once per video and
// size where the video's patterns are set (PanelModel::info_widest).
std::size_t infoLines(const PanelModel& panel, double size_px, double width_px,
                      const text::TextWidth& width) {
  if (panel.info_widest) return panel.info_widest->lines(size_px, width_px, width);
  return text::wrapText(wrappedAs(panel.info, panel.info_pattern), size_px, width_px, width).size();
}

// Room for the title left of the time readout, as drawHeader leaves it. A video's slow-motion
// subtitle takes what the title leaves (drawHeader): it never changes the layout, so a still at
// t, which shows no subtitle, is the video's frame at t.
double titleRoom(const FrameModel& frame, const FrameLayout& l, const text::TextWidth& width) {
  double right = l.header.x1;
  if (!frame.time_readout.empty()) right -= width(frame.time_readout, l.title_px);
  return right - l.text_px - l.header.x0;
}

// Whether every panel's heading, info line and bar labels fit across `column_w`; sets the rows
// the labels need.
bool readoutsFitAcross(const FrameModel& frame, FrameShape& shape, const FrameLayout& l,
                       double column_w, const text::TextWidth& width) {
  const double small = l.small_px;
  shape.bar_label_rows = 1;
  shape.info_lines = 1;
  bool fits = true;
  for (const PanelModel& panel : frame.panels) {
    const double heading_w = panel.heading.empty() ? 0.0 : width(panel.heading, l.text_px);
    if (shape.grid_heading_one_line) {
      const double info_w = panel.info.empty() ? 0.0 : l.text_px + width(panel.info, l.text_px);
      fits = fits && heading_w + info_w <= column_w;
    } else if (shape.grid_stacked) {
      // Under the heading, the info may take two lines.
      const std::size_t lines = infoLines(panel, small, column_w, width);
      shape.info_lines = std::max(shape.info_lines, std::min(2, static_cast<int>(lines)));
      fits = fits && heading_w <= column_w;
    } else {
      fits = fits && heading_w <= column_w &&
             width(wrappedAs(panel.info, panel.info_pattern), small) <= column_w;
    }
    if (!panel.show_energy_bar) continue;
    const std::vector<double> widths = barLabelWidths(panel.energy_bar, small, width);
    for (double w : widths) fits = fits && w <= column_w;
    shape.bar_label_rows =
        std::max(shape.bar_label_rows, barLabelRows(widths, barLabelSlots(panel.energy_bar), small,
                                                    column_w, frame.style.right_to_left));
  }
  return fits;
}

// Whether every panel's caption takes no more lines at its column's width than `shape` gives it
// (FrameShape::grid_captions; true without them).
bool gridCaptionsFit(const FrameModel& frame, const FrameShape& shape, int width_px, int height_px,
                     const text::TextWidth& width) {
  if (!shape.grid_captions) return true;
  const FrameLayout l = computeFrameLayout(width_px, height_px, shape);
  for (std::size_t p = 0; p < frame.panels.size() && p < l.panels.size(); ++p) {
    const PanelLayout& where = l.panels[p];
    const std::string& caption = frame.panels[p].caption;
    if (caption.empty()) continue;
    const std::size_t lines =
        text::wrapText(caption, l.small_px, where.caption.width(), width).size();
    if (lines > static_cast<std::size_t>(std::max(0, where.caption_lines))) return false;
  }
  return true;
}

// A comparison grid's arrangement: readouts in a column right of each scene, the narrowest
// column whose label rows fit across it and whose readouts fit in the cell's height (heading and
// info share a line only where they must); where no column fits (a small printed figure), the
// panels side by side, each with its bar under its scene.
void fitGrid(const FrameModel& frame, FrameShape& shape, int width_px, int height_px,
             const text::TextWidth& width) {
  const FrameLayout l = computeFrameLayout(width_px, height_px, shape);
  const PixelRect& cell = l.panels.front().cell;
  // A strobe's captions (FrameShape::grid_captions) take a wider column where the narrowest
  // that holds the readouts would cut them; where none holds them whole, the narrowest does.
  std::optional<FrameShape> narrowest;
  for (double share : {0.34, 0.42, 0.5, 0.58, 0.66}) {
    const double column_w = cell.x1 - std::round(cell.x1 - share * cell.width());
    for (bool one_line : {false, true}) {
      shape.grid_column_share = share;
      shape.grid_heading_one_line = one_line;
      if (readoutsFitAcross(frame, shape, l, column_w, width) &&
          gridColumnHeight(l, shape) <= cell.height()) {
        if (!narrowest) narrowest = shape;
        if (gridCaptionsFit(frame, shape, width_px, height_px, width)) return;
        break;
      }
    }
  }
  if (narrowest) {
    shape = *narrowest;
    return;
  }
  shape.grid_stacked = true;
  const double stacked_w =
      computeFrameLayout(width_px, height_px, shape).panels.front().cell.width();
  for (bool one_line : {false, true}) {
    shape.grid_heading_one_line = one_line;
    const bool across = readoutsFitAcross(frame, shape, l, stacked_w, width);
    // Room left for the scene: three lines of text (a readout, the bodies, their labels).
    const FrameLayout side = computeFrameLayout(width_px, height_px, shape);
    if (across && side.panels.front().scene.height() >= 3.0 * kLineSpacing * side.text_px) return;
  }
  shape.grid_heading_one_line = false;
  static_cast<void>(readoutsFitAcross(frame, shape, l, stacked_w, width));
}

// The most caption lines a side column holds above its foot (the momentum diagram, if any), at
// least 1: the rest of a longer caption gives way.
int sideCaptionRoom(const FrameShape& shape, int width_px, int height_px) {
  FrameShape one = shape;
  one.caption_lines = 1;
  const FrameLayout l = computeFrameLayout(width_px, height_px, one);
  const PanelLayout& p = l.panel();
  const double foot = p.momentum.height() > 0.0 ? p.momentum.y0 - l.gap_px : p.cell.y1;
  const double line = p.scale_row.height();
  const int room = static_cast<int>(std::floor((foot - p.scale_row.y1) / line + 1e-9)) + 1;
  return std::max(room, 1);
}

// The most lines the caption of any shape takes at a size (the widest among them; counted once
// per size and width), else those of the widest, or of the caption itself.
std::size_t captionLinesAt(const PanelModel& panel, double size_px, double caption_w,
                           double scale_room, const text::TextWidth& width) {
  return panel.caption_shapes
             ? panel.caption_shapes->captionLines(size_px, caption_w, scale_room, width)
             : text::captionLinesBesideScale(wrappedAs(panel.caption, panel.caption_pattern),
                                             size_px, caption_w, scale_room, width)
                   .size();
}

// A single panel's text rows: the bar's label rows, the caption's lines (the scale arrow at the
// last one's end) and the info's lines, as `shape` lays the panel out. Returns whether a side
// column holds its caption whole: in the lines left under the bar's labels (their rows and a
// staircase's band counted), at its size or shrunk down to kTextShrinkFloor of it, as the
// painter draws it (a stacked panel's caption: true).
bool fitSinglePanel(const FrameModel& frame, FrameShape& shape, int width_px, int height_px,
                    const text::TextWidth& width) {
  const FrameLayout l = computeFrameLayout(width_px, height_px, shape);
  const PanelModel& panel = frame.panels.front();
  const PanelLayout& where = l.panel();
  const bool side = shape.side_column_share > 0.0;
  if (panel.show_energy_bar) {
    shape.bar_label_rows = barLabelRows(barLabelWidths(panel.energy_bar, l.small_px, width),
                                        barLabelSlots(panel.energy_bar), l.small_px,
                                        where.bar_outer.width(), frame.style.right_to_left);
  }
  const bool small = side || where.info_small;
  const double heading_w =
      panel.heading.empty() || small ? 0.0 : width(panel.heading, l.text_px) + l.text_px;
  const std::size_t info_lines =
      infoLines(panel, small ? l.small_px : l.text_px, where.info.width() - heading_w, width);
  shape.info_lines = std::clamp(static_cast<int>(info_lines), 1, side ? kSideMostInfoLines : 2);
  // A side column's scale arrow has a row of its own, not the caption's end.
  const double scale_room = side ? 0.0 : captionScaleRoomPx(panel, where, l, width);
  const std::size_t lines =
      captionLinesAt(panel, l.small_px, where.caption.width(), scale_room, width);
  if (!side) {
    shape.caption_lines = std::clamp(static_cast<int>(lines), 1, 2);
    return true;
  }
  const int room = sideCaptionRoom(shape, width_px, height_px);
  shape.caption_lines = std::clamp(static_cast<int>(lines), 1, room);
  if (lines <= static_cast<std::size_t>(room)) return true;
  const double floor_px = std::ceil(kTextShrinkFloor * l.small_px);
  return captionLinesAt(panel, floor_px, where.caption.width(), scale_room, width) <=
         static_cast<std::size_t>(room);
}

// The widths a side column is tried at (chooseSideColumn), in pixels: from the narrowest that
// holds its text, a label em wider each time, to the widest it may take; `cell_w` the panel's.
struct SideWidths {
  double least_w, most_w, step_w, cell_w;
};

// Sets `shape` to `side` at the narrowest of `widths` whose column holds its caption whole
// (fitSinglePanel), else at the narrowest: a wider column wraps the caption in fewer lines and
// its bar's legend in fewer rows, so a caption that the legend's rows leave too few lines is
// re-flowed rather than cut. Only widths that hold the scale arrow and still draw the world at
// `least_px_per_m` or larger; none: `shape` is left as it is (stacked).
void widenForCaption(const FrameModel& frame, FrameShape side, FrameShape& shape,
                     const SideWidths& widths, double least_px_per_m, int width_px, int height_px,
                     const text::TextWidth& width) {
  const PanelModel& panel = frame.panels.front();
  std::optional<FrameShape> narrowest;
  for (double w = widths.least_w; w <= widths.most_w + 1e-9; w += std::max(1.0, widths.step_w)) {
    side.side_column_share = w / widths.cell_w;
    const bool whole = fitSinglePanel(frame, side, width_px, height_px, width);
    const FrameLayout l = computeFrameLayout(width_px, height_px, side);
    const PanelLayout& where = l.panel();
    // A wider column only draws the world smaller.
    if (panelMapping(panel, where, l).px_per_m < least_px_per_m) break;
    if (captionScaleRoomPx(panel, where, l, width) > where.caption.width()) continue;
    if (!narrowest) narrowest = side;
    if (whole) {
      shape = side;
      return;
    }
  }
  if (narrowest) shape = *narrowest;
}

// A plane scene's readouts in a column beside it where that draws its world larger: the scene
// keeps the whole height and the column is as narrow as its text allows. Keeps `shape` stacked
// where the column's text does not fit in it, or where the world would not grow (a scene wider than
// the frame's shape).
void chooseSideColumn(const FrameModel& frame, FrameShape& shape, int width_px, int height_px,
                      const text::TextWidth& width) {
  const PanelModel& panel = frame.panels.front();
  const double view_w = panel.view.max_m.x() - panel.view.min_m.x();
  const double view_h = panel.view.max_m.y() - panel.view.min_m.y();
  if (!(view_w > 0.0 && view_h > 0.0)) return;
  const FrameLayout stacked = computeFrameLayout(width_px, height_px, shape);
  const double stacked_px_per_m = panelMapping(panel, stacked.panel(), stacked).px_per_m;

  FrameShape side = shape;
  side.side_column_share = kSideColumnMostShare;
  const FrameLayout probe = computeFrameLayout(width_px, height_px, side);
  const PixelRect& cell = probe.panel().cell;
  // The narrowest column that holds its text: the scene keeps the rest of the width, so labels
  // have room beside the bodies at the world's edges.
  double least_w = kSideColumnLeastEm * probe.text_px;
  if (panel.show_energy_bar) {
    for (double w : barLabelWidths(panel.energy_bar, probe.small_px, width)) {
      least_w = std::max(least_w, w);
    }
  }
  const double most_w = kSideColumnMostShare * cell.width();
  if (least_w > most_w) return;
  side.side_column_share = least_w / cell.width();
  // The column must hold its text at its longest (a label for every bar segment, each as wide
  // as the widest now, the info at its most lines) with kSideLeastCaptionLines of caption above
  // its foot, so the choice, and the world's scale, stay the same through a video however its
  // texts change.
  FrameShape longest = side;
  longest.info_lines = kSideInfoLines;
  longest.caption_lines = kSideLeastCaptionLines;
  double widest = 0.0;
  if (panel.show_energy_bar) {
    for (double w : barLabelWidths(panel.energy_bar, probe.small_px, width)) {
      widest = std::max(widest, w);
    }
  }
  const std::size_t segments = panel.energy_bar.segments.size();
  longest.bar_label_rows = barLabelRows(std::vector<double>(segments, widest), segments,
                                        probe.small_px, least_w, frame.style.right_to_left);
  const PanelLayout tallest = computeFrameLayout(width_px, height_px, longest).panel();
  const double foot =
      tallest.momentum.height() > 0.0 ? tallest.momentum.y0 - probe.gap_px : tallest.cell.y1;
  if (tallest.scale_row.y1 > foot) return;
  widenForCaption(frame, side, shape, {least_w, most_w, probe.text_px, cell.width()},
                  kSideColumnLeastGain * stacked_px_per_m, width_px, height_px, width);
}

}  // namespace

FrameLayout layoutFrame(const FrameModel& frame, int width_px, int height_px, double text_floor_px,
                        const text::TextWidth& width) {
  FrameShape shape = shapeOf(frame, text_floor_px);
  FrameLayout l = computeFrameLayout(width_px, height_px, shape);
  if (!frame.title.empty() && width(frame.title, l.title_px) > titleRoom(frame, l, width)) {
    shape.title_lines = 2;
    l = computeFrameLayout(width_px, height_px, shape);
    const double room = titleRoom(frame, l, width);
    const std::vector<std::string> lines = text::wrapText(frame.title, l.title_px, room, width);
    if (lines.size() > 2 || width(lines.front(), l.title_px) > room) {
      shape.title_small = true;
      l = computeFrameLayout(width_px, height_px, shape);
    }
  }
  if (l.scale_px > height_px && !l.panels.empty()) {
    shape.print_label_lines = printLabelLines(frame, l, width);
  }
  if (l.panels.size() == 1) {
    // Stacked, the caption takes at most 2 lines (fitSinglePanel); a side column widens for it.
    static_cast<void>(fitSinglePanel(frame, shape, width_px, height_px, width));
    if (frame.panels.front().two_d) {
      chooseSideColumn(frame, shape, width_px, height_px, width);
    } else if (shape.print_label_lines > 0) {
      givePrintValuesRoom(frame, shape, width_px, height_px, width);
    }
  } else if (l.panels.size() > 1) {
    fitGrid(frame, shape, width_px, height_px, width);
  }
  return computeFrameLayout(width_px, height_px, shape);
}

}  // namespace collide::frame
