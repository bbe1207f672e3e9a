#pragma once
// Small worlds for the report tests, with every expected number derived in the tests themselves.
#include <string>

#include "physics/simulate.hpp"

namespace collide::report::test {

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// 2 kg at x = -1 m moving at 3 m/s towards 1 kg at rest at x = 1 m; both 0.5 m wide, so they meet
// when the gap of 1.5 m has closed: t = 1.5 / 3 = 0.5 s.
inline physics::WorldDef twoBlocks(double e, double duration_s = 3.0) {
  physics::WorldDef world;
  world.dimensions = 1;
  world.duration_s = duration_s;
  world.restitution = e;
  world.bodies.push_back({"left", physics::Shape::kBlock, 2.0, 0.5, {-1.0, 0.0}, {3.0, 0.0}});
  world.bodies.push_back({"right", physics::Shape::kBlock, 1.0, 0.5, {1.0, 0.0}, {0.0, 0.0}});
  return world;
}

// twoBlocks plus a wall at x = 3 m facing left: "right" bounces back and meets "left" again.
inline physics::WorldDef twoBlocksAndWall(double e) {
  physics::WorldDef world = twoBlocks(e, 4.0);
  world.walls.push_back({"far", {3.0, 0.0}, {-1.0, 0.0}, 1.0});
  return world;
}

}  // namespace collide::report::test
