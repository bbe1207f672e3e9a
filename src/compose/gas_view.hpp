#pragma once
// How a panel of many bodies (a gas) is drawn: hundreds of arrows, contact flashes and number tags
// would bury the bodies they belong to, so a panel of more than kGasBodies bodies shows the bodies
// alone, and the speeds go to the histogram (speed_histogram.hpp).
#include "frame/frame_model.hpp"
#include "scene/scene_desc.hpp"

namespace collide::compose {

inline constexpr std::size_t kGasBodies = 40;

inline bool isGas(const scene::SceneDesc& scene) {
  return scene.bodies.size() > kGasBodies;
}

// Takes the per-body arrows, flashes and tags off a panel of a gas.
void drawAsGas(frame::PanelModel& panel);

}  // namespace collide::compose
