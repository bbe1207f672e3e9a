#pragma once
// Where things go in a frame, in pixels. Public so tests can compute exactly where the renderer
// draws, e.g. the energy bar's segment boundaries.
//
// Pixel coordinates: origin at the top-left corner of the image, x to the right, y downwards, one
// unit per pixel; pixel (i, j) covers [i, i+1) × [j, j+1). Every size is a fraction of the frame
// height, so 640×360 and 3840×2160 show the same picture (to within a pixel of rounding), unless a
// printed figure sets a floor for its text size (FrameShape::text_floor_px).
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/vec.hpp"
#include "frame/frame_model.hpp"
#include "text/text_wrap.hpp"

namespace collide::frame {

// A line of text is this many ems high (the layout's rows and the world area's label room).
inline constexpr double kLineSpacing = 1.3;
// The info line and the caption are drawn down to this share of their size where at their own
// they would cut their text or part a vector from its unit (render's PanelReadouts::shrunkSize;
// a side column's fit counts on it): a fifth smaller still reads.
inline constexpr double kTextShrinkFloor = 0.8;

struct PixelRect {
  double x0 = 0.0, y0 = 0.0;  // top-left corner, pixels
  double x1 = 0.0, y1 = 0.0;  // bottom-right corner, pixels; x1 >= x0, y1 >= y0
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

// How one panel is arranged. A single panel stacks its readouts under the scene, or, a plane
// scene in a wide frame, puts them in a column right of it (the scene keeps the whole height); in
// a comparison grid each panel puts them in a column right of its scene, so the scenes keep their
// height.
struct PanelLayout {
  PixelRect cell;        // the whole panel
  PixelRect heading;     // one text line: the heading, left-aligned
  PixelRect info;        // one text line, right-aligned (the heading's line in a single panel)
  PixelRect scene;       // the world is fitted into this area, minus room for labels
  PixelRect world_clip;  // world things (and their labels) are clipped to this; never the bar
  PixelRect bar_outer;   // outer edge of the energy bar's frame; whole pixels
  PixelRect bar_inner;   // inside of the frame: full_scale_J spans its width; whole pixels
  PixelRect bar_labels;  // segment labels under the bar, bar_label_rows rows
  PixelRect caption;     // caption_lines text lines; empty (zero height) in a comparison grid
  // The scale arrow's own row (a side column's last line); zero height: the arrow goes at the
  // caption's end (or, in a comparison grid, after the heading).
  PixelRect scale_row;
  // The momentum diagram's place in a side column, under its text; zero height: none there
  // (momentumBox says where a panel's diagram goes).
  PixelRect momentum;
  int bar_label_rows = 1;
  int caption_lines = 1;
  int info_lines = 1;  // lines of the info text (a long one wraps); 0: none (it gave way)
  // A 1D scene's lines of text above its arrows (its readouts, or a printed figure's legend:
  // FrameShape::print_label_lines) and under its track (its mass labels; a printed figure's go
  // into the lines above).
  int label_lines_above = 1;
  int label_lines_below = 1;
  // The info in small text on lines of its own, not beside the heading at the labels' size (a
  // printed figure's single 1D panel).
  bool info_small = false;
};

struct FrameLayout {
  int width_px = 0;
  int height_px = 0;
  // Every size below is a fraction of this: the frame height, or more in a printed figure whose
  // text would otherwise fall below FrameShape::text_floor_px.
  double scale_px = 0;
  PixelRect header;  // title (left, title_lines lines) and time readout (right)
  int title_lines = 1;
  std::vector<PanelLayout> panels;
  std::vector<PixelRect> charts;

  // Text sizes: font pixel sizes (em), whole pixels.
  double title_px = 0;
  double text_px = 0;   // labels and readouts
  double small_px = 0;  // captions, axis numbers
  double gap_px = 0;    // spacing between text and what it labels

  double bar_frame_px = 0;          // thickness of the bar's frame (whole pixels, >= 1)
  double outline_px = 0;            // body outline thickness
  double track_px = 0;              // track line thickness; the line lies just below track_y_m
  double line_px = 0;               // chart lines, trails, ruler ticks
  double arrow_gap_px = 0;          // from a block's top to its arrow's centre line
  double arrow_shaft_px = 0;        // shaft thickness
  double arrow_head_length_px = 0;  // along the arrow
  double arrow_head_width_px = 0;   // across the arrow, full width

