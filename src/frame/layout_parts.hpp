// SPDX-License-Identifier: MIT
#pragma once
// What the frame's layout (layout.cpp) and its fitting to the frame's text (layout_fit.cpp) share:
// the side column's bounds and a grid cell's readout column height.
#include "frame/layout.hpp"

namespace collide::frame {

// A single plane panel's readout column (FrameShape::side_column_share): at least this many
// label ems wide (or as wide as its widest bar label), at most this share of the panel; its
// info is reckoned at kSideInfoLines lines when the column is chosen, but wraps to as many as
// it needs up to kSideMostInfoLines (a longer language's info is never cut: it states values
// nothing else does), and its caption to as many as the column holds above its foot
// (sideCaptionRoom), widened a label em at a time where those are too few for it whole
// (widenForCaption). Chosen where it draws the world kSideColumnLeastGain times as large.
inline constexpr double kSideColumnLeastEm = 11.0, kSideColumnMostShare = 0.45;
inline constexpr int kSideInfoLines = 4, kSideMostInfoLines = 8;
inline constexpr int kSideLeastCaptionLines = 2;
inline constexpr double kSideColumnLeastGain = 1.05;

// Height of a grid cell's readout column.
double gridColumnHeight(const FrameLayout& l, const FrameShape& shape);

}  // namespace collide::frame
