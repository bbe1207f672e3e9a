#pragma once
// Small builders for test worlds.
#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "physics/world.hpp"

namespace collide::physics::testing {

// "b3" and the like (snprintf: GCC 12 warns falsely on "b" + std::to_string(k)).
inline std::string numbered(const char* prefix, int k) {
  char text[32];
  std::snprintf(text, sizeof text, "%s%d", prefix, k);
  return text;
}

inline BodyDef block(const std::string& name, double mass_kg, double width_m, double x_m,
                     double v_mps) {
  BodyDef body;
  body.name = name;
  body.shape = Shape::kBlock;
  body.mass_kg = mass_kg;
  body.size_m = width_m;
  body.position_m = {x_m, 0.0};
  body.velocity_mps = {v_mps, 0.0};
  return body;
}

inline BodyDef disk(const std::string& name, double mass_kg, double radius_m, core::Vec2 x_m,
                    core::Vec2 v_mps) {
  BodyDef body;
  body.name = name;
  body.shape = Shape::kDisk;
  body.mass_kg = mass_kg;
  body.size_m = radius_m;
  body.position_m = x_m;
  body.velocity_mps = v_mps;
  return body;
}

inline WallDef wall(const std::string& name, core::Vec2 point_m, core::Vec2 normal,
                    double restitution = 1.0) {
  return WallDef{name, point_m, normal.normalized(), restitution};
}

// The four walls of the square box [-half_m, half_m]^2, facing in: left, right, floor, ceiling,
// in that order, with `restitution` each in that order.
inline std::vector<WallDef> boxWalls(double half_m, const std::array<double, 4>& restitution) {
  return {wall("left", {-half_m, 0.0}, {1.0, 0.0}, restitution[0]),
          wall("right", {half_m, 0.0}, {-1.0, 0.0}, restitution[1]),
          wall("floor", {0.0, -half_m}, {0.0, 1.0}, restitution[2]),
          wall("ceiling", {0.0, half_m}, {0.0, -1.0}, restitution[3])};
}

// The same box, every wall with one restitution.
inline std::vector<WallDef> boxWalls(double half_m, double restitution = 1.0) {
  return boxWalls(half_m, {restitution, restitution, restitution, restitution});
}

}  // namespace collide::physics::testing