  // The first panel (a single-panel frame's only one).
  const PanelLayout& panel() const { return panels.front(); }
};

// What the layout depends on besides the size.
struct FrameShape {
  int panels = 1;   // >= 0
  int columns = 1;  // >= 1
  int charts = 0;   // >= 0
  double line_scale = 1.0;
  // Labels and readouts (text_px) are at least this em size, and everything else grows with them;
  // 0: sizes follow the frame height alone.
  double text_floor_px = 0.0;
  // What the frame's text needs (layoutFrame measures it): lines of the title (1 or 2) and of a
  // single panel's caption, rows of the energy bar's segment labels, and a comparison grid's
  // readout column (its share of the cell width; heading and info on one line where the column
  // is short).
  int title_lines = 1;
  int caption_lines = 1;
  int info_lines = 1;
  int bar_label_rows = 1;
  // A printed figure whose text the floor enlarged (too large for the one line of readouts over
  // a 1D scene's arrows and the one of mass labels under its track that a screen keeps, in a
  // scene too short for both and the ruler): the lines of text every 1D panel keeps above its
  // arrows instead, enough for a legend of all its labels in as many columns as fit across its
  // scene (layoutFrame measures them: PanelModel::placed_label_lines); none under its track, and
  // a single panel's info in small text. 0: as on screens.
  int print_label_lines = 0;
  // Such a figure's single 1D panel whose scene is too short for those lines (a chain of six
  // blocks, a scene beside its chart; PanelModel::print_values_room, where compose found a value
  // lost without it): its values come before the text that repeats them. Its caption keeps one
  // line (the scale arrow's; the text is cut there anyway, and the figure's caption, its alt
  // text and the data say it whole), and where that is not enough its info gives way too (no
  // info lines).
  bool print_caption_one_line = false;
  bool print_info_gives_way = false;
  bool title_small = false;  // the title at the labels' size: two lines at its own do not hold it
  double grid_column_share = 0.34;
  bool grid_heading_one_line = false;
  // A grid too short for its readout columns: panels side by side (columns = panels), each
  // stacked like a single panel (heading, scene, bar under it, label rows; no caption).
  bool grid_stacked = false;
  // A panel shows its energy bar (false for a strobe photograph: its scene takes the bar's room).
  bool energy_bar = true;
  // A comparison grid's strobe photograph (no bars, images of the bodies): each cell's readout
  // column keeps the rest of its height for its caption, which says what the images are (their
  // rate, what was left out), as a single strobe's does.
  bool grid_captions = false;
  // A single panel with its readouts (info, bar, bar labels, caption) in a column right of the
  // scene, this share of the panel's width; 0: stacked under the scene. layoutFrame chooses it
  // for a plane scene where it draws the world larger.
  double side_column_share = 0.0;
  bool headings = false;  // some panel has a heading (a side column then starts with its line)
  bool momentum = false;  // some panel shows a momentum diagram (a side column keeps it a place)
  // The share of the body's width the column of charts takes when it holds a working panel (its
  // last place): a long working needs more than a chart for its math to be read in a classroom.
  // 0: a chart's share (no working, or a short one).
  double working_share = 0.0;
};
FrameShape shapeOf(const FrameModel& frame, double text_floor_px = 0.0);

// The layout of `frame` at width_px × height_px: computeFrameLayout of its shape, with room for
// its text as measured by `width` (a long title on two lines, a long caption on two, the bar's
// labels in as many rows as they need, a comparison grid's readout column as wide as its labels).
// The one layout every painter and compose's label placement use.
FrameLayout layoutFrame(const FrameModel& frame, int width_px, int height_px, double text_floor_px,
                        const text::TextWidth& width);

// Where the bar's labels stand. Where they all fit in one row, one slot per segment that has one
// (EnergySegment::has_slot), labelled now or not, each with room to grow (kBarGrowEm: a value
// that gains a digit or a unit prefix) and a gap (kBarGapEm): each stands in its slot, still
// while its segment grows and shrinks through a video. Otherwise (a crowded bar) they stand in
// a staircase in the segments' order (frame/bar_legend.hpp), in as few rows as that allows: in
// a video every entry keeps its room (barLabelRoom) whether it is labelled now or not, so none
// moves while others come and go. `widths`: the rooms' widths in pixels, set at size_px.
bool barLabelsInSlots(const std::vector<double>& widths, std::size_t slots, double size_px,
                      double row_width);
// The rows the labels need: 1 in slots, else the staircase's (mirrored in a language read from
// the right) in `row_width`.
int barLabelRows(const std::vector<double>& widths, std::size_t slots, double size_px,
                 double row_width, bool right_to_left);
// The label slots under `bar`, and the slot of its segment `segment` (which has one).
std::size_t barLabelSlots(const EnergyBar& bar);
std::size_t barLabelSlot(const EnergyBar& bar, std::size_t segment);

// The widths (swatch, pad and text) of the room each of a bar's legend entries keeps
// (barLabelRoom) at `size_px`, as drawn: one for each segment with a slot and a room.
std::vector<double> barLabelWidths(const EnergyBar& bar, double size_px,
                                   const text::TextWidth& width);
// The text whose width a segment's legend entry keeps: its widest in the picture, else its own.
const std::string& barLabelRoom(const EnergySegment& segment);
inline constexpr double kBarSwatchEm = 0.6;  // colour swatch beside a bar label, em
inline constexpr double kBarPadEm = 0.3;     // swatch to text, em
inline constexpr double kBarGapEm = 1.0;     // between labels in a row, em
inline constexpr double kBarGrowEm = 0.75;   // room a bar label may grow by in its slot, em

// Printed figures keep labels at least this size (points, 1/72 inch): legible on paper, like the
// 8-10 pt of a journal figure. An 8 cm wide 16:9 figure would otherwise get 5 pt text.
inline constexpr double kPrintTextFloor_pt = 8.5;
// kPrintTextFloor_pt in pixels of a figure printed at this resolution (0 for none).
double printTextFloorPx(double dots_per_inch);

// The layout of a width_px × height_px frame (both > 0).
FrameLayout computeFrameLayout(int width_px, int height_px, const FrameShape& shape = {});

// Uniform world → pixel mapping: metres stay square, the view window is centred in the scene area
// and as large as fits. World y points up, pixel y down.
struct WorldToPixel {
  double px_per_m = 1.0;
  core::Vec2 origin_px = {0.0, 0.0};  // pixel position of the world origin

