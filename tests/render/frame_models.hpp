#pragma once
// Hand-built frames shared by the render tests.
#include "frame/frame_model.hpp"

namespace collide::render::testing {

inline constexpr frame::Rgba kBlue{0.12f, 0.47f, 0.71f, 1.0f};
inline constexpr frame::Rgba kOrange{1.0f, 0.5f, 0.05f, 1.0f};
inline constexpr frame::Rgba kGray{0.6f, 0.6f, 0.6f, 1.0f};

// Two blocks on a track moving towards each other; bar: KE1 0.45 J, KE2 0.30 J, lost 0.15 J of 1 J.
// No text at all (shapes only).
frame::FrameModel twoBlocks();

// A disk, a translucent block overlapping it, one body at rest; no track; no text.
frame::FrameModel diskAndTranslucent();

// twoBlocks with every annotation: title, time, labels with subscripts and primes, bar labels,
// info line, caption, ruler.
frame::FrameModel labelledBlocks();

// 2D: three disks (one spinning with an orientation mark, two bonded), a wall, trails, a contact
// flash, the centre-of-mass marker and a momentum diagram.
frame::FrameModel twoDimensional();

// One block at rest on the left of a 1D scene (no track, no arrow) whose mass label compose placed
// right of it, a leader running left from it, at `label_opacity`, and one legend line (the
// block's readout) below that at `legend_opacity`: a label fading between its body and its
// legend (frame::PlacedText::opacity). Placed for width_px × height_px.
frame::FrameModel fadingLabels(int width_px, int height_px, float label_opacity,
                               float legend_opacity);

// A chart alone: two solid series, one dashed, cursor at 60% of the x range.
frame::FrameModel chartOnly();

}  // namespace collide::render::testing
