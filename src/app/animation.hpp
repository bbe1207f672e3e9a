#pragma once
// A scene simulated (each comparison panel once) and handed to compose, which turns it into
// frames; with the physics warnings of every panel, for the user.
#include <string>
#include <vector>

#include "compose/frame_source.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {

struct Animation {
  compose::FrameSource frames;
  std::vector<std::string> warnings;  // physicsWarnings of each panel, headed by its heading
};

// Frames for a picture of `size`. Throws core::InputError for a bad theme or panel parameter in
// scene.view.
Animation animate(const scene::SceneDesc& scene, compose::PictureSize size);

}  // namespace collide::app
