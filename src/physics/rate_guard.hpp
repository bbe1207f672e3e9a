#pragma once
// Internal: the cap on collisions per simulated second (WorldDef::max_collisions_per_second).
// A cascade of ever faster collisions that still advances time (a Zeno-like pile-up) escapes the
// same-instant stall check; this guard stops it once more than the cap fall within one second.
//
// Memory stays bounded for any cap: the guard keeps the times of every `stride`-th collision
// (stride = cap / 64, at least 1) and compares collision k with collision k - span, where span is
// the smallest multiple of stride that is >= the cap. So a trip means span + 1 > cap collisions
// within less than a second; a cap below 128 is checked at every collision, exactly.
#include <cstdint>
#include <string>
#include <vector>

namespace collide::physics::detail {

class CollisionRateGuard {
 public:
  // max_per_second <= 0 disables the guard.
  explicit CollisionRateGuard(std::int64_t max_per_second);

  // Called once for each collision about to be processed, in order: `index` its 0-based position
  // in the log, t_s its time. True when it would make more than the cap within one second.
  bool exceeded(std::int64_t index, double t_s) {
    return index >= next_check_ && check(index, t_s);
  }
  // The first index that exceeded() checks: below it, it answers false without looking.
  std::int64_t nextCheck() const { return next_check_; }
  // After exceeded() returned true: the sentence for the user. `processed` collisions were
  // simulated, the last at stopped_at_s.
  std::string message(std::int64_t processed, double stopped_at_s) const;

 private:
  bool check(std::int64_t index, double t_s);

  std::int64_t cap_ = 0;
  std::int64_t stride_ = 1;
  std::int64_t span_ = 0;          // collisions between the two compared, a multiple of stride_
  std::int64_t next_check_ = 0;    // next index that is a multiple of stride_; max when disabled
  std::int64_t first_index_ = -1;  // oldest index whose time is kept
  std::vector<double> times_s_;    // ring: time of index first_index_ + k * stride_ at slot k
  double window_start_s_ = 0.0, window_end_s_ = 0.0;  // the pile-up found, for the message
};

}  // namespace collide::physics::detail
