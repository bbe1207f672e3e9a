#pragma once
// Galperin's billiard: a small block between a wall and a big block of 100^(d - 1) times its mass,
// everything elastic. The number of collisions is the first d digits of pi. The engine is the
// general 1D one; nothing here knows the answer.
#include "physics/world.hpp"

namespace collide::physics {

// digits d in [1, 9]. Wall "wall" at x = 0; "small" (1 kg, 0.4 m wide) at rest with its centre
// at x = 1.5 m; "big" (100^(d-1) kg, 1 m wide) centred at x = 3.5 m moving at -1 m/s. The duration
// (12 s) covers every collision with room to see the blocks leave.
WorldDef piBlocksWorld(int digits);

}  // namespace collide::physics
