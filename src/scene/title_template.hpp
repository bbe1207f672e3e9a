#pragma once
// Internal to collide_scene: titles with placeholders. "{restitution}", "{body.2.mass}" or any
// other key path that --set accepts is replaced by the scene's value, so that "e = {restitution}"
// stays true under --set restitution=1 and in a sweep. "{{" and "}}" are literal braces.
#include <string>

#include "scene/scene_desc.hpp"

namespace collide::scene::detail {

// `title` with its placeholders filled from `scene` (defaults included). On a placeholder that
// names no value, returns "" and sets `problem` to "what is wrong; allowed: ...".
std::string fillTitle(const std::string& title, const SceneDesc& scene, std::string& problem);

}  // namespace collide::scene::detail
