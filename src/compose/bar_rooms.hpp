// SPDX-License-Identifier: MIT
#pragma once
// The energy bar's legend planned over the whole picture (issue 37): each entry keeps the room of
// the widest label it has in any frame, and one never labelled keeps none, so the legend's rows
// and every entry's place are the same in every frame of a video and in a still at any instant
// (but a printed figure, one frame of its own: FrameSource); an entry whose segment has no width
// for a while is left out there, the others standing still.
#include <string>
#include <vector>

#include "compose/frame_builder.hpp"
#include "compose/palette.hpp"
#include "physics/timeline.hpp"
#include "scene/scene_desc.hpp"
#include "text/text_wrap.hpp"

namespace collide::compose {

// Each bar segment's widest label (FramePlan::bar_rooms), "" for one never labelled: the bar as
// energyBar makes it (with the plan's final formats) at evenly spaced instants, at every
// collision and in the middle of every soft contact (a spring holds energy only then), its labels
// compared by `width`.
std::vector<std::string> planBarRooms(const scene::SceneDesc& scene,
                                      const physics::Timeline& timeline, const FramePlan& plan,
                                      const Theme& theme, const text::TextWidth& width);

}  // namespace collide::compose
