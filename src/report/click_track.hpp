#pragma once
// The collision sound (`--sound`): a short knock at each collision, placed at its exact time to
// the fraction of a sample, louder for harder impacts. Made here as samples; an output sink
// encodes and muxes them.
#include <functional>
#include <vector>

#include "physics/timeline.hpp"

namespace collide::report {

struct ClickTrack {
  int sample_rate_hz = 48000;
  std::vector<float> samples;  // mono, in [-1, 1]; samples.size() = round(length * rate)
};

// Length of one knock: after this the sound has decayed below -80 dB, s.
inline constexpr double kClickLengthS = 0.045;
// Peak of the hardest knock, and of the softest relative to it (so every impact stays audible).
inline constexpr double kLoudestPeak = 0.8;
inline constexpr double kQuietestFraction = 0.2;

// How loud the knock of `event` is, in (0, kLoudestPeak]: the impulse (momentum exchanged, N s)
// relative to the largest impulse among `events`, on a square-root curve (hearing is closer to
// logarithmic than linear), never below kQuietestFraction of the loudest.
double clickPeak(const physics::CollisionEvent& event, double largest_impulse_Ns);

// Every collision heard before length_s contributes one knock starting at its time. Overlapping
// knocks are summed and softly limited to stay within [-1, 1]. `heard_at` maps a collision's
// simulated time to the track's (a video with slow motion shows it later); none: the same.
ClickTrack synthesizeClicks(const physics::Timeline& timeline, double length_s,
                            int sample_rate_hz = 48000,
                            const std::function<double(double)>& heard_at = {});

}  // namespace collide::report
