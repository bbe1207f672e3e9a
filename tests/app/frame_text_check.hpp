#pragma once
// What a student reads on a frame, checked against physics worked out in the test: every text
// item of a FrameModel (title, time, headings, info lines, body and velocity labels, energy bar
// labels, momentum labels, caption) is parsed by a grammar for its slot, and each number is
// compared with the expected value at the precision it is shown with, its sign and its unit.
// A text item that no grammar reads fails the check too, so nothing on screen goes unread.
#include <optional>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "frame/frame_model.hpp"

namespace collide::test {

// The truth about one body at the frame's time.
struct BodyTruth {
  double mass_kg = 0.0;
  core::Vec2 velocity_mps = {0.0, 0.0};
  bool collided = false;  // it has had a collision by now: its velocity is primed (v₁′)
};

// The truth about one panel at the frame's time.
struct PanelTruth {
  std::string heading;  // e.g. "e = 0.5"; empty for a single picture
  std::vector<BodyTruth> bodies;
  int collisions = 0;
  core::Vec2 momentum_start_Ns = {0.0, 0.0};
  double lost_J = 0.0;
  std::optional<double> potential_J;  // gravity: shown above the lowest point reached
  double energy_start_J = 0.0;        // kinetic + potential at the start: the "%" base
  bool momentum_diagram = false;
};

struct FrameTruth {
  std::string title;
  double t_s = 0.0;
  int dimensions = 1;
  std::vector<PanelTruth> panels;
};

// Checks every text item of `frame` against `truth` with gtest assertions (failures name the
// item and what was expected). Returns how many numbers were compared, so a caller can tell
// that the check saw the frame's text.
int checkFrameText(const frame::FrameModel& frame, const FrameTruth& truth);

}  // namespace collide::test
