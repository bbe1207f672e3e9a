#pragma once
#include "physics/timeline.hpp"
#include "physics/world.hpp"

namespace collide::physics {

// Runs the event-driven simulation of `world` over [0, world.duration_s]. Times of impact are
// solved analytically; nothing is stepped. The world must be valid (see scene validation).
Timeline simulate(const WorldDef& world);

}  // namespace collide::physics
