#include "physics/pi_blocks.hpp"

#include <cmath>

#include "core/error.hpp"

namespace collide::physics {

WorldDef piBlocksWorld(int digits) {
  COLLIDE_ASSERT(digits >= 1 && digits <= 9, "digits must be in [1, 9]");
  WorldDef world;
  world.dimensions = 1;
  world.restitution = 1.0;
  world.duration_s = 12.0;
  world.walls.push_back({"wall", {0.0, 0.0}, {1.0, 0.0}, 1.0});
  BodyDef small;
  small.name = "small";
  small.mass_kg = 1.0;
  small.size_m = 0.4;
  small.position_m = {1.5, 0.0};
  BodyDef big;
  big.name = "big";
  big.mass_kg = 1.0;
  for (int k = 1; k < digits; ++k) big.mass_kg *= 100.0;  // exact: 100^8 = 2^16 5^16
  big.size_m = 1.0;
  big.position_m = {3.5, 0.0};
  big.velocity_mps = {-1.0, 0.0};
  world.bodies = {small, big};
  return world;
}

}  // namespace collide::physics
