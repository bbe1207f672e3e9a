#pragma once
// SPDX-License-Identifier: MIT
// Version 2's "events" of `collide data --json --events`: every event of the run in time order,
// each with its kind, the bodies (numbered from 1) and walls it involves, their positions and
// velocities, and its share of the energy books (docs/data-format.md).
#include "physics/timeline.hpp"
#include "report/json_writer.hpp"

namespace collide::report {

// Writes the "events" array (its key written by the caller). The losses of the events add up to
// the run's energy_lost, their releases to its energy_released.
void writeJsonEvents(JsonWriter& json, const physics::Timeline& timeline);

}  // namespace collide::report
