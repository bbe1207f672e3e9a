#pragma once
// Slow motion around collisions: playback time runs `factor` times slower than simulated time
// within a window around each collision and at normal speed elsewhere, with linear ramps between
// (no jumps in speed). Frames sample playback time; readouts keep showing simulated time.
#include <vector>

namespace collide::compose {

class TimeMap {
 public:
  // factor <= 1 or no collisions: the identity. collision_times_s need not be sorted.
  TimeMap(double duration_s, std::vector<double> collision_times_s, double factor);

  double playbackDuration_s() const { return playback_.empty() ? duration_s_ : playback_.back(); }
  // The simulated time shown at playback time p (clamped to the playback duration); increasing.
  double simulatedAt(double playback_s) const;
  // The playback time at which simulated time t is shown (simulatedAt's inverse); increasing.
  double playbackAt(double t_s) const;
  // Playback seconds per simulated second at simulated time t: 1 outside the windows.
  double slowdownAt(double t_s) const;

 private:
  double duration_s_;
  double factor_;
  double window_s_ = 0.0;           // half-width of the slowed window, and of each ramp
  std::vector<double> collisions_;  // sorted
  std::vector<double> playback_;    // playback time at each grid point; empty for identity
};

}  // namespace collide::compose
