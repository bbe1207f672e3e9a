#pragma once
// 1D pictures: velocity arrows drawn over one another's span are lifted into rows, so the arrows
// of two bodies closing on each other never cross in the gap between them, and an arrow that
// would run across a taller body (a bullet's at the block) goes over it.
#include "frame/frame_model.hpp"

namespace collide::compose {

// Sets BodyModel::arrow_row of every body of a 1D panel: body by body in index order, the lowest
// row where its arrow's span (tail at the centre, to scale or off-scale as frame::arrowShape
// draws it, drawn back from a wall it would reach, and a margin of `margin_m` each side) meets no
// arrow already in that row; never row 0 where the span crosses a body taller than its own (row
// 0 runs just over its own body). 2D panels and bodies without an arrow keep row 0.
void assignArrowRows(frame::PanelModel& panel, double margin_m);

}  // namespace collide::compose
