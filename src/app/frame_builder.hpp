#pragma once
// Turns physics snapshots into FrameModels: chooses a camera that frames the whole motion once per
// timeline, then maps each sampled state to bodies, arrows and the energy bar.
#include "physics/timeline.hpp"
#include "render/frame_model.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {

// Per-timeline drawing choices, fixed for every frame so the picture does not jump.
struct FramePlan {
  render::ViewWindow view;
  double arrow_m_per_mps = 0.25;  // world metres of arrow per m/s
  double energy_full_scale_J = 1.0;
};

FramePlan planFrames(const scene::SceneDesc& scene, const physics::Timeline& timeline);

render::FrameModel buildFrame(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                              const FramePlan& plan, const physics::Snapshot& snapshot);

}  // namespace collide::app
