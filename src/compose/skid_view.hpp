// SPDX-License-Identifier: MIT
#pragma once
// A skid measured on the picture (accident-reconstruction): once an impact between two bodies
// sets a body, or the two locked together, sliding with sliding friction, a horizontal dimension
// line runs along the track from where its trailing face was at the impact to where it is now,
// labelled with that length ("skid d = 7.61 m"); at rest it holds the final length, the one a
// reconstruction reads the speed after the impact from (v² = 2 μ g d).
#include <limits>
#include <vector>

#include "core/vec.hpp"
#include "frame/frame_model.hpp"
#include "physics/timeline.hpp"
#include "text/number_format.hpp"

namespace collide::compose {

struct Skid {
  std::vector<int> bodies;  // the body, or the two locked together at the impact
  double from_s = 0.0;      // the impact
  // The next collision of one of them: the skid ends there (and its line with it).
  double until_s = std::numeric_limits<double>::infinity();
  bool rightward = true;  // slides towards +x: its trailing face, the one measured, is its left
};

// The skids of a 1D run whose bodies slide with friction (none in 2D or without friction): one
// for each body that an impact between two bodies leaves moving with sliding friction, one for
// the pair where the impact locked them together.
std::vector<Skid> findSkids(const physics::Timeline& timeline);

// How far the skid has gone by t_s: its bodies' travel since the impact (0 before it).
double skidLength_m(const Skid& skid, const physics::Timeline& timeline, double t_s);

// The longest any of the skids gets in the run (0: none), for the picture's length format.
double longestSkid_m(const std::vector<Skid>& skids, const physics::Timeline& timeline);

// Adds each skid under way or done at t_s (from_s < t_s < until_s) to panel.dimensions, as
// "skid.1", "skid.2"...: its line just above its bodies, its length read in `length`.
// panel.bodies must hold this instant's bodies.
void addSkids(frame::PanelModel& panel, const physics::Timeline& timeline,
              const std::vector<Skid>& skids, const text::QuantityFormat& length, double t_s);

}  // namespace collide::compose
