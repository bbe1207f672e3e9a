#pragma once
// The machine-readable summary of a simulation (`collide data SCENE --json`), so its numbers can be
// checked from outside: bodies, momentum and kinetic energy before and after, energy lost, and
// optionally every collision.
#include <ostream>
#include <string>

#include "physics/timeline.hpp"

namespace collide::report {

struct JsonSummaryOptions {
  std::string scene_name;
  bool include_collisions = false;  // --events: the "collisions" array
};

// About how many bytes writeJsonSummary writes for `timeline` (an event is some 370 bytes).
double estimateJsonSummaryBytes(const physics::Timeline& timeline,
                                const JsonSummaryOptions& options);

void writeJsonSummary(std::ostream& out, const physics::Timeline& timeline,
                      const JsonSummaryOptions& options);

}  // namespace collide::report
