// SPDX-License-Identifier: MIT
#pragma once
// The checks VideoFramesTest makes on `collide layout --fps 60`'s items (render::drawnItems), one
// frame at a time and between two consecutive frames (issue 37's "Done when").
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/vec.hpp"
#include "frame/drawn_items.hpp"

namespace collide::test {

// Between two frames with no event between them, a label, readout or legend entry moves no more
// than this beyond its body's own motion (or stands still while its body moves); within
// kEventSpan_s after an event, no more than kEventPx.
inline constexpr double kCalmPx = 2.0;
inline constexpr double kEventPx = 8.0;
// How long after an event the looser bound holds, simulated seconds: as long as a label's place
// may change at the faster pace an event allows (compose/label_timeline.hpp's kShortestShot_s).
inline constexpr double kEventSpan_s = 0.3;
// An arrow drawn on the scale is as long as its value says, within this.
inline constexpr double kArrowPx = 2.0;
// A text that fades in or out (a label changing places between its body and its legend, shown
// at both meanwhile) changes its opacity by no more than this from one frame to the next at 60
// fps: a fade takes at least the 0.3 s a change of place eases over. A hair over the share, for
// an opacity written as a float.
inline constexpr double kFadeStep = 1.0 / (0.3 * 60.0) + 1e-6;

// The first arrow whose segment crosses a wall or the box of another body of its panel (not one
// whose box holds its tail: the body itself, one it overlaps or is stuck to), described; empty
// where none does.
std::string arrowThroughSomething(const std::vector<frame::DrawnItem>& items);

// The first arrow drawn on the scale whose length differs from its value times the scale by more
// than kArrowPx, described; empty where none does.
std::string arrowOffItsValue(const std::vector<frame::DrawnItem>& items);

// A frame's items as the motion checks read them.
struct FrameItems {
  double t_s = 0.0;                                        // simulated
  std::map<std::string, frame::DrawnItem> texts;           // labels, readouts, legend, by id
  std::map<std::pair<int, int>, frame::PixelRect> bodies;  // by (panel, body)
  std::map<std::string, std::size_t> lines;                // every text item's lines, by id
};
FrameItems frameItems(double t_s, const std::vector<frame::DrawnItem>& items);

// How far a text moved from `was` to `now` beyond `carried` (its body's motion, or none): its box
// compared edge for edge and centre for centre, the nearest of the three across and up or down,
// so that a text whose value grows or shrinks does not count as moving where its anchored side
// stays.
double movedBeyond(const frame::PixelRect& was, const frame::PixelRect& now,
                   const core::Vec2& carried);

// Which texts a motion check reads: those attached to a body (its mass and velocity labels,
// tags, the label list's entries: body >= 0), or the rest (the info line, the time, the bar's
// entries: placed by the frame's layout, not beside a body).
enum class TextsOf { kBodies, kFrame };

// Each text of `now` of `which` that moved more than `limit_px` since `was` (beyond its body's
// motion, or standing still while its body moved), described. A label listed in its legend and
// the same label by its body ("legend.mass.2" and "mass.2") are one text where one of them takes
// the other's turn: a label that leaves its body for the legend jumps there.
std::vector<std::string> textsThatJump(const FrameItems& was, const FrameItems& now,
                                       double limit_px, TextsOf which);

// Each text that fades faster than kFadeStep a frame from `was` to `now`, described: one drawn
// less than solid in either frame, or one that comes or goes while the same label at its other
// place (legend.mass.2 for mass.2) is there in both, counted as 0 where it is not drawn.
std::vector<std::string> textsThatFadeTooFast(const FrameItems& was, const FrameItems& now);

// Each text of `now` whose number of lines differs from `was`'s, described.
std::vector<std::string> textsThatRewrap(const FrameItems& was, const FrameItems& now);

}  // namespace collide::test
