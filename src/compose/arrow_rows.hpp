#pragma once
// 1D pictures: velocity arrows drawn over one another's span are lifted into rows, so the arrows
// of two bodies closing on each other never cross in the gap between them.
#include "render/frame_model.hpp"

namespace collide::compose {

// Sets BodyModel::arrow_row of every body of a 1D panel: body by body in index order, the lowest
// row where its arrow's span (tail at the centre, to scale or off-scale as render::arrowShape
// draws it, and a margin of `margin_m` each side) meets no arrow already in that row. 2D panels
// and bodies without an arrow keep row 0.
void assignArrowRows(render::PanelModel& panel, double margin_m);

}  // namespace collide::compose
