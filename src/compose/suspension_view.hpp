#pragma once
// Bodies on strings in a panel: the bar the strings hang from, a string from each pivot to its
// body, the arc each body has swept (view.arc_trail) and, for a body caught by a hanging one
// (a ballistic pendulum), the rise to the top of the swing with a dimension line and the speed
// that rise gives back beside the true one.
#include "compose/frame_builder.hpp"

namespace collide::compose {

// Fills panel.suspension; panel.bodies must hold this instant's bodies.
void addSuspension(frame::PanelModel& panel, const scene::SceneDesc& scene,
                   const physics::Timeline& timeline, const FramePlan& plan, double t_s);

// The view must show the pivots and the bar: grows [low, high] to hold them.
void includePivots(const scene::SceneDesc& scene, core::Vec2& low, core::Vec2& high);

}  // namespace collide::compose
