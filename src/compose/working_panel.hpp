// SPDX-License-Identifier: MIT
#pragma once
// The working panel's content (issue 41): the working of a scene's first impact (src/working) as
// the lines a painter typesets beside the scene.
#include <optional>

#include "frame/frame_model.hpp"
#include "physics/timeline.hpp"

namespace collide::compose {

// The working of the first impact as the panel shows it: headings and equations, without the
// laws solved in symbols (the numbers substituted show them) and the notes in words, which stay
// in `collide solve`; nullopt when the run has no impact.
std::optional<frame::WorkingModel> workingPanel(const physics::Timeline& timeline);

// Simulated seconds between one step of the working appearing and the next, from the impact on,
// where the scene runs long enough after its impact for every step to appear so.
inline constexpr double kWorkingStepDelay_s = 0.2;

// How many of the panel's lines show at t_s in a video of a scene that ends at end_s: the given
// values from the start, each further step a delay after the one before, the first of them at the
// impact (`impact_s`). The delay is kWorkingStepDelay_s, shorter where the scene would end first:
// every step has appeared by the video's last frame, which a strobe picture's whole working and a
// still at the scene's end then match (a still at t is the video's frame at t).
int workingLinesShown(const frame::WorkingModel& working, double impact_s, double end_s,
                      double t_s);

}  // namespace collide::compose
