// SPDX-License-Identifier: MIT
// What the scene loader says of a scene file's text: its one-line error, or "" when it loads.
// The scene key tests ask this of many small scene texts.
#pragma once

#include <string>

#include "scene/scene_io.hpp"

namespace collide::scene::testing {

inline std::string problemOf(const std::string& text) {
  try {
    parseSceneText(text, "scene.toml");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

}  // namespace collide::scene::testing
