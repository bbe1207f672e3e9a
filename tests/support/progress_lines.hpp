// SPDX-License-Identifier: MIT
#pragma once
// A run slower than the quiet time (core::kQuietSimulationTime, and the render's progress interval)
// reports its progress on stderr: "simulating: ..." and "rendering: N/M frames ...". How long a run
// takes depends on the machine, its load and the build (a sanitizer build on a busy 2-core
// machine), so a test that checks what else stderr says looks at it without those lines.
#include <string>

namespace collide::test {

// `err` with every progress line left out, the other lines kept in order.
std::string withoutProgressLines(const std::string& err);

}  // namespace collide::test