  core::Vec2 toPixel(const core::Vec2& world_m) const {
    return {origin_px.x() + px_per_m * world_m.x(), origin_px.y() - px_per_m * world_m.y()};
  }
  core::Vec2 toWorld(const core::Vec2& pixel) const {
    return {(pixel.x() - origin_px.x()) / px_per_m, (origin_px.y() - pixel.y()) / px_per_m};
  }
};

// Fits `view` into `area`. A degenerate view (zero width or height) fits by its other side.
WorldToPixel fitView(const ViewWindow& view, const PixelRect& area);

// The area the world of `panel` is fitted into: the panel's scene minus room for the labels above
// and below the bodies and for the ruler.
PixelRect worldArea(const PanelModel& panel, const PanelLayout& panel_layout,
                    const FrameLayout& layout);

// The box of `panel`'s momentum diagram (MomentumDiagram), the one compose keeps labels out of
// and the painters draw in: its place in a side column, else a square at the top right of the
// scene; none for a panel without a diagram, or where the box would be too small for its title
// and labels (a small printed figure, a grid cell).
std::optional<PixelRect> momentumBox(const PanelModel& panel, const PanelLayout& panel_layout,
                                     const FrameLayout& layout);

// How the momentum diagram's chain sits in its box (momentumBox): one scale for the whole
// picture, the chain's reach over the run (MomentumDiagram::reach_*) fitted into the plot
// between the title line and the scale bar's line with a label's room around it. Public so
// tests can check the scale bar against the arrows.
struct MomentumChainPlot {
  PixelRect area;               // where the chain's points go
  double px_per_Ns = 0.0;       // pixels per kg·m/s, along both axes
  core::Vec2 start_px{0, 0};    // the chain's first tail (zero momentum)
  bool one_d = false;           // every momentum along x: drawn as a staircase
  double scale_bar_px = 0.0;    // the scale bar's length (scale_bar_Ns at px_per_Ns); 0: none
  double scale_bar_y_px = 0.0;  // its line's height
};
MomentumChainPlot momentumChainPlot(const MomentumDiagram& diagram, const PixelRect& box,
                                    const FrameLayout& layout);

// The world → pixel mapping the renderer uses for a panel.
WorldToPixel panelMapping(const PanelModel& panel, const PanelLayout& panel_layout,
                          const FrameLayout& layout);

// A velocity arrow as the painters draw it, in pixels. Its length is speed × arrow_m_per_mps, to
// scale, but never longer than the panel's arrow_max_length_m (off scale: drawn with a break in
// its shaft) nor shorter than a visible minimum, one head length beyond the first hidden_px of
// it (a 2D arrow's part under its body: bodyArrowShape): such an arrow is under scale, drawn as
// one "below scale" mark at that minimum's end (a bar across the base of a head, no shaft), its
// value in its readout. Its head grows with the shaft
// between half and the whole of the layout's head size.
struct ArrowShape {
  double length_px = 0.0;  // tail to tip; 0: no arrow
  double shaft_px = 0.0;   // thickness
  double head_length_px = 0.0;
  double head_width_px = 0.0;
  bool off_scale = false;    // longer than drawn: a break in its shaft
  bool under_scale = false;  // shorter than drawn: a below-scale mark, no shaft
  // Under scale: where along it the mark begins, past the part hidden under a 2D body (its edge);
  // off scale: where its break may begin at the earliest (arrowBreak).
  double mark_from_px = 0.0;
  // 1D: how far the tail sits behind the body's centre, against the motion: an arrow that would
  // reach a wall it moves towards is drawn back from it, whole and to its scale, its tip a gap
  // short of the wall's face (bodyArrowShape). 0: the tail at the centre.
  double tail_back_px = 0.0;
  // 2D: how far the arrow's line runs beside its body's centre, across its motion (positive:
  // towards the top of the picture; arrowBesideDirection), where straight on from the centre it
  // has no room at all before another body or a wall: drawn whole and to its scale beside the
  // body, clear of it, as a 1D arrow runs over its block (arrow_room.hpp). 0: from the centre.
  double beside_px = 0.0;
  // 2D: how far ahead of its body's centre, along its motion, the tail stands: an arrow that
  // reads at its true length but would not clear its body from the centre is drawn from the
  // body's edge, on its scale (arrowReadingOrMark). 0: from the centre (or beside it). Negative,
  // beside it: drawn back, behind the centre, where ahead of it a wall or a body leaves no room
  // for the whole arrow (arrow_room.cpp's placeBeside).
  double tail_ahead_px = 0.0;
};
ArrowShape arrowShape(double speed_mps, const PanelModel& panel, const FrameLayout& layout,
                      const WorldToPixel& to_px, double hidden_px = 0.0);
// The scale arrow of `speed_mps` (PanelModel::scale_arrow_mps): always exactly to scale, since it
// states the scale; shorter than a head, the one-head arrow shrunk whole. Compose picks its speed
// so that it reads (compose/scale_arrow.hpp).
ArrowShape scaleArrowShape(double speed_mps, const PanelModel& panel, const FrameLayout& layout,
                           const WorldToPixel& to_px);
// The arrow of `body` (its speed): in a 2D panel it starts at the body's centre, so at least the
// visible minimum of it reaches beyond the body's edge: never hidden under the body; one that
// would run into a wall or another body stops short of it, off the scale, or is drawn beside the
// body, or not at all (arrowInRoom, arrowBesideOrInRoom). One whose true length reads (a head or
// more) but would not clear the body from its centre is drawn that long from the body's edge, or
// beside it, never as "below scale" (arrowReadingOrMark). In a 1D panel it never strikes through
// a wall: one that would reach past the face of a wall the body moves towards is drawn back from
// it (ArrowShape::tail_back_px).
ArrowShape bodyArrowShape(const BodyModel& body, const PanelModel& panel, const FrameLayout& layout,
                          const WorldToPixel& to_px);
// Where the painter starts `body`'s arrow of `shape` (bodyArrowShape), pixels: 2D at the body's
// centre (or beside it by shape.beside_px, or at its edge by shape.tail_ahead_px); 1D at its arrow
// line's height (arrowLineYPx) over the centre, drawn back by shape.tail_back_px.
core::Vec2 bodyArrowTailPx(const BodyModel& body, const PanelModel& panel,
                           const FrameLayout& layout, const WorldToPixel& to_px,
                           const ArrowShape& shape);

// The room the scale arrow and its label take at the right end of a single panel's caption
// (arrow, gap, label and a text-size gap before the caption's end); 0 for a panel without one.
double captionScaleRoomPx(const PanelModel& panel, const PanelLayout& panel_layout,
                          const FrameLayout& layout, const text::TextWidth& width);

// The text of body `body`'s mass label (`mass`) or velocity readout as `panel` states it: by the
// body, or in the panel's legend where compose's placement put it there (a text the legend wrapped
// in two lines joined again); empty where it states none. One definition for compose (which puts
// a frame placed at another size back) and the print layout (which counts the labels' lines).
std::string statedLabel(const PanelModel& panel, std::size_t body, bool mass);

// The widths of a legend's columns where texts of `widths` (in order) fill `columns` columns row
// by row: each column as wide as its widest text, so a column of short mass labels beside one of
// readouts takes only its own room (compose's legend and the print layout's lines alike).
std::vector<double> legendColumnWidths(const std::vector<double>& widths, std::size_t columns);

// How far a 1D arrow of `row` (BodyModel::arrow_row) sits above its usual height, pixels: a
// row is an arrowhead's width and a gap.
double arrowLiftPx(int row, const FrameLayout& layout);

// The pixel height of a 1D body's arrow (its centre line): arrow_gap_px above the body's top in
// row 0; in row r >= 1, r rows (arrowLiftPx) above the row-0 line of the panel's tallest body, so
// a lifted arrow clears every arrow below it whatever the bodies' heights.
double arrowLineYPx(const PanelModel& panel, const BodyModel& body, const FrameLayout& layout,
                    const WorldToPixel& to_px);

// The break drawn in an off-scale arrow's shaft: the shaft stops at break_start_px and resumes at
// break_end_px (distances from the tail), with a slanted stroke across each end.
struct ArrowBreak {
  double break_start_px = 0.0, break_end_px = 0.0;
};
ArrowBreak arrowBreak(const ArrowShape& shape);

// Whether `panel`'s ruler is drawn: it asks for one (PanelModel::ruler), and, in a printed
// figure's 1D scene (label_lines_below 0), the scene has room for it under the track besides the
// lines of labels above the arrows; else the ruler gives way to the labels.
bool drawsRuler(const PanelModel& panel, const PanelLayout& panel_layout,
                const FrameLayout& layout);

// One axis of a panel's ruler, in world metres: it covers only the drawn region [lo_m, hi_m] (the
// view window, not the empty sides the equal aspect leaves), ticks a nice step apart (at least
// min_spacing_px at px_per_m). No ticks when fewer than two fall inside: a lone tick gives no
// scale, so the axis is left out.
struct RulerAxis {
  double from_m = 0.0, to_m = 0.0;  // the axis line
  double step_m = 1.0;
  std::vector<double> ticks_m;  // increasing; empty: draw no axis
};
RulerAxis rulerAxis(double lo_m, double hi_m, double px_per_m, double min_spacing_px);

// The pixel x of a 2D panel's vertical ruler line: at the left of the drawn region (the view
// window), never left of `area` (worldArea, which keeps room for its tick labels).
double verticalRulerX(const PanelModel& panel, const WorldToPixel& to_px, const PixelRect& area,
                      const FrameLayout& layout);

// The x positions (pixels) of the energy bar's segment boundaries inside `inner`: element 0 is
// inner.x0 and element i+1 = inner.x0 + inner.width() · (E_0 + … + E_i) / full_scale_J, clamped to
// [inner.x0, inner.x1]; negative energies count as 0. Size = segments + 1. Segment i is drawn over
// [edges[i], edges[i+1]] × [inner.y0, inner.y1]. A strip segment counts as 0 here: its own
// place is barStripPx's.
std::vector<double> barSegmentEdgesPx(const EnergyBar& bar, const PixelRect& inner);

// Where a strip segment (EnergySegment::strip) is drawn: from its from_J to from_J + energy_J
// along the lower kBarStripShare of `inner`, clamped to it.
inline constexpr double kBarStripShare = 0.4;
PixelRect barStripPx(const EnergyBar& bar, const EnergySegment& strip, const PixelRect& inner);

// Places intervals of the given widths, each as near as possible to its wanted centre, without
// overlap (at least gap apart) and inside [lo, hi] where they fit, in the order of their wanted
// centres. Returns the left edges, in the given order. Used for labels in a row (bar labels, block
// labels).
std::vector<double> spreadIntervals(const std::vector<double>& wanted_centers,
                                    const std::vector<double>& widths, double gap, double lo,
                                    double hi);

}  // namespace collide::frame
