#include "app/world_from_scene.hpp"

namespace collide::app {

physics::WorldDef worldFromScene(const scene::SceneDesc& scene) {
  physics::WorldDef world;
  world.dimensions = scene.dimensions;
  world.duration_s = scene.duration_s;
  world.gravity_mps2 = scene.gravity_mps2;
  world.restitution = scene.restitution;
  for (const scene::BodyDesc& body : scene.bodies) {
    physics::BodyDef def;
    def.name = body.name;
    def.shape = body.shape == "disk" ? physics::Shape::kDisk : physics::Shape::kBlock;
    def.mass_kg = body.mass_kg;
    def.size_m = body.size_m;
    def.position_m = body.position_m;
    def.velocity_mps = body.velocity_mps;
    world.bodies.push_back(def);
  }
  for (const scene::WallDesc& wall : scene.walls) {
    world.walls.push_back({wall.name, wall.position_m, wall.normal, wall.restitution});
  }
  return world;
}

}  // namespace collide::app
