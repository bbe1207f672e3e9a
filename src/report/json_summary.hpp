#pragma once
// The machine-readable summary of a simulation (`collide data SCENE --json`), so its numbers can be
// checked from outside: bodies, momentum and energy before and after, energy lost, and optionally
// every event (docs/data-format.md, docs/data.schema.json). Version 2 (the default) numbers bodies
// from 1, gives positions and the potential energy, and logs "events" of every kind; version 1
// logs "collisions" with bodies numbered from 0.
#include <ostream>
#include <string>

#include "physics/timeline.hpp"
#include "report/data_version.hpp"

namespace collide::report {

struct JsonSummaryOptions {
  std::string scene_name;
  bool include_collisions = false;  // --events: the "events" (version 1: "collisions") array
  int version = kDataVersion;       // kOldestDataVersion to kDataVersion
};

// About how many bytes writeJsonSummary writes for `timeline` (an event is some 370 bytes; in
// version 2 some 560).
double estimateJsonSummaryBytes(const physics::Timeline& timeline,
                                const JsonSummaryOptions& options);

void writeJsonSummary(std::ostream& out, const physics::Timeline& timeline,
                      const JsonSummaryOptions& options);

}  // namespace collide::report
