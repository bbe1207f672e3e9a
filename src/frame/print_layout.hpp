#pragma once
// A figure of physical size, for print: the pixels its frame is laid out at, how large one of them
// is on the page, and the smallest text legible on paper (printTextFloorPx). The GL renderer, the
// vector painter and compose's label placement all lay the figure out at the PrintFrame below;
// layoutFrame keeps such a figure's labels their lines (printLabelLines, givePrintValuesRoom).
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"

namespace collide::frame {

// The physical size asked for (e.g. 8 cm wide at 300 dpi), already checked.
struct PrintSize {
  // The layout (and PNG) size in pixels, at the printing resolution.
  int width_px = 0;
  int height_px = 0;
  double width_cm = 0.0;       // physical size of the figure; height_cm keeps the frame's aspect
  double height_cm = 0.0;      // exactly (the frame rounds it to whole pixels)
  double dots_per_inch = 0.0;  // the PNG's resolution; the text floor follows it
  double px_per_inch = 0.0;    // layout pixels per inch on a vector page: width_px / width in
                               // inches, so the page is exactly width_cm wide
};

// Where a printed figure is laid out.
struct PrintFrame {
  int width_px = 0;
  int height_px = 0;
  double px_per_inch = 0.0;    // how large a layout pixel is on the page
  double text_floor_px = 0.0;  // smallest text em, pixels (printTextFloorPx of px_per_inch)
};

// A PNG: the print size's pixels at its printing resolution.
PrintFrame rasterPrintFrame(const PrintSize& print);

// A vector figure (SVG, PDF): at least kVectorLayoutPpi pixels per inch, so whole pixels keep its
// page within 0.05 mm of width_cm × height_cm (a PNG's pixels are its DPI's).
inline constexpr double kVectorLayoutPpi = 600.0;
PrintFrame vectorPrintFrame(const PrintSize& print);

// A printed figure whose text the floor enlarged keeps, above each 1D scene's arrows, the lines
// a legend of all the scene's labels needs (in as many columns as fit across the scene, an em
// between columns, as compose arranges it), so no value gives way for want of room; as many as
// compose placed the labels with, where it did (FrameShape::print_label_lines, of layout `l`).
int printLabelLines(const FrameModel& frame, const FrameLayout& l, const text::TextWidth& width);

// The room a printed figure's single 1D panel gives its lines of labels as compose asked
// (PanelModel::print_values_room): sets `shape`'s print_caption_one_line and
// print_info_gives_way.
void givePrintValuesRoom(const FrameModel& frame, FrameShape& shape, int width_px, int height_px,
                         const text::TextWidth& width);

}  // namespace collide::frame
