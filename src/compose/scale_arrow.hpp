#pragma once
// The velocity scale arrow ("1 m/s" at the caption's end) read at the picture's size. It is drawn
// exactly to scale (frame::scaleArrowShape), so its speed is chosen long enough to read: at
// least the visible minimum render gives a body's arrow.
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"

namespace collide::compose {

// For every panel of `frame` with a scale arrow, laid out as `layout`: the plan's round speed if
// its arrow is at least the visible minimum of a body's arrow, else the next round speed (1, 2 or
// 5 × 10^k) that is, as long as it stays within an eighth of the panel's scene width; its label
// rewritten ("2 m/s"). It depends only on the picture's size and the (fixed) arrow scale, so
// every frame of a picture states the same one.
void fitScaleArrows(frame::FrameModel& frame, const frame::FrameLayout& layout);

// The largest round value (1, 2 or 5 × 10^k) at most `most` (> 0); 0 for most <= 0.
double roundValueBelow(double most);

// The scale arrow's label for a speed, e.g. "0.5 m/s", in the active language's numbers.
std::string scaleArrowLabel(double speed_mps);

}  // namespace collide::compose
