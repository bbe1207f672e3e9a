#include "core/simulation_report.hpp"

#include <algorithm>
#include <cstdio>

namespace collide::core {

namespace {

// A count as a report says it: "7.6 million", "400 million", "81234".
std::string countText(double count) {
  char text[48];
  const auto scaled = [&](double unit, const char* name) {
    const double value = count / unit;
    std::snprintf(text, sizeof text, value < 10 ? "%.1f %s" : "%.0f %s", value, name);
  };
  if (count >= 1e9) {
    scaled(1e9, "billion");
  } else if (count >= 1e6) {
    scaled(1e6, "million");
  } else {
    std::snprintf(text, sizeof text, "%.0f", count);
  }
  return text;
}

// Wall seconds until the collision cap at the recent collision rate; negative: no bound known.
double secondsToTheCap(std::int64_t collisions, const RunLimits& limits, const RecentPace& recent) {
  if (limits.max_collisions <= collisions || !(recent.collisions_per_s > 0.0)) return -1.0;
  return static_cast<double>(limits.max_collisions - collisions) / recent.collisions_per_s;
}

std::string capText(const RunLimits& limits) {
  return "the cap of " + countText(static_cast<double>(limits.max_collisions)) + " collisions";
}

// "about 6.0 s left", or "time left unknown (why)" with the cap's bound where one is known.
std::string timeLeft(double simulated_s, std::int64_t collisions, double elapsed_s,
                     const RunLimits& limits, const RecentPace& recent) {
  const double fraction = simulated_s / limits.duration_s;
  const double average_s = elapsed_s / fraction * (1 - fraction);
  const double cap_s = secondsToTheCap(collisions, limits, recent);
  double left_s = average_s;
  std::string unknown_why;
  if (SimulationReport::stalled(simulated_s, elapsed_s, limits, recent)) {
    unknown_why = "simulated time hardly advances";
  } else if (recent.simulated_s_per_s > 0.0) {
    const double recent_s = (limits.duration_s - simulated_s) / recent.simulated_s_per_s;
    // Two estimates a factor of 2 apart: the pace is changing, and neither can be trusted.
    if (recent_s > 2.0 * average_s || recent_s < 0.5 * average_s) {
      unknown_why = "the pace is changing";
    } else {
      left_s = std::max(left_s, recent_s);
    }
  }
  if (unknown_why.empty()) {
    if (cap_s >= 0.0 && cap_s < left_s)
      return "at most " + reportSeconds(cap_s) + " left (" + capText(limits) + ")";
    return "about " + reportSeconds(left_s) + " left";
  }
  std::string text = "time left unknown (" + unknown_why + ")";
  if (cap_s >= 0.0) text += ", at most " + reportSeconds(cap_s) + " (" + capText(limits) + ")";
  return text;
}

}  // namespace

SimulationReport::SimulationReport(std::ostream& out, ProgressStyle style, RunLimits limits,
                                   Clock::time_point start, Clock::duration quiet_time)
    : out_(out),
      style_(style),
      limits_(limits),
      start_(start),
      quiet_time_(quiet_time),
      last_drawn_(start),
      pace_start_(start) {}

SimulationReport::~SimulationReport() {
  if (style_ == ProgressStyle::kBar && drawn_ && !finished_) out_ << "\n" << std::flush;
}

bool SimulationReport::stalled(double simulated_s, double elapsed_s, const RunLimits& limits,
                               const RecentPace& recent) {
  const double left_s = limits.duration_s - simulated_s;
  if (recent.simulated_s_per_s < 0.0 || !(left_s > 0.0)) return false;
  constexpr double kStallFactor = 1000.0;
  return left_s > kStallFactor * std::max(elapsed_s, 1.0) * recent.simulated_s_per_s;
}

std::string SimulationReport::stallNote(double simulated_s, const RunLimits& limits,
                                        const RecentPace& recent) {
  char at[64];
  std::snprintf(at, sizeof at, "%.6g s", simulated_s);
  std::string text = "collisions pile up at t = " + std::string(at) + ": " +
                     countText(std::max(recent.collisions_per_s, 0.0)) +
                     " a second while simulated time hardly advances";
  if (limits.settling_off) {
    text +=
        "; with contact.collapse_time = 0 nothing ends a settling series (a body bouncing ever "
        "lower) or an inelastic collapse";
  }
  if (limits.max_collisions > 0) text += "; the run stops at " + capText(limits) + " at the latest";
  return text;
}

std::string SimulationReport::describe(double simulated_s, std::int64_t collisions,
                                       double elapsed_s, const RunLimits& limits,
                                       const RecentPace& recent) {
  const double duration_s = limits.duration_s;
  const double fraction = duration_s > 0 ? std::clamp(simulated_s / duration_s, 0.0, 1.0) : 1.0;
  char reached[96];
  std::snprintf(reached, sizeof reached, "t = %.4g of %.4g s simulated (%d%%)", simulated_s,
                duration_s, static_cast<int>(100 * fraction));
  std::string text = std::string(reached) + ", " + std::to_string(collisions) + " collision" +
                     (collisions == 1 ? "" : "s") + ", " + reportSeconds(elapsed_s) + " elapsed";
  if (fraction > 0 && fraction < 1)
    text += ", " + timeLeft(simulated_s, collisions, elapsed_s, limits, recent);
  return text;
}

void SimulationReport::update(double simulated_s, std::int64_t collisions, Clock::time_point now) {
  if (style_ == ProgressStyle::kSilent) return;
  // The pace is measured from the start, so that the first report already knows the recent one.
  measurePace(simulated_s, collisions, now);
  if (now - start_ < quiet_time_) return;
  // The first report comes as soon as the quiet time is over; later ones at the interval.
  if (drawn_ && now - last_drawn_ < reportInterval(style_)) return;
  draw(simulated_s, collisions, now);
}

RecentPace SimulationReport::measurePace(double simulated_s, std::int64_t collisions,
                                         Clock::time_point now) {
  // The recent pace, over at least kPaceSpan; none until the run is that old.
  constexpr std::chrono::seconds kPaceSpan{1};
  if (now - pace_start_ < kPaceSpan) return last_pace_;
  const double span_s = std::chrono::duration<double>(now - pace_start_).count();
  last_pace_.simulated_s_per_s = std::max(simulated_s - pace_simulated_s_, 0.0) / span_s;
  last_pace_.collisions_per_s =
      static_cast<double>(std::max<std::int64_t>(collisions - pace_collisions_, 0)) / span_s;
  pace_start_ = now;
  pace_simulated_s_ = simulated_s;
  pace_collisions_ = collisions;
  return last_pace_;
}

void SimulationReport::draw(double simulated_s, std::int64_t collisions, Clock::time_point now) {
  last_drawn_ = now;
  drawn_ = true;
  const RecentPace recent = measurePace(simulated_s, collisions, now);
  const double elapsed_s = std::chrono::duration<double>(now - start_).count();
  // \r and the erase-to-end-of-line code redraw a bar's line in place; a note stands on its own
  // line above the bar.
  const char* start = style_ == ProgressStyle::kBar ? "\rsimulating: " : "simulating: ";
  const char* end = style_ == ProgressStyle::kBar ? "\x1b[K" : "\n";
  if (!stall_noted_ && stalled(simulated_s, elapsed_s, limits_, recent)) {
    stall_noted_ = true;
    out_ << start << stallNote(simulated_s, limits_, recent)
         << (style_ == ProgressStyle::kBar ? "\x1b[K\n" : "\n");
  }
  out_ << start << describe(simulated_s, collisions, elapsed_s, limits_, recent) << end
       << std::flush;
}

void SimulationReport::finish(double simulated_s, std::int64_t collisions, Clock::time_point now) {
  finished_ = true;
  if (style_ == ProgressStyle::kSilent || !drawn_) return;
  draw(simulated_s, collisions, now);
  if (style_ == ProgressStyle::kBar) out_ << "\n" << std::flush;
}

}  // namespace collide::core
