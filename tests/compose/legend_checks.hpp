// SPDX-License-Identifier: MIT
#pragma once
// The energy bar's legend read as the painters draw it (issue 37): leaders that cross each other
// or run through another entry read as the wrong part's, and an entry that comes and goes while
// its segment is there makes the legend flicker. And a video's label legend (or other texts)
// watched frame by frame.
#include <string>
#include <vector>

#include "compose/frame_source.hpp"
#include "frame/drawn_items.hpp"
#include "frame/frame_model.hpp"

namespace collide::test {

// The first bar leader (`leader.energy.N`, its `path`) that meets another leader, runs through
// another entry's box (`energy.M`) or does not end on its own entry, described; empty where none.
std::string tangledLeader(const std::vector<frame::DrawnItem>& items);

// Each bar segment of `now` whose legend entry is drawn in one of `was` and `now` and not in the
// other while its segment has energy in both (more than round-off of the bar's full scale),
// described. Between two frames of a shot a legend keeps its entries.
std::vector<std::string> entriesThatComeAndGo(const frame::FrameModel& was,
                                              const frame::FrameModel& now);

// What the legend entries (or the texts of another `kind`) of a video do between two
// consecutive frames at 60 fps whose simulated times lie in [from_s, to_s]: those that move more
// than limit_px beyond their bodies (textsThatJump), and how many of the frames have one at all.
struct LegendWatch {
  std::vector<std::string> jumps;
  int listed_frames = 0;
};
LegendWatch watchLegend(const compose::FrameSource& source, double from_s, double to_s,
                        double limit_px, int width_px, int height_px,
                        const std::string& kind = "legend");

}  // namespace collide::test
