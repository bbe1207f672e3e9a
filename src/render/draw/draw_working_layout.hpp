// SPDX-License-Identifier: MIT
#pragma once
// Private to draw_working.cpp: the working panel's lines typeset in pieces and placed in the
// panel's room. An equation's right sides are cut before their operators ("= a", "+ b", "· c"):
// a line too long for the panel breaks before an equals sign, and a side too long for a line of
// its own before a "+", "−", "·" or "×", its continuation indented; the given values, and short
// equations that follow one another in a step, stand several to a row. Sizes are tried by planning
// the pieces of one typesetting at a scale.
#include <string>
#include <vector>

#include "frame/frame_model.hpp"
#include "render/text/font_set.hpp"
#include "render/text/math_typesetter.hpp"
#include "text/number_format.hpp"

namespace collide::render {

// One line of WorkingModel::lines, typeset: a heading, or an equation.
struct SetLine {
  std::size_t source = 0;  // its index in WorkingModel::lines
  int step = 0;            // the lines of one step align their equals signs
  frame::WorkingPart part = frame::WorkingPart::kStep;
  std::string heading;
  MathBox left;                             // sides[0]
  std::vector<std::vector<MathBox>> sides;  // each further side as its pieces, "= a", "+ b", ...
};

// A piece of an equation too wide for any line of the panel (a long fraction) is set smaller than
// the rest, alone, down to this share of their size.
inline constexpr double kLeastSqueeze = 0.7;

// Per line of the working, the size of each piece of its right sides, a share of the others'.
using PieceScales = std::vector<std::vector<double>>;

// The lines of `working` set at size_px, each piece times its share in `piece_scales` (none: 1),
// their numbers in the frame's digits.
std::vector<SetLine> setWorkingLines(const frame::WorkingModel& working,
                                     const text::NumberStyle& numbers, FontSet& fonts,
                                     double size_px, const PieceScales& piece_scales = {});

struct PlacedMath {
  std::size_t source = 0;
  const MathBox* box = nullptr;
  double x_px = 0.0, baseline_px = 0.0;  // from the room's top left
  double scale = 1.0;                    // the box's size in the plan, times its own
};

struct PlacedWords {
  std::size_t source = 0;
  std::string text;
  double y_px = 0.0;  // its top, from the room's top
  bool note = false;  // the given values' note, in their place
};

struct WorkingPlan {
  std::vector<PlacedMath> math;
  std::vector<PlacedWords> words;
  double height_px = 0.0;
  bool overflows = false;    // a piece wider than the room even set at kLeastSqueeze
  PieceScales piece_scales;  // where PlanOptions::squeeze
};

struct PlanOptions {
  double scale = 1.0;             // the pieces' size times this (a size tried before setting it)
  double size_px = 0.0;           // the pieces' em at scale 1
  double heading_px = 0.0;        // headings' em, not scaled
  double width_px = 0.0;          // the room's
  bool skip_repeats = false;      // leave out results the lines above already end in
  bool skip_given = false;        // leave out the given values, `note` in their place
  std::vector<std::string> note;  // its lines, wrapped to the room
  bool squeeze = true;            // false: the pieces are already set at their lines' scales
};

WorkingPlan planWorking(const std::vector<SetLine>& lines, const PlanOptions& options);

}  // namespace collide::render
