// SPDX-License-Identifier: MIT
#pragma once
// Where the energy bar's leaders end (draw_bar.cpp): each leader runs from its segment's
// middle under the bar to its legend entry, and ends where it strikes through no other entry
// and crosses no other leader, where some point of its entry allows that (issue 37: legend
// leaders that cross each other or strike a number read as the wrong part's).
#include <vector>

#include "core/vec.hpp"
#include "frame/layout.hpp"

namespace collide::render {

// A legend entry as its leader sees it: the box drawn for it (swatch and text), where its
// leader starts (under its segment's middle) and its swatch's centre.
struct BarLeaderEntry {
  frame::PixelRect box;
  core::Vec2 from_px;
  core::Vec2 swatch_px;
};

// Each entry's leader end, in order: its swatch's centre where that leader strikes through no
// other entry's box (clear_px around it) and crosses no other leader; else the first point of its
// box's top edge (under its segment, at its right end, at its left end, in the middle) that
// does; else the first of those that runs into the fewest. Chosen in rounds, each leader against
// the others as they stand, until none changes (at most a few rounds).
std::vector<core::Vec2> barLeaderEnds(const std::vector<BarLeaderEntry>& entries, double clear_px);

}  // namespace collide::render
