#pragma once
// What to draw in one frame, as plain data. Built by compose from physics snapshots; the renderer
// never sees physics types. World coordinates are metres (y up); the renderer maps them to pixels
// (frame/layout.hpp); text compose placed (PlacedText) lands where compose put it.
//
// Text is UTF-8. Unicode subscripts (U+2080..U+209C, e.g. "v₁") and superscripts ("m²") are drawn
// as smaller glyphs below or above the baseline, whatever the font; "′" (U+2032) is a prime.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "text/math.hpp"
#include "text/most_lines.hpp"
#include "text/number_format.hpp"

namespace collide::frame {

struct Rgba {
  float r = 0.0f, g = 0.0f, b = 0.0f, a = 1.0f;  // each in [0, 1], straight alpha
};

// Colours and line weight shared by everything in a frame; the app fills it from a theme.
struct FrameStyle {
  Rgba background = {1.0f, 1.0f, 1.0f, 1.0f};
  Rgba text = {0.10f, 0.10f, 0.10f, 1.0f};               // titles, readouts, labels
  Rgba muted_text = {0.35f, 0.35f, 0.35f, 1.0f};         // captions, axis numbers, units
  Rgba track = {0.30f, 0.30f, 0.30f, 1.0f};              // 1D track, walls, ruler, chart axes
  Rgba arrow = {0.12f, 0.12f, 0.12f, 1.0f};              // velocity arrows
  Rgba bar_frame = {0.78f, 0.78f, 0.78f, 1.0f};          // energy bar frame, panel and chart boxes
  Rgba flash = {0.95f, 0.75f, 0.10f, 1.0f};              // contact flash
  Rgba inset_background = {0.96f, 0.96f, 0.96f, 0.92f};  // momentum diagram box
  float outline_shade = 0.7f;  // body outline = fill × this (dark themes lighten: > 1)
  double line_scale = 1.0;     // multiplies outline, track, arrow and line thickness (>= 1)
  // How the frame's language writes the numbers render draws itself (ruler and chart axes);
  // compose fills it with the active language's (the GL module has no language of its own).
  text::NumberStyle numbers;
  // The language reads from the right (Arabic): the title, headings, captions and legends start
  // at the right edge, the time readout goes to the left, a legend's swatch follows its text.
  // The physics is not mirrored: x still grows to the right.
  bool right_to_left = false;
};

enum class BodyShape { kRectangle, kDisk };

// A line of text placed by compose, in pixels of the frame size it was composed for
// (PanelModel::placed_for_*): its box is the line's advance × (ascender + descender), the text
// drawn left-aligned from the top-left corner. A leader line runs from the box's nearest edge
// point to `leader_to_px` when the box sits away from what it names.
struct PlacedText {
  core::Vec2 top_left_px = {0.0, 0.0};
  core::Vec2 size_px = {0.0, 0.0};
  std::optional<core::Vec2> leader_to_px;
  // 1: solid. Less: fading out or in with its leader where it stands, the label changing places
  // between its body and its legend (compose/label_fades.hpp), so that it never jumps.
  float opacity = 1.0f;
};

// A soft contact's spring while it is compressed: a coil from one partner's centre to the other's
// (or to the wall), drawn over the bodies; its turns crowd together as it shortens. Also a
// glider's bumper, from its block's face to the bumper's tip.
struct SpringModel {
  core::Vec2 from_m = {0.0, 0.0}, to_m = {1.0, 0.0};
  double half_width_m = 0.05;  // of the zigzag, across the line
  int turns = 6;               // of the zigzag (a glider's short bumper: fewer)
};

struct BodyModel {
  BodyShape shape = BodyShape::kRectangle;
  core::Vec2 center_m = {0.0, 0.0};
  core::Vec2 half_extent_m = {0.25, 0.25};  // rectangle: half width, half height; disk: radius in x
  Rgba fill;
  core::Vec2 velocity_mps = {0.0, 0.0};  // drawn as an arrow; none at rest
  double angle_rad = 0.0;                // rotation, counter-clockwise (disks: orientation mark)
  bool show_orientation = false;         // disks: a spoke from the centre at angle_rad
  std::string label;                     // under a block / beside a disk, e.g. "m₁ = 1.00 kg"
  std::string velocity_label;            // beside the arrow, e.g. "v₁′ = +0.25 m/s"
  std::string tag;                       // short text inside the body, e.g. "1" (crowded scenes)
  std::vector<core::Vec2> trail_m;       // past centre positions, oldest first; fades to the past
  float trail_start_alpha = 0.0f;        // the trail's opacity at its oldest end (a strobe's path)
  // The opacity of `tag` drawn inside the body (PlacedText::opacity; tag_at and arrow_tag_at carry
  // their own).
  float tag_opacity = 1.0f;
  // Stuck to the body at this index and moving with it as one (a bullet in its block): drawn over
  // it, with no arrow of its own (that body's arrow and labels speak for both); -1: on its own.
  int moves_with = -1;
  // 1D: rows its arrow is lifted above the usual height (arrowLiftPx), so the arrows of two
  // bodies closing on each other never cross; 0: just above the body.
  int arrow_row = 0;
  // Where compose put label and velocity_label; unset: the painter's own place.
  std::optional<PlacedText> label_at, velocity_label_at;
  // Where compose put `tag` beside a body too small to carry it inside (frame::tagFitsInside)
  // whose texts stand in the legend, so the legend's "m₁" names something seen; unset: inside.
  std::optional<PlacedText> tag_at;
  // 1D: where compose put `tag` again, at the tail of an arrow lifted above the bodies (arrow_row
  // > 0) or drawn back from a wall (no longer starting over its body) whose value stands in the
  // legend, so that the legend's "v₁′" names an arrow the reader can tell apart; unset: none.
  std::optional<PlacedText> arrow_tag_at;
  // 2D: its arrow, where it reads on its scale, drawn beside the body wherever a place there
  // holds it, before straight on, from its edge or shorter with a break (arrow_room.hpp's
  // arrowBesideOrInRoom and arrowReadingOrMark). Planned over time by compose
  // (compose/arrow_forms.hpp): set where another form would last a few frames between two
  // changes, so the arrow's form changes once.
  bool arrow_beside_first = false;
  // 2D: no arrow drawn (its value in its readout), planned over time by compose where a form
  // would last a few frames between two frames with none (a below-scale mark that finds room
  // straight on for a frame as its ball creeps past another).
  bool arrow_hidden = false;
  // A strobe's image that another body's last (solid) image would hide: drawn over the bodies,
  // so every image of a body stands at its equal time step (heavy-light's light cart at 3 s).
  bool over_bodies = false;
  // A strobe image's bumpers (a glider's), drawn with it and as faint; a solid body's bumpers are
  // the panel's springs.
  std::vector<SpringModel> bumpers;
};

// An infinitely massive wall: the line through point_m perpendicular to normal; hatched on the
// solid side (opposite to normal).
struct WallModel {
  core::Vec2 point_m = {0.0, 0.0};
  core::Vec2 normal = {1.0, 0.0};  // unit, into free space
};

// A rigid link drawn between the centres of two bodies that stuck together.
struct BondModel {
  int body_a = 0, body_b = 0;  // indices into PanelModel::bodies
};

// Bodies on strings (render/draw/draw_strings.cpp): a string from a pivot to the centre of the body
// it holds, under the bodies.
struct StringModel {
  core::Vec2 pivot_m = {0.0, 0.0};
  core::Vec2 body_m = {0.0, -1.0};
};
// The fixed bar strings hang from: a beam from from_m to to_m (one height), hatched above.
struct SupportModel {
  core::Vec2 from_m = {0.0, 0.0}, to_m = {1.0, 0.0};
};
// The arc a body on a string has swept so far (view.arc_trail), dotted: angles from straight
// down, counter-clockwise.
struct ArcModel {
  core::Vec2 center_m = {0.0, 0.0};
  double radius_m = 1.0;
  double from_rad = 0.0, to_rad = 0.0;
  Rgba color;
};
// A length measured on the picture: extension lines from the two measured points to a dimension
// line with an arrowhead at each end, its label beside it and the notes under the label. Vertical:
// a height (a ballistic pendulum's rise), the line at x = line_at_m. Horizontal: a distance
// along the track (a skid), the line at y = line_at_m.
enum class DimensionAxis { kVertical, kHorizontal };
struct DimensionModel {
  DimensionAxis axis = DimensionAxis::kVertical;
  // The two measured points (vertical: the lower, then the higher; horizontal: where the length
  // starts, then where it ends); the line measures their difference along the axis.
  core::Vec2 from_m = {0.0, 0.0}, to_m = {0.0, 1.0};
  double line_at_m = 0.0;
  // Its item in the picture's layout (`collide layout`), e.g. "skid.1"; empty: "dimension.N".
  std::string id;
  std::string label;                // e.g. "rise h = 0.200 m", "skid d = 7.61 m"
  std::vector<std::string> notes;   // e.g. the speed the rise gives back, the true one
  core::Vec2 notes_m = {0.0, 0.0};  // top-left of the notes, in a free corner of the scene
  // Where compose put the label and the notes' top-left corner, in pixels of the panel's
  // placed_for_* size (compose/dimension_placement.hpp); unset: the painter's own place.
  std::optional<PlacedText> label_at;
  std::optional<core::Vec2> notes_at_px;
  // The notes' lines as compose broke them where it placed them (a note too wide for a free
  // place is broken after its lead-in, "speed from h:", then wrapped); empty: a note a line.
  std::vector<std::string> notes_lines;
  // The notes' text size where compose set them smaller than the labels' to find them a place
  // (down to the caption size: never left out); 0: the labels' size.
  double notes_px = 0.0;
};
struct SuspensionModel {
  std::vector<SupportModel> supports;
  std::vector<StringModel> strings;
  std::vector<ArcModel> arcs;
};

// A short burst at a contact point right after a collision.
struct FlashModel {
  core::Vec2 center_m = {0.0, 0.0};
  double strength = 1.0;  // 1 at the impact, fading to 0
  // The burst reaches no farther than this (a 1D flash at the top of a contact face: the shorter
  // partner's height, so it stays clear of the track and the labels under it); 0: no limit.
  double max_radius_m = 0.0;
};

struct MomentumArrow {
  core::Vec2 momentum_Ns = {0.0, 0.0};  // kg·m/s
  Rgba color;
  std::string label;  // e.g. "p₁"
};

// Momenta of the bodies drawn tip to tail in an inset box beside the scene (never over it), with
// their sum from the first tail to the last tip, at one scale for the whole picture, stated by a
// scale bar under the diagram.
struct MomentumDiagram {
  std::vector<MomentumArrow> arrows;
  std::string title = "momentum";  // its heading, in the picture's language
  std::string sum_label = "Σp";
  double full_scale_Ns = 1.0;  // the farthest the chain reaches from its start, > 0; fixed
  // Where the chain's points (its start at 0, each partial sum) reach over the whole picture,
  // kg·m/s: the box is fitted to this. Empty (low > high): a square of ±full_scale_Ns.
  core::Vec2 reach_low_Ns = {1.0, 1.0}, reach_high_Ns = {-1.0, -1.0};
  double scale_bar_Ns = 0.0;    // a round momentum drawn as a bar under the diagram; 0: none
  std::string scale_bar_label;  // e.g. "0.1 kg·m/s"
};

struct EnergySegment {
  double energy_J = 0.0;  // length of this segment in the bar's energy units
  Rgba color;
  std::string label;  // e.g. "KE₁ 0.25 J", drawn under the segment; empty: none now
  // Whether the segment has a label slot under the bar. False only for one that is never
  // labelled in the picture (the loss of a run that loses nothing), so that it leaves no gap.
  bool has_slot = true;
  // The widest label the segment has in the picture (a video's every frame): the room its entry
  // keeps under the bar whether it is labelled now or not, so that the legend's rows and places
  // stay the same through the video (issue 37). Empty: the label's own.
  std::string label_room = {};
  // Not a part but a strip along the bar's lower edge, from from_J to from_J + energy_J, over the
  // parts: the energy released from a store so far, which the parts add up to with the start's.
  bool strip = false;
  double from_J = 0.0;
};

// One horizontal bar whose full length stands for full_scale_J; segments are laid left to right.
struct EnergyBar {
  std::vector<EnergySegment> segments;
  double full_scale_J = 1.0;  // > 0: the initial total energy, and all that is released
  std::string title;          // drawn left of the labels' row, e.g. "Kinetic energy"
};

// The rectangle of the world shown in the scene area; the renderer keeps metres square (uniform
// scale) and centres this window.
struct ViewWindow {
  core::Vec2 min_m = {-4.0, -1.0};
  core::Vec2 max_m = {4.0, 1.0};
};

// Readouts with no room beside their arrows (a crowded chain of blocks), and mass labels with no
// room beside their bodies: the bodies carry their numbers (BodyModel::tag) and their texts
// ("v₃′ = +0.285 m/s", "m₁ = 1.00 kg", tied to the number by the subscript) stand together in a
// free place of the scene, in rows and columns that compose chose, each line drawn left-aligned
// from its top-left corner.
struct ReadoutLegend {
  struct Entry {
    int body = 0;                         // index into PanelModel::bodies
    std::string text;                     // its velocity readout, or its mass label
    core::Vec2 top_left_px = {0.0, 0.0};  // pixels of the panel's placed_for_* size
    bool mass = false;                    // the body's mass label (BodyModel::label)
    float opacity = 1.0f;                 // as PlacedText::opacity
  };
  std::vector<Entry> entries;  // none: no legend
};

// One scene view with its own readouts: the whole frame normally, one cell of a comparison grid.
struct PanelModel {
  std::string heading;  // top-left of the panel, e.g. "e = 0.5"; empty: none
  std::string info;     // top-right of the panel, e.g. "collisions: 1   Σp = +1.00 kg·m/s"
  ViewWindow view;
  bool draw_track = true;  // 1D scenes: the line the blocks slide on, at y = track_y_m
  double track_y_m = 0.0;
  bool ruler = false;  // a scale in metres along the bottom (and left, in 2D) of the scene
  // A calibration stick of a round length on the ruler and a cross at the world's origin (1D: on
  // the track), for measuring the video in Tracker (ViewDesc::calibration).
  bool calibration = false;
  bool two_d = false;  // arrows start at disk centres; labels beside bodies
  std::vector<WallModel> walls;
  std::vector<BodyModel> ghosts;  // strobe images: bodies only, drawn first, no labels or arrows
  std::vector<BodyModel> bodies;
  std::vector<BondModel> bonds;
  std::vector<SpringModel> springs;
  std::vector<FlashModel> flashes;
  ReadoutLegend legend;        // readouts of a crowded scene, beside it (compose places it)
  SuspensionModel suspension;  // bodies on strings: bars, strings, arc trails
  // Lengths measured on the picture: a ballistic pendulum's rise, a skid after an impact.
  std::vector<DimensionModel> dimensions;
  std::optional<core::Vec2> center_of_mass_m;
  std::optional<MomentumDiagram> momentum;
  double arrow_m_per_mps = 0.25;  // arrow length in world metres per m/s of speed
  // An arrow longer than this is drawn this long, with a break in its shaft: off the scale (a
  // bullet 100 times faster than its block); its value is in its readout. 0: no limit.
  double arrow_max_length_m = 0.0;
  // The velocity scale, stated once: an arrow of this speed drawn with its value (e.g. "1 m/s")
  // at the start of the panel's heading line. 0: none (no arrows, or a strobe).
  double scale_arrow_mps = 0.0;
  std::string scale_arrow_label;
  bool show_energy_bar = true;
  EnergyBar energy_bar;
  std::string caption;  // one line under the bar, most important part first; a caption too wide
                        // loses whole parts from its end (TextPainter::fitWhole)
  // The info and the caption planned over the video (compose/text_patterns.hpp), each word the
  // widest it is there (text/wrap_pattern.hpp); empty: as the text itself wraps.
  // *_pattern: the widest text the video shows, the layout counts the lines it takes from it.
  // *_like: the widest of the texts of this one's shape (text::wordShape, its words but for
  // their numbers) in its shot, the painter breaks it where this breaks, so no line re-wraps
  // while the shot plays.
  // *_shot: the widest text of the shot this frame belongs to, the painter keeps at least the
  // lines this takes, so their number holds still through the shot.
  std::string info_pattern, caption_pattern;
  std::string info_like, caption_like;
  std::string info_shot, caption_shot;
  // The widest caption of each shape the video shows (the *_like's of all its frames, the
  // *_pattern among them): one narrower than caption_pattern may break into more lines, and the
  // layout and the painter keep the most any takes. Shared by the video's frames, each count
  // made once per size (text::MostLines); null: caption_pattern alone.
  std::shared_ptr<const text::MostLines> caption_shapes;
  // info_pattern alone, its lines counted once per size for the layout and the painter's shrink
  // search; null: info_pattern (or the info) wrapped each time.
  std::shared_ptr<const text::MostLines> info_widest;
  // The frame size and layout scale (FrameLayout::scale_px: a printed figure's text floor raises
  // it) the PlacedTexts were computed for; a painter of another size or scale ignores them.
  int placed_for_width_px = 0, placed_for_height_px = 0;
  double placed_for_scale_px = 0.0;
  // The lines of text the layout kept above this 1D panel's arrows for a printed figure's labels
  // (FrameShape::print_label_lines) when compose placed them, measured from the labels then
  // (placement may clear one that found no room), so every painter lays the panel out as it was
  // placed; -1: measured anew.
  int placed_label_lines = -1;
  // How much of the text that repeats a printed figure's values gives way to those lines in a
  // single 1D panel, as compose placed it: 0 none, 1 the caption but its last line, 2 that and
  // the info (FrameShape::print_caption_one_line, print_info_gives_way). Compose asks for more
  // only where a value would otherwise be lost.
  int print_values_room = 0;
};

struct ChartSeries {
  std::string label;  // drawn at the right end of the line, e.g. "KE₁"
  Rgba color;
  std::vector<core::Vec2> points;  // (x, y) in chart units, x increasing
  bool dashed = false;
};

// A line chart with fixed axes. Only points with x <= cursor_x are drawn when cursor_x is set, and
// a vertical line marks it.
struct ChartModel {
  std::string title;
  // What the chart states besides its title, most important first, each on its own line under
  // it (e.g. "total impulse 2.27 N·s"); where the plot would be left too little height the
  // last give way.
  std::vector<std::string> notes;
  std::string x_label;                            // e.g. "t (s)"
  std::string y_label;                            // e.g. "energy (J)"
  core::Vec2 min = {0.0, 0.0}, max = {1.0, 1.0};  // axis ranges, max > min
  std::vector<ChartSeries> series;
  std::optional<double> cursor_x;
};

// What a line of a working panel is to the panel, which may set it compactly or leave it out for
// room (render/draw/draw_working.cpp): a given value (they stand several to a row, and where the
// working cannot be read otherwise they give way, the panel saying so), a result the lines above
// already end in (left out first: nothing is lost), or any other line of a step.
enum class WorkingPart { kStep, kGiven, kRepeatedResult };

// One line of a working panel: a step's heading (sides empty), or an equation
// sides[0] = sides[1] = ..., its equals signs aligned with the step's others.
struct WorkingLine {
  std::string heading;
  std::vector<text::Math> sides;
  WorkingPart part = WorkingPart::kStep;  // a heading: its step's
};

// The working of an impact (src/working), typeset in a column right of the panels (issue 41).
struct WorkingModel {
  std::string title;
  std::vector<WorkingLine> lines;
  // The first this many lines are drawn (a video reveals the steps in turn from the impact on);
  // the size is chosen for all of them, so nothing moves as the rest appear. -1: all.
  int shown_lines = -1;
  // Said where the given values were when the panel leaves them out for room.
  std::string given_left_out;
};

struct FrameModel {
  FrameStyle style;
  std::string lang = "en";   // BCP 47 tag of the frame's words (the SVG and PDF language tag)
  std::string title;         // top-left of the frame
  std::string time_readout;  // top-right, e.g. "t = 1.167 s"
  std::string subtitle;      // beside the time readout, e.g. "slow motion ×4"; a video's only
  // The widest subtitle the video shows (set with `subtitle`): the painter sizes and places the
  // subtitle by it in the room the title leaves, so it holds its place while the factor changes.
  // Never drawn, and never part of the layout: a still at t is the video's frame at t.
  std::string subtitle_room;
  std::vector<PanelModel> panels;
  int panel_columns = 1;                // grid of panels, filled row by row
  std::vector<ChartModel> charts;       // stacked in a column right of the panels (the whole frame
                                        // when there is no panel)
  std::optional<WorkingModel> working;  // the last of that column's places
};

}  // namespace collide::frame
