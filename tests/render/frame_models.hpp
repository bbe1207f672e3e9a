#pragma once
// Hand-built frames shared by the render tests.
#include "render/frame_model.hpp"

namespace collide::render::testing {

inline constexpr Rgba kBlue{0.12f, 0.47f, 0.71f, 1.0f};
inline constexpr Rgba kOrange{1.0f, 0.5f, 0.05f, 1.0f};
inline constexpr Rgba kGray{0.6f, 0.6f, 0.6f, 1.0f};

// Two blocks on a track moving towards each other; bar: KE1 0.45 J, KE2 0.30 J, lost 0.15 J of 1 J.
FrameModel twoBlocks();

// A disk, a translucent block overlapping it, one body at rest; no track.
FrameModel diskAndTranslucent();

}  // namespace collide::render::testing
