// What every preset is built from: its scene and its bodies.
#include "scene/preset_builders.hpp"

#include <utility>

namespace collide::scene::detail {

BodyDesc body(const std::string& name, const std::string& shape, double mass_kg, double size_m,
              core::Vec2 position_m, core::Vec2 velocity_mps) {
  BodyDesc b;
  b.name = name;
  b.shape = shape;
  b.mass_kg = mass_kg;
  b.size_m = size_m;
  b.position_m = position_m;
  b.velocity_mps = velocity_mps;
  return b;
}

BodyDesc block(const std::string& name, double mass_kg, double width_m, double x_m, double v_mps) {
  return body(name, "block", mass_kg, width_m, {x_m, 0.0}, {v_mps, 0.0});
}

SceneDesc presetScene(int dimensions, const std::string& name, const std::string& title,
                      double duration_s, double e, std::vector<BodyDesc> bodies) {
  SceneDesc scene;
  scene.name = name;
  scene.title = title;
  scene.dimensions = dimensions;
  scene.duration_s = duration_s;
  scene.restitution = e;
  scene.bodies = std::move(bodies);
  return scene;
}

}  // namespace collide::scene::detail
