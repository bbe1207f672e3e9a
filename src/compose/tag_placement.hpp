#pragma once
// The number of a body too small to carry it inside (a billiard ball at 640x360), written beside
// the body where nothing else is, when the readout legend names the body by it ("m₁ = 0.170 kg"
// in the legend, "1" by its ball): a legend entry always names something the picture shows.
#include <optional>
#include <utility>
#include <vector>

#include "compose/placement_obstacles.hpp"
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"
#include "text/text_measure.hpp"

namespace collide::compose {

// Sets BodyModel::tag_at of every body of `panel` with named[i], a tag, and no room for it inside
// (frame::tagFitsInside): the first free place (`obstacles`, which holds every text placed so
// far) around the body, nearest first, clearly nearer its own body than any other body or any
// other body's arrow (readAsOthers; `arrows`: per body, tail and tip in pixels; `moves_with`: per
// body, the body it rides on, or -1); adds it to `obstacles`. Where none is free the tag stays
// inside (unseen).
void placeTagsBeside(frame::PanelModel& panel, const std::vector<bool>& named,
                     const BodyArrows& arrows, const std::vector<int>& moves_with,
                     const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                     text::TextMeasure& metrics, Obstacles& obstacles);

// Sets BodyModel::arrow_tag_at of every body of a 1D `panel` whose arrow is lifted above the
// bodies (arrow_row > 0) or drawn back from a wall (its tail behind the body) and carries no
// readout beside it (its value in the legend): its number
// just behind the arrow's tail on the arrow's line, else above or below the tail (or along the
// shaft from it, as far as its middle), in the first free place clearly nearer that arrow than
// any other arrow or body; adds it to `obstacles`.
void placeArrowTags(frame::PanelModel& panel, const BodyArrows& arrows,
                    const std::vector<int>& moves_with, const frame::FrameLayout& layout,
                    const frame::WorldToPixel& to_px, text::TextMeasure& metrics,
                    Obstacles& obstacles);

}  // namespace collide::compose
