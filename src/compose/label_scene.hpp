#pragma once
// A panel's scene as label placement sees it (LabelScene): every body, arrow, wall, flash, string,
// beam, dimension line, the track, the ruler and the momentum diagram as the painter draws them,
// the obstacles every text keeps clear of.
#include "compose/label_candidates.hpp"
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"

namespace collide::compose {

// `area` is the panel's world area, `small_line_px` the height of a line of small text (the
// ruler's numbers). Texts keep inside the panel's world clip and the frame's margin (the title's,
// from every edge of the frame), or with `in_margin` only the world clip.
LabelScene describePanel(const frame::PanelModel& panel, const frame::PanelLayout& where,
                         const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                         const frame::PixelRect& area, double small_line_px,
                         bool in_margin = false);

}  // namespace collide::compose
