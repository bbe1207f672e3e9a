// The click track: one knock per collision starting at its exact time, louder for harder impacts.
#include "report/click_track.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "report_test_scenes.hpp"

namespace collide::report {
namespace {

// Sample indices where the track rises above `threshold` after at least 10 ms of silence.
std::vector<std::size_t> onsets(const std::vector<float>& samples, int rate, float threshold) {
  std::vector<std::size_t> found;
  std::size_t quiet_since = 0;
  bool loud = false;
  for (std::size_t n = 0; n < samples.size(); ++n) {
    if (std::fabs(samples[n]) > threshold) {
      if (!loud && (found.empty() || n - quiet_since > static_cast<std::size_t>(rate / 100))) {
        found.push_back(n);
      }
      loud = true;
      quiet_since = n;
    } else {
      loud = false;
    }
  }
  return found;
}

TEST(ClickTrackTest, OneKnockPerCollisionAtItsTime) {
  const physics::Timeline timeline = physics::simulate(test::twoBlocksAndWall(0.5));
  const ClickTrack track = synthesizeClicks(timeline, 4.0);
  ASSERT_EQ(track.samples.size(), 4u * 48000u);
  const auto& events = timeline.collisions();
  const std::vector<std::size_t> found = onsets(track.samples, 48000, 1e-4f);
  ASSERT_EQ(found.size(), events.size());
  for (std::size_t i = 0; i < events.size(); ++i) {
    // Audible from the first or second sample after the impact: placed to the sample.
    EXPECT_NEAR(static_cast<double>(found[i]), events[i].time_s * 48000, 1.5) << "collision " << i;
  }
  for (const float s : track.samples) ASSERT_LE(std::fabs(s), 1.0f);
  // Nothing before the first impact.
  for (std::size_t n = 0; n < found.front(); ++n) ASSERT_EQ(track.samples[n], 0.0f);
}

// A video with slow motion shows each collision later than its simulated time: the knock sounds
// where the video shows it (here every instant twice as late), and one shown past the end is not
// heard.
TEST(ClickTrackTest, KnocksFollowTheVideosClock) {
  const physics::Timeline timeline = physics::simulate(test::twoBlocksAndWall(0.5));
  const auto& events = timeline.collisions();
  ASSERT_GE(events.size(), 2u);
  const double length_s = 2.0 * events[1].time_s - 0.01;  // the second one heard just after it
  const ClickTrack track =
      synthesizeClicks(timeline, length_s, 48000, [](double t_s) { return 2.0 * t_s; });
  const std::vector<std::size_t> found = onsets(track.samples, 48000, 1e-4f);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(static_cast<double>(found[0]), 2.0 * events[0].time_s * 48000, 1.5);
}

TEST(ClickTrackTest, HarderImpactsAreLouder) {
  const physics::Timeline timeline = physics::simulate(test::twoBlocksAndWall(0.5));
  const auto& events = timeline.collisions();
  double largest = 0.0;
  for (const auto& e : events) largest = std::max(largest, e.impulse_Ns);
  ASSERT_GT(largest, 0.0);
  // The first impact, 2 kg at 3 m/s onto 1 kg at rest with e = 0.5: J = μ (1 + e) u, μ = 2/3 kg.
  ASSERT_FALSE(events.empty());
  EXPECT_NEAR(events[0].impulse_Ns, (2.0 / 3.0) * 1.5 * 3.0, 1e-12);
  // The documented loudness law, written out here rather than taken from clickPeak: the
  // quietest fraction plus the rest on a square root of the impulse relative to the largest.
  const auto expected_peak = [&](double impulse_Ns) {
    return kLoudestPeak *
           (kQuietestFraction + (1.0 - kQuietestFraction) * std::sqrt(impulse_Ns / largest));
  };
  const ClickTrack track = synthesizeClicks(timeline, 4.0);
  for (std::size_t i = 0; i < events.size(); ++i) {
    const auto first = static_cast<std::size_t>(std::ceil(events[i].time_s * 48000));
    float peak = 0.0f;
    for (std::size_t n = first; n < first + 480; ++n)
      peak = std::max(peak, std::fabs(track.samples[n]));
    EXPECT_NEAR(peak, expected_peak(events[i].impulse_Ns), 0.01) << "collision " << i;
  }
  physics::CollisionEvent soft, hard;
  soft.impulse_Ns = 1.0;
  hard.impulse_Ns = 4.0;
  EXPECT_LT(clickPeak(soft, 4.0), clickPeak(hard, 4.0));
  EXPECT_NEAR(clickPeak(hard, 4.0), kLoudestPeak, 1e-12);
  EXPECT_NEAR(clickPeak(soft, 4.0), kLoudestPeak * (0.2 + 0.8 * 0.5), 1e-12);
}

}  // namespace
}  // namespace collide::report
