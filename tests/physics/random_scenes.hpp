#pragma once
// Random scenes for property tests, from a fixed seed. The generator is spelled out here (not
// std::uniform_real_distribution, whose output differs between standard libraries) so the scenes
// are the same everywhere.
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "physics/world.hpp"
#include "worlds.hpp"

namespace collide::physics::testing {

class Dice {
 public:
  explicit Dice(std::uint64_t seed) : engine_(seed) {}
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(engine_() >> 11) * 0x1.0p-53;
  }
  int integer(int lo, int hi) { return lo + static_cast<int>(engine_() % (hi - lo + 1)); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
  // A restitution drawn to exercise merges (0), elastic (1) and everything between.
  double restitution() {
    const int kind = integer(0, 4);
    if (kind == 0) return 0.0;
    if (kind == 1) return 1.0;
    return uniform(0.0, 1.0);
  }

 private:
  std::mt19937_64 engine_;
};

struct SceneTraits {
  bool walls = false;
  bool gravity = false;
  bool soft = false;
};

inline WorldDef randomLine(Dice& dice, SceneTraits& traits) {
  WorldDef world;
  world.dimensions = 1;
  world.duration_s = 4.0;
  world.restitution = dice.restitution();
  traits.walls = dice.chance(0.5);
  traits.gravity = traits.walls && dice.chance(0.3);
  const int n = dice.integer(2, 7);
  double x = 0.0;
  for (int i = 0; i < n; ++i) {
    const double width = dice.uniform(0.1, 0.6);
    x += dice.chance(0.2) ? 0.0 : dice.uniform(0.0, 1.0);  // sometimes touching
    x += 0.5 * width;
    // Drawn one statement each: the order of a call's arguments is the compiler's choice (g++
    // draws right to left, clang left to right), and every build must see the same scenes.
    const double velocity_mps = dice.uniform(-3.0, 3.0);
    const double mass_kg = dice.uniform(0.1, 10.0);
    world.bodies.push_back(block(numbered("b", i), mass_kg, width, x, velocity_mps));
    x += 0.5 * width;
  }
  for (int k = dice.integer(0, 2); k > 0; --k) {
    const int a = dice.integer(0, n - 1), b = dice.integer(0, n - 1);
    if (a != b) world.pair_restitution.push_back({a, b, dice.restitution()});
  }
  if (traits.walls) {
    const double left_restitution = dice.restitution();  // before its place, as g++ drew them
    world.walls.push_back(
        wall("left", {-dice.uniform(0.0, 1.0), 0.0}, {1.0, 0.0}, left_restitution));
    const double right_restitution = dice.restitution();
    world.walls.push_back(
        wall("right", {x + dice.uniform(0.0, 1.0), 0.0}, {-1.0, 0.0}, right_restitution));
  }
  if (traits.gravity) world.gravity_mps2 = {dice.uniform(-10.0, 10.0), 0.0};
  return world;
}

inline WorldDef randomPlane(Dice& dice, SceneTraits& traits) {
  WorldDef world;
  world.dimensions = 2;
  world.duration_s = 4.0;
  world.restitution = dice.restitution();
  world.inelastic_mode = dice.chance(0.5) ? InelasticMode::kStick : InelasticMode::kSlip;
  traits.walls = dice.chance(0.6);
  traits.gravity = traits.walls && dice.chance(0.3);
  traits.soft = !traits.gravity && dice.chance(0.1);
  if (traits.soft) {
    world.contact_model = ContactModel::kSpringDamper;
    world.contact_duration_s = 0.002;
  }
  const double half = 2.0;  // box [-2, 2]^2
  if (traits.walls) {
    // One restitution a wall, drawn left to right (a braced list is evaluated in order).
    world.walls = boxWalls(
        half, {dice.restitution(), dice.restitution(), dice.restitution(), dice.restitution()});
    // Sometimes a slope cutting the lower left corner.
    if (dice.chance(0.3))
      world.walls.push_back(wall("slope", {-2.0, -1.0}, {1.0, 1.0}, dice.restitution()));
  }
  const int n = dice.integer(2, 7);
  for (int i = 0; i < n; ++i) {
    for (int attempt = 0; attempt < 100; ++attempt) {
      const double r = dice.uniform(0.1, 0.35);
      const double y_m = dice.uniform(-half + r, half - r);  // y first, as g++ drew them
      const core::Vec2 x(dice.uniform(-half + r, half - r), y_m);
      bool clear = true;
      for (const BodyDef& other : world.bodies) {
        if ((other.position_m - x).norm() < other.size_m + r) clear = false;
      }
      for (const WallDef& w : world.walls) {
        if ((x - w.point_m).dot(w.normal) < r) clear = false;
      }
      if (!clear) continue;
      const core::Vec2 velocity_mps{dice.uniform(-3.0, 3.0), dice.uniform(-3.0, 3.0)};
      const double mass_kg = dice.uniform(0.1, 10.0);
      world.bodies.push_back(disk(numbered("d", i), mass_kg, r, x, velocity_mps));
      break;
    }
  }
  if (traits.gravity) world.gravity_mps2 = {dice.uniform(-3.0, 3.0), -9.81};
  return world;
}

// The scene reflected about x = 0 with its bodies numbered in reverse: the same motion, reflected
// and renumbered, to 1e-12 of the scene's speeds and extent.
inline WorldDef mirroredAndRenumbered(const WorldDef& world) {
  WorldDef image = world;
  const int n = static_cast<int>(world.bodies.size());
  for (int i = 0; i < n; ++i) {
    BodyDef body = world.bodies[n - 1 - i];
    body.position_m.x() = -body.position_m.x();
    body.velocity_mps.x() = -body.velocity_mps.x();
    image.bodies[i] = body;
  }
  for (WallDef& wall : image.walls) {
    wall.point_m.x() = -wall.point_m.x();
    wall.normal.x() = -wall.normal.x();
  }
  for (PairRestitution& pair : image.pair_restitution) {
    pair.body_a = n - 1 - pair.body_a;
    pair.body_b = n - 1 - pair.body_b;
  }
  image.gravity_mps2.x() = -image.gravity_mps2.x();
  return image;
}

}  // namespace collide::physics::testing
