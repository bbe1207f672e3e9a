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

// Frames for a picture of `size`, labels placed with the painter's text measure. Throws
// core::InputError for a bad theme or panel parameter in scene.view (or a language whose font is
// not installed), render::FontError for a font that cannot be loaded.
Animation animate(const scene::SceneDesc& scene, compose::PictureSize size);

}  // namespace collide::app
