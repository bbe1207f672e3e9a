#pragma once
// A fingerprint of a run: FNV-1a over the bits of every collision (all of them, replayed) and
// the final totals. Equal hashes mean bit-identical event logs.
#include <cstdint>

#include "physics/timeline.hpp"

namespace collide::physics {

std::uint64_t hashEventLog(const Timeline& timeline);

}  // namespace collide::physics
