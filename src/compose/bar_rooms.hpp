// SPDX-License-Identifier: MIT
#pragma once
// The energy bar's legend planned over the whole picture (issue 37): each entry keeps the room of
// the widest label it has in any frame, and one never labelled keeps none, so the legend's rows
// and every entry's place are the same in every frame of a video and in a still at any instant
// (but a printed figure, one frame of its own: FrameSource); an entry whose segment has no width
// for a while is left out there, the others standing still. Within a shot an entry labelled at
// any instant of it stays while its segment has energy (FramePlan::bar_shots): a crowded bar's
// small segment (a cradle's PE near the bottom of the swing) no longer comes and goes.
#include <string>
#include <vector>

#include "compose/frame_builder.hpp"
#include "compose/palette.hpp"
#include "physics/timeline.hpp"
#include "scene/scene_desc.hpp"
#include "text/text_wrap.hpp"

namespace collide::compose {

// Sets plan.bar_rooms, each bar segment's widest label ("" for one never labelled), and
// plan.bar_shots, the segments labelled in each shot of `shot_starts_s` (label_timeline.hpp's
// shotStarts): the bar as energyBar makes it (with the plan's final formats) at evenly spaced
// instants (at least kShotSamples in each shot), at every collision and in the middle of every
// soft contact (a spring holds energy only then), its labels compared by `width`.
void planBarLegend(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                   FramePlan& plan, const Theme& theme, const text::TextWidth& width,
                   const std::vector<double>& shot_starts_s);

}  // namespace collide::compose
