#include "report/click_track.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace collide::report {
namespace {

// The knock: two damped partials (a wooden-block "tock") with a 0.2 ms attack so it starts
// without a step, evaluated at continuous time since the impact, tau in seconds.
double knock(double tau_s) {
  constexpr double kAttackS = 0.0002, kDecayS = 0.006;
  constexpr double kLowHz = 1100.0, kHighHz = 2900.0;
  const double envelope = (1.0 - std::exp(-tau_s / kAttackS)) * std::exp(-tau_s / kDecayS);
  return envelope * (0.65 * std::sin(2.0 * M_PI * kLowHz * tau_s) +
                     0.35 * std::sin(2.0 * M_PI * kHighHz * tau_s));
}

// Strength of an impact: the normal impulse, or the closing speed where no impulse is recorded.
double strength(const physics::CollisionEvent& event) {
  return event.impulse_Ns > 0.0 ? event.impulse_Ns : event.closing_speed_mps;
}

// Identity below 0.8, then a smooth approach to 1: sums of overlapping knocks never clip.
float softLimit(double x) {
  const double magnitude = std::fabs(x);
  if (magnitude <= 0.8) return static_cast<float>(x);
  return static_cast<float>(std::copysign(0.8 + 0.2 * std::tanh((magnitude - 0.8) / 0.2), x));
}

}  // namespace

double clickPeak(const physics::CollisionEvent& event, double largest_impulse_Ns) {
  if (largest_impulse_Ns <= 0.0) return kLoudestPeak;
  const double ratio = std::clamp(strength(event) / largest_impulse_Ns, 0.0, 1.0);
  return kLoudestPeak * (kQuietestFraction + (1.0 - kQuietestFraction) * std::sqrt(ratio));
}

ClickTrack synthesizeClicks(const physics::Timeline& timeline, double length_s, int sample_rate_hz,
                            const std::function<double(double)>& heard_at) {
  const auto at = [&](const physics::CollisionEvent& event) {
    return heard_at ? heard_at(event.time_s) : event.time_s;
  };
  COLLIDE_ASSERT(sample_rate_hz > 0 && length_s >= 0.0, "need a rate and a length");
  ClickTrack track;
  track.sample_rate_hz = sample_rate_hz;
  const auto total = static_cast<std::size_t>(std::llround(length_s * sample_rate_hz));
  std::vector<double> mix(total, 0.0);

  const std::vector<physics::CollisionEvent>& events = timeline.collisions();
  double largest = 0.0;
  for (const physics::CollisionEvent& event : events) {
    if (at(event) < length_s) largest = std::max(largest, strength(event));
  }
  // The knock's own peak, measured once, so clickPeak() gives the peak actually heard.
  double knock_peak = 0.0;
  for (int n = 0; n < static_cast<int>(kClickLengthS * 48000); ++n) {
    knock_peak = std::max(knock_peak, std::fabs(knock(n / 48000.0)));
  }

  const double rate = sample_rate_hz;
  for (const physics::CollisionEvent& event : events) {
    const double heard_s = at(event);
    if (heard_s >= length_s) break;
    const double gain = clickPeak(event, largest) / knock_peak;
    // First sample at or after the impact; the knock is evaluated at each sample's exact offset
    // from the impact, which places it to a fraction of a sample.
    const auto first = static_cast<std::size_t>(std::ceil(heard_s * rate));
    const auto last =
        std::min(total, static_cast<std::size_t>(std::ceil((heard_s + kClickLengthS) * rate)));
    for (std::size_t n = first; n < last; ++n) {
      mix[n] += gain * knock(static_cast<double>(n) / rate - heard_s);
    }
  }
  track.samples.resize(total);
  std::transform(mix.begin(), mix.end(), track.samples.begin(), softLimit);
  return track;
}

}  // namespace collide::report
