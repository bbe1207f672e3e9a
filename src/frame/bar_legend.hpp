// SPDX-License-Identifier: MIT
#pragma once
// A crowded energy bar's legend as a staircase (issue 37: leaders that cross each other, or
// strike through another entry, read as the wrong part's). The entries stand in the order of
// the segments they name: each has a column, where its leader comes down to it, and the columns
// run across in the segments' order, so that leaders from the segments (in that order along the
// bar) to the columns never cross. An entry whose box reaches over another's column stands below
// that one, so no leader runs down through an entry; entries of a row never overlap. The fewest
// rows that allow this; a leader lands on its entry's swatch where it can, else further along
// its box's top. Planned from the rooms' widths alone, so the same in every frame of a video.
#include <vector>

namespace collide::frame {

// Between a bar's entries in a row, em.
inline constexpr double kBarFlowGapEm = 0.5;
// Between two entries' columns, em: the leaders come down at least this far apart.
inline constexpr double kBarColumnStepEm = 0.8;
// From an entry's box to a leader running down past it, em.
inline constexpr double kBarLeaderClearEm = 0.5;

struct BarStaircase {
  // For each entry, in reading order (left to right, or mirrored for a language read from the
  // right): the left end of its box, its column (where its leader comes down onto its top) and
  // its row (0 under the bar).
  std::vector<double> x0_px, column_px;
  std::vector<int> row;
  int rows = 1;
  // Whether every leader runs clear of the other entries: false where the entries are too wide
  // for any staircase in the row (each then stands in a row of its own, left to right).
  bool clear = true;
};

// The staircase of entries `widths_px` (swatch, pad and text, in reading order) between x0_px
// and x1_px, text at size_px with a swatch of swatch_px.
BarStaircase barStaircase(const std::vector<double>& widths_px, double size_px, double swatch_px,
                          double x0_px, double x1_px);

}  // namespace collide::frame
