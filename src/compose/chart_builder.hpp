#pragma once
// Charts against time: each body's kinetic energy, the total, potential energy (with gravity) and
// the energy lost; or the momenta; or the contact force of soft contacts (F = dp/dt, the area
// under a pulse is the impulse). Fixed axes over the whole scene.
#include <string>

#include "compose/frame_builder.hpp"
#include "compose/palette.hpp"
#include "frame/frame_model.hpp"
#include "physics/timeline.hpp"
#include "scene/scene_desc.hpp"

namespace collide::compose {

// quantity: "energy", "momentum" or "force" (ViewDesc::chart_quantity); anything else: energy.
// "speed": the speed histogram at the end (speed_histogram.hpp; frames build their own).
frame::ChartModel buildChart(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                             const FramePlan& plan, const Theme& theme,
                             const std::string& quantity);

}  // namespace collide::compose
