#include "core/simulation_report.hpp"

#include <algorithm>
#include <cstdio>

namespace collide::core {

SimulationReport::SimulationReport(std::ostream& out, ProgressStyle style, double duration_s,
                                   Clock::time_point start, Clock::duration quiet_time)
    : out_(out),
      style_(style),
      duration_s_(duration_s),
      start_(start),
      quiet_time_(quiet_time),
      last_drawn_(start),
      pace_start_(start) {}

SimulationReport::~SimulationReport() {
  if (style_ == ProgressStyle::kBar && drawn_ && !finished_) out_ << "\n" << std::flush;
}

std::string SimulationReport::describe(double simulated_s, double duration_s,
                                       std::int64_t collisions, double elapsed_s,
                                       double recent_rate) {
  const double fraction = duration_s > 0 ? std::clamp(simulated_s / duration_s, 0.0, 1.0) : 1.0;
  char reached[96];
  std::snprintf(reached, sizeof reached, "t = %.4g of %.4g s simulated (%d%%)", simulated_s,
                duration_s, static_cast<int>(100 * fraction));
  std::string text = std::string(reached) + ", " + std::to_string(collisions) + " collision" +
                     (collisions == 1 ? "" : "s") + ", " + reportSeconds(elapsed_s) + " elapsed";
  if (fraction > 0 && fraction < 1) {
    if (recent_rate == 0.0) return text + ", time left unknown (no simulated time gained lately)";
    double left_s = elapsed_s / fraction * (1 - fraction);
    if (recent_rate > 0.0) left_s = std::max(left_s, (duration_s - simulated_s) / recent_rate);
    text += ", about " + reportSeconds(left_s) + " left";
  }
  return text;
}

void SimulationReport::update(double simulated_s, std::int64_t collisions, Clock::time_point now) {
  if (style_ == ProgressStyle::kSilent || now - start_ < quiet_time_) return;
  // The first report comes as soon as the quiet time is over; later ones at the interval.
  if (drawn_ && now - last_drawn_ < reportInterval(style_)) return;
  draw(simulated_s, collisions, now);
}

void SimulationReport::draw(double simulated_s, std::int64_t collisions, Clock::time_point now) {
  last_drawn_ = now;
  drawn_ = true;
  // The recent pace, over at least kPaceSpan; none until the run is that old.
  constexpr std::chrono::seconds kPaceSpan{2};
  double recent_rate = -1.0;
  const double pace_span_s = std::chrono::duration<double>(now - pace_start_).count();
  if (now - pace_start_ >= kPaceSpan) {
    recent_rate = std::max(simulated_s - pace_simulated_s_, 0.0) / pace_span_s;
    pace_start_ = now;
    pace_simulated_s_ = simulated_s;
  } else if (last_rate_ >= 0.0) {
    recent_rate = last_rate_;
  }
  last_rate_ = recent_rate;
  const std::string text =
      describe(simulated_s, duration_s_, collisions,
               std::chrono::duration<double>(now - start_).count(), recent_rate);
  if (style_ == ProgressStyle::kBar) {
    // \r and the erase-to-end-of-line code redraw the line in place.
    out_ << "\rsimulating: " << text << "\x1b[K" << std::flush;
  } else {
    out_ << "simulating: " << text << "\n" << std::flush;
  }
}

void SimulationReport::finish(double simulated_s, std::int64_t collisions, Clock::time_point now) {
  finished_ = true;
  if (style_ == ProgressStyle::kSilent || !drawn_) return;
  draw(simulated_s, collisions, now);
  if (style_ == ProgressStyle::kBar) out_ << "\n" << std::flush;
}

}  // namespace collide::core
