#pragma once
// The physics warnings of a run (stopped at a cap, stalled, a soft contact off target, the
// collapse rule used) as lines for the user: every command that simulates prints them to stderr,
// and batch workers report them into the manifest.
#include <iosfwd>
#include <string>
#include <vector>

#include "physics/timeline.hpp"

namespace collide::report {

// One sentence per warning, prefixed with `context` (e.g. a comparison panel's heading) when it
// is not empty. At most kWarningsPerKind of one kind are listed; a last line counts the rest.
std::vector<std::string> physicsWarnings(const physics::Timeline& timeline,
                                         const std::string& context = "");

// Writes each as "warning: TEXT".
void printWarnings(const std::vector<std::string>& warnings, std::ostream& err);

inline constexpr int kWarningsPerKind = 3;

}  // namespace collide::report
