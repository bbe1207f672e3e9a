#include "app/world_from_scene.hpp"

namespace collide::app {
namespace {

physics::RestitutionModel restitutionModel(const scene::RestitutionLawDesc& law) {
  physics::RestitutionModel model;
  switch (law.kind) {
    case scene::RestitutionLawKind::kConstant:
      model.law = physics::RestitutionLaw::kConstant;
      break;
    case scene::RestitutionLawKind::kSpeedThreshold:
      model.law = physics::RestitutionLaw::kSpeedThreshold;
      break;
    case scene::RestitutionLawKind::kTable:
      model.law = physics::RestitutionLaw::kTable;
      break;
  }
  model.threshold_speed_mps = law.threshold_speed_mps;
  model.exponent = law.exponent;
  for (const auto& [speed_mps, e] : law.table) model.table.push_back({speed_mps, e});
  return model;
}

// A ball's spin as the cue leaves it: rolling (follow), none (stop) or rolling's backwards (draw).
core::Vec2 strikeSpin(const scene::BodyDesc& body) {
  const double turns = body.spin == "stop" ? 0.0 : body.spin == "draw" ? -1.0 : 1.0;
  return turns / body.size_m * core::Vec2(-body.velocity_mps.y(), body.velocity_mps.x());
}

}  // namespace

physics::WorldDef worldFromScene(const scene::SceneDesc& scene) {
  physics::WorldDef world;
  world.dimensions = scene.dimensions;
  world.duration_s = scene.duration_s;
  world.gravity_mps2 = scene.gravity_mps2;
  world.restitution = scene.restitution;
  world.string_restitution = scene.string_restitution;
  world.surface_gravity_mps2 = scene.surface_gravity_mps2;
  world.internal_dof = scene.internal_dof;
  world.rolling = scene.rolling;
  for (const scene::BodyDesc& body : scene.bodies) {
    physics::BodyDef def;
    def.name = body.name;
    const bool disk = body.shape == "disk";
    def.shape = disk && scene.dimensions == 2 ? physics::Shape::kDisk : physics::Shape::kBlock;
    def.mass_kg = body.mass_kg;
    // The scene gives a disk's radius; on a line the physics needs the full width (a ball on a
    // track is a block as wide as the ball).
    def.size_m = disk && scene.dimensions == 1 ? 2.0 * body.size_m : body.size_m;
    def.position_m = body.position_m;
    def.velocity_mps = body.velocity_mps;
    def.on_string = body.pivot_m.has_value();
    def.pivot_m = body.pivot_m.value_or(core::Vec2{0.0, 0.0});
    def.friction = body.friction;
    def.static_friction = body.static_friction.value_or(body.friction);
    def.drag_linear_kgps = body.drag_linear_kgps;
    def.drag_quadratic_kgpm = body.drag_quadratic_kgpm;
    def.rolling_friction = body.rolling_friction;
    if (scene.rolling) def.spin_radps = strikeSpin(body);
    world.bodies.push_back(def);
  }
  // The scene's walls, then the box's, in the order scene::allWalls gives (event logs name them).
  for (const scene::WallDesc& wall : scene::allWalls(scene)) {
    world.walls.push_back(
        {wall.name, wall.position_m, wall.normal, scene::wallRestitution(scene, wall)});
  }
  for (const scene::PairDesc& pair : scene.pairs) {
    world.pair_restitution.push_back({pair.body_a, pair.body_b, pair.restitution});
  }
  for (const scene::ReleaseDesc& release : scene.releases) {
    world.releases.push_back({release.body_a, release.body_b, release.time_s,
                              release.energy_J.value_or(0.0), release.speed_mps.value_or(0.0)});
  }
  world.restitution_model = restitutionModel(scene.restitution_law);
  world.contact_model = scene.contact.model == scene::ContactModelKind::kSpringDamper
                            ? physics::ContactModel::kSpringDamper
                            : physics::ContactModel::kImpulse;
  world.contact_duration_s = scene.contact.duration_s;
  world.inelastic_mode = scene.contact.inelastic == scene::InelasticMode::kStick
                             ? physics::InelasticMode::kStick
                             : physics::InelasticMode::kSlip;
  world.collapse_time_s = scene.contact.collapse_time_s;
  return world;
}

}  // namespace collide::app
