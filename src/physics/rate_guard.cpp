#include "physics/rate_guard.hpp"

#include <cstdio>
#include <limits>

namespace collide::physics::detail {
namespace {

// Times kept per cap: the granularity of the check is cap / kSlots collisions.
constexpr std::int64_t kSlots = 64;
constexpr double kWindow_s = 1.0;  // "per simulated second"

}  // namespace

CollisionRateGuard::CollisionRateGuard(std::int64_t max_per_second) : cap_(max_per_second) {
  if (cap_ <= 0) {
    next_check_ = std::numeric_limits<std::int64_t>::max();
    return;
  }
  stride_ = cap_ / kSlots > 0 ? cap_ / kSlots : 1;
  span_ = (cap_ + stride_ - 1) / stride_ * stride_;
  times_s_.assign(static_cast<std::size_t>(span_ / stride_ + 1), 0.0);
}

bool CollisionRateGuard::check(std::int64_t index, double t_s) {
  // Only multiples of stride_ are kept; a guard started mid-run (replaying from a checkpoint)
  // begins at the first one it sees.
  if (index % stride_ != 0) {
    next_check_ = (index / stride_ + 1) * stride_;
    return false;
  }
  next_check_ = index + stride_;
  const auto slots = static_cast<std::int64_t>(times_s_.size());
  if (first_index_ < 0) first_index_ = index;
  const std::int64_t earlier = index - span_;
  if (earlier >= first_index_) {
    const double earlier_s = times_s_[static_cast<std::size_t>((earlier / stride_) % slots)];
    if (t_s - earlier_s < kWindow_s) {
      window_start_s_ = earlier_s;
      window_end_s_ = t_s;
      return true;
    }
  }
  times_s_[static_cast<std::size_t>((index / stride_) % slots)] = t_s;
  return false;
}

std::string CollisionRateGuard::message(std::int64_t processed, double stopped_at_s) const {
  char text[400];
  std::snprintf(text, sizeof text,
                "stopped at t = %.9g s after %lld collisions because they piled up faster than "
                "the limit of %lld collisions per simulated second (max_collisions_per_second): "
                "%lld were due between t = %.9g s and t = %.9g s; "
                "later states are not simulated",
                stopped_at_s, static_cast<long long>(processed), static_cast<long long>(cap_),
                static_cast<long long>(span_ + 1), window_start_s_, window_end_s_);
  return text;
}

}  // namespace collide::physics::detail
