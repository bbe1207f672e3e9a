#pragma once
#include <cstdint>
#include <functional>

#include "physics/timeline.hpp"
#include "physics/world.hpp"

namespace collide::physics {

// Told now and then how far a run has got: the simulated time reached, in seconds (from 0 to
// world.duration_s), and the collisions so far. Called where the run checks for a stop request
// (after each collision at first, later every few thousand), so it must be cheap; for progress
// reports.
using SimulationProgress = std::function<void(double simulated_s, std::int64_t collisions)>;

// Runs the event-driven simulation of `world` over [0, world.duration_s]. Times of impact are
// solved analytically; nothing is stepped. The world must be valid (see scene validation).
// `progress`, when set, hears how far the run has got (see SimulationProgress).
Timeline simulate(const WorldDef& world, const SimulationProgress& progress = {});

}  // namespace collide::physics
