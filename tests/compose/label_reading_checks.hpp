#pragma once
// Checks that a placed frame's labels read as what they name, beyond "no overlap": a leader may
// bridge a short way, never across the picture; and an arrow lifted into a row above the bodies
// or drawn back from a wall (no longer starting over its body) carries its value or its body's
// number beside it, nearer that arrow than anything else.
// Checked on the frame description with the painter's own geometry (render/layout.hpp).
#include <string>

#include "render/frame_model.hpp"
#include "render/text_metrics.hpp"

namespace collide::compose_test {

// A leader is at most this many text heights (ascender + descender of its label's text) long.
inline constexpr double kLongestLeaderLines = 3.0;
// A label's own body (a readout's: or its arrow) is nearer it than any other body or arrow by at
// least this many of its text heights.
inline constexpr double kNearerByLines = 0.25;

// Adds a gtest failure naming `where` for every label of `frame` (placed for width_px × height_px,
// text_floor_px as compose placed it) that hangs on a long leader, and for every lifted or
// drawn-back arrow left without a tie.
void expectLabelsReadAsTheirOwn(const render::FrameModel& frame, int width_px, int height_px,
                                double text_floor_px, render::TextMetrics& metrics,
                                const std::string& where);

}  // namespace collide::compose_test
