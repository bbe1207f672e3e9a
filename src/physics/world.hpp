#pragma once
// Plain definition structs: what the simulation is asked to run. Every field has a default and a
// unit. Validation of user input happens in scene/; physics asserts only on programmer mistakes.
#include <string>
#include <vector>

#include "core/vec.hpp"

namespace collide::physics {

enum class Shape {
  kBlock,  // 1D: a block sliding on the x axis; size_m is its full width
  kDisk,   // 2D: a smooth disk in the plane; size_m is its radius
};

struct BodyDef {
  std::string name;                         // shown in labels and data files
  Shape shape = Shape::kBlock;
  double mass_kg = 1.0;                     // > 0
  double size_m = 0.5;                      // block width or disk radius, > 0
  core::Vec2 position_m = {0.0, 0.0};       // centre; y is ignored in 1D
  core::Vec2 velocity_mps = {0.0, 0.0};     // y is ignored in 1D
};

// An infinitely massive wall: the half-plane behind `point_m` opposite to `normal`.
struct WallDef {
  std::string name;                         // reported as the partner in collision events
  core::Vec2 point_m = {0.0, 0.0};          // any point on the wall
  core::Vec2 normal = {1.0, 0.0};           // unit normal pointing into the free space
  double restitution = 1.0;                 // e for impacts on this wall, in [0, 1]
};

struct WorldDef {
  int dimensions = 1;                       // 1: blocks on a line, 2: disks in a plane
  std::vector<BodyDef> bodies;
  std::vector<WallDef> walls;
  core::Vec2 gravity_mps2 = {0.0, 0.0};     // uniform acceleration
  double restitution = 1.0;                 // default e for every body pair, in [0, 1]
  double duration_s = 1.0;                  // simulated time span, > 0
};

}  // namespace collide::physics
