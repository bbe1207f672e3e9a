#include "compose/slow_motion.hpp"

#include <algorithm>
#include <cmath>

namespace collide::compose {
namespace {

constexpr int kGridSteps = 20000;      // integration grid over the duration
constexpr double kWindowShare = 0.06;  // window half-width: this share of the duration,
constexpr double kMaxWindowS = 0.25;   // at most this many seconds

}  // namespace

TimeMap::TimeMap(double duration_s, std::vector<double> collision_times_s, double factor)
    : duration_s_(duration_s), factor_(factor), collisions_(std::move(collision_times_s)) {
  if (!(factor > 1.0) || collisions_.empty() || !(duration_s > 0.0)) return;
  std::sort(collisions_.begin(), collisions_.end());
  window_s_ = std::min(kMaxWindowS, kWindowShare * duration_s);
  playback_.resize(kGridSteps + 1);
  playback_[0] = 0.0;
  const double dt = duration_s / kGridSteps;
  double previous = slowdownAt(0.0);
  for (int k = 1; k <= kGridSteps; ++k) {
    const double rate = slowdownAt(k * dt);
    playback_[k] = playback_[k - 1] + 0.5 * (previous + rate) * dt;  // trapezoid
    previous = rate;
  }
}

double TimeMap::slowdownAt(double t_s) const {
  if (window_s_ <= 0.0) return 1.0;
  // Distance to the nearest collision.
  const auto it = std::lower_bound(collisions_.begin(), collisions_.end(), t_s);
  double distance = HUGE_VAL;
  if (it != collisions_.end()) distance = *it - t_s;
  if (it != collisions_.begin()) distance = std::min(distance, t_s - *(it - 1));
  if (distance <= window_s_) return factor_;
  if (distance >= 2.0 * window_s_) return 1.0;
  const double f = (distance - window_s_) / window_s_;  // 0 at the window, 1 at the ramp's end
  return factor_ + (1.0 - factor_) * f;
}

double TimeMap::playbackAt(double t_s) const {
  if (playback_.empty()) return std::clamp(t_s, 0.0, duration_s_);
  const double dt = duration_s_ / kGridSteps;
  const double at = std::clamp(t_s / dt, 0.0, static_cast<double>(kGridSteps));
  const auto k = std::min(static_cast<std::size_t>(at), static_cast<std::size_t>(kGridSteps - 1));
  return playback_[k] + (at - static_cast<double>(k)) * (playback_[k + 1] - playback_[k]);
}

double TimeMap::simulatedAt(double playback_s) const {
  if (playback_.empty()) return std::clamp(playback_s, 0.0, duration_s_);
  if (playback_s <= 0.0) return 0.0;
  if (playback_s >= playback_.back()) return duration_s_;
  const auto it = std::upper_bound(playback_.begin(), playback_.end(), playback_s);
  const std::size_t k = static_cast<std::size_t>(it - playback_.begin());  // playback_[k] > p
  const double p0 = playback_[k - 1], p1 = playback_[k];
  const double dt = duration_s_ / kGridSteps;
  return (static_cast<double>(k - 1) + (playback_s - p0) / (p1 - p0)) * dt;
}

}  // namespace collide::compose
