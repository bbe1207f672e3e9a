#pragma once
#include "physics/world.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {

// The physics world a scene describes (the scene is already validated).
physics::WorldDef worldFromScene(const scene::SceneDesc& scene);

}  // namespace collide::app
