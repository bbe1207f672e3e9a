#pragma once
// Checks that a placed frame's labels read as what they name, beyond "no overlap": a leader may
// bridge a short way, never across the picture; and an arrow lifted into a row above the bodies
// or drawn back from a wall (no longer starting over its body) carries its value or its body's
// number beside it, nearer that arrow than anything else.
// Checked on the frame description with the painter's own geometry (frame/layout.hpp).
#include <string>

#include "frame/frame_model.hpp"
#include "render/text/text_metrics.hpp"

namespace collide::compose_test {

// A leader is at most this many text heights (ascender + descender of its label's text) long.
inline constexpr double kLongestLeaderLines = 3.0;
// A label's own body (a readout's: or its arrow) is nearer it than any other body or arrow by at
// least this many of its text heights.
inline constexpr double kNearerByLines = 0.25;

// Two labels on one line (baselines nearer than half a line apart) read as two only this many em
// apart: within a line words stand about a quarter em apart, and a formula stands a quad or two
// (1 to 2 em, LaTeX's \quad and \qquad) from the condition that still belongs to it;
// "m₁ = 0.0100 kg   m₂ = 1.00 kg" a word space or two apart read as one line of two masses, not as
// a label under each body. Farther apart than a qquad, or on another line, they read as two.
inline constexpr double kOneLineLeastGapEm = 2.0;
inline constexpr double kOneLineBaselineLines = 0.5;

// Adds a gtest failure naming `where` for every label of `frame` (placed for width_px × height_px,
// text_floor_px as compose placed it) that hangs on a long leader, and for every lifted or
// drawn-back arrow left without a tie, and for every two labels of bodies that read as one line.
void expectLabelsReadAsTheirOwn(const frame::FrameModel& frame, int width_px, int height_px,
                                double text_floor_px, render::TextMetrics& metrics,
                                const std::string& where);

}  // namespace collide::compose_test
