// SPDX-License-Identifier: MIT
// collide_scene_schema: prints docs/scene.schema.json as the field table makes it. Regenerate the
// committed file with: build/tests/scene/collide_scene_schema > docs/scene.schema.json
#include <iostream>

#include "scene/scene_io.hpp"

int main() {
  std::cout << collide::scene::sceneJsonSchema();
  return std::cout ? 0 : 1;
}
