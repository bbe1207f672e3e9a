#pragma once
// Label placement: where each body's label ("m₁ = 1.00 kg") and velocity readout go in a picture
// of a given size, decided on the frame description, never by reading pixels back.
//
// Point-feature placement after Christensen, Marks & Shieber (ACM TOG 1995): every label has
// candidate boxes around its body (nearest ring first, farther rings need a leader line); a
// candidate costs its distance and, far more, any overlap with another label, a body, an arrow, a
// wall, the track, a contact flash, the ruler, the momentum inset or the frame edge, and being
// nearer another body than its own. Greedy in priority order, then rounds of local improvement.
// A label that fits nowhere gives way: crowded scenes lose it and keep the number in the body.
#include <cstddef>
#include <optional>
#include <vector>

#include "core/vec.hpp"
#include "frame/frame_model.hpp"
#include "text/text_measure.hpp"

namespace collide::compose {

// Where placement put a label by its body: the index of the candidate place it chose
// (label_candidates.hpp), so that a later frame can keep the label there (a shot's plan:
// frame_source.cpp). A candidate's index names the same side of the same body from frame to
// frame, as long as the label has as many candidates (its kind of place is the same).
// Leaving a kept slot costs as much as this many lines of its text farther off (a label keeps
// its side of its body through a shot, and returns to a better place only where that gains
// more), far less than continuing another label's line (kOneLine) or an overlap: where it must
// move, it moves.
inline constexpr double kLeavesItsSlotLines = 2.0;

// Where a label listed in its panel's legend stands: its line's top left corner and width,
// pixels; where
// the legend stands by its bodies (legend_placement.hpp's placeLegendNear), the body it rides
// with and that body's centre then (by -1: it stands in the frame).
struct LegendLine {
  core::Vec2 px{0.0, 0.0};
  double width_px = 0.0;  // its text's
  int by = -1;
  core::Vec2 by_px{0.0, 0.0};
  core::Vec2 first_px{0.0, 0.0};  // its legend's first line's place: the lines of one legend
};

struct LabelSlot {
  std::size_t panel = 0, body = 0;
  bool velocity = false;  // the velocity readout, else the mass label
  int candidate = -1;     // -1: by no body (it gave way)
  std::size_t candidates = 0;
  // What leaving the slot costs, in lines of the label's text farther off.
  double leaves_lines = kLeavesItsSlotLines;
  // Where the label should stand now (its box's top left corner, pixels): where it glides to
  // its slot, or its slot's place carried along by its body. Taken where it runs into nothing.
  std::optional<core::Vec2> wanted_px;
  // Its planned way runs into nothing at wanted_px: leaving it costs as much as an overlap, so a
  // label whose own way runs into something finds a place elsewhere rather than pushing this one
  // off its way (every label it pushes jumps in the video, not only itself). One listed in its
  // legend (candidate -1) stays listed: a place by its body costs as much as an overlap.
  bool holds = false;
  // Listed in its panel's legend (or, where it is by its body now, where it was listed last): a
  // later frame lists it there again where that is free, so that a legend's lines hold still or
  // ride with their bodies rather than move to each frame's best place.
  std::optional<LegendLine> legend{};
  // How wide the text was where its way was planned (0: as placed): a way is planned for a
  // label's widest text of its shot (the number changes its count of digits).
  double planned_width_px = 0.0;
};
using LabelSlots = std::vector<LabelSlot>;

// Where a label `size_px` large stands at slot.wanted_px (its top left corner there): a text
// narrower than planned in a place wholly left of its body (whose left edge is at body_x0_px)
// keeps the planned box's right edge, by its body, where the left edge would leave it standing
// off, on a leader across the body (ballistic-pendulum's readout as its number narrows). Within
// the planned box either way, so it runs into nothing the plan saw free.
core::Vec2 wantedCorner(const LabelSlot& slot, const core::Vec2& size_px, double body_x0_px);

// Fills BodyModel::label_at and velocity_label_at of every panel of `frame` for a
// width_px × height_px picture (both > 0) whose text is at least text_floor_px (a printed
// figure's, frame::printTextFloorPx; 0: none), and the panels' placed_for_* sizes. A label with
// no free place is cleared (its body gets its number as tag).
// `keep`: places to keep where they are free (a label leaves its slot only where it would run into
// something there); `chosen`: filled with the places found.
void placeLabels(frame::FrameModel& frame, int width_px, int height_px, text::TextMeasure& metrics,
                 double text_floor_px = 0.0, const LabelSlots* keep = nullptr,
                 LabelSlots* chosen = nullptr);

}  // namespace collide::compose
