#pragma once
// The pieces of label placement (label_placement.cpp) that more than one of its files use: a label
// with its candidate places, a panel's scene as placement sees it, and the candidates themselves.
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "compose/label_placement.hpp"
#include "compose/placement_obstacles.hpp"
#include "core/vec.hpp"
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"

namespace collide::compose {

inline constexpr double kRestSpeed_mps = 1e-6;
// Least room between two lines of text, of the text size: across, about a word space (two labels
// nearer than that read as one, "m₁ = 1.00 kgm₂ = 1.00 kg"); up or down, a little more than the
// line box's own leading.
inline constexpr double kTextGapAcrossEm = 0.3;
inline constexpr double kTextGapAlongEm = 0.1;
// Two labels on one line (baselines nearer than half a line) read as two only farther apart than
// this many em: within a line words stand a quarter em apart and a formula a quad or two (1 to 2
// em) from the condition that belongs to it, so "m₁ = 0.0100 kg   m₂ = 1.00 kg", under a bullet
// and a block a word space or two apart, reads as one line of masses, not a label under each.
inline constexpr double kOneLineLeastGapEm = 2.0;
inline constexpr double kOneLineBaselineLines = 0.5;
// Farther apart than that they read as two, but still as a row of two ("m₁ = 0.0100 kg", three em,
// "m₂ = 1.00 kg" under a bullet and its block): from twice that gap on, the eye takes each for
// the label of what stands over it. Placement prefers another baseline or this gap where it has a
// place.
inline constexpr double kApartOnOneLineEm = 2.0 * kOneLineLeastGapEm;
// The longest leader line, in lines of its label's text: a reader follows a short leader, not
// one hung across the picture ("m₁ = 1.00 kg" under the ruler, its leader up to a block); a label
// with no place nearer gives way to the legend.
inline constexpr double kLongestLeaderLines = 3.0;

struct Label {
  std::size_t body;
  bool velocity;  // the velocity readout, else the mass label
  std::string* text;
  core::Vec2 size;
  std::vector<Box> candidates;
  std::vector<double> base_cost;  // distance and preference
  std::vector<bool> needs_leader;
  int chosen = -1;
  // A place asked for by the layout over time (label_timeline.hpp): the candidate it kept from
  // the frame before (-1: none), and the last candidate is where it glides or rides now
  // (`wanted`, appended to its own candidates).
  int kept = -1;
  bool wanted = false;
  bool in_legend = false;  // listed in the legend: not placed by its body
  // Its legend line's place (label_placement.hpp): where the frame before listed it
  // (`wanted_legend`), and where this one lists it (`legend`, none where it is not listed).
  std::optional<LegendLine> wanted_legend{}, legend{};
  bool listed_before = false;  // the frame before listed it (at wanted_legend)
};

// A panel's scene as placement sees it: the obstacles every text keeps clear of, and what the
// labels are attached to.
struct LabelScene {
  Obstacles obstacles;
  std::vector<int> moves_with;  // per body: the body it rides on (one body with it), or -1
  // Per body: its arrow (tail to tip, pixels), none at rest or for a rider.
  BodyArrows arrows;
  double em_px = 0.0;  // the labels' text size
};

// Candidate boxes for a label of `size` beside a body: 2D all around it, ring by ring; 1D the mass
// label under the track and the velocity readout over the arrow, in rows, slid sideways.
void addCandidates(Label& label, const frame::PanelModel& panel, const LabelScene& scene,
                   const frame::FrameLayout& layout, const frame::WorldToPixel& to_px);

}  // namespace collide::compose
