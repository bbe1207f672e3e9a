#include "core/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace collide::core {
namespace {

constexpr std::chrono::milliseconds kBarInterval{100};  // terminal redraws, at most
constexpr std::chrono::seconds kLineInterval{5};        // plain lines, at most
constexpr int kBarWidth = 24;                           // characters

}  // namespace

ProgressStyle chooseProgressStyle(const std::ostream& stream, bool quiet) {
  if (quiet) return ProgressStyle::kSilent;
  if (&stream == &std::cerr && ::isatty(STDERR_FILENO)) return ProgressStyle::kBar;
  return ProgressStyle::kLines;
}

std::chrono::steady_clock::duration reportInterval(ProgressStyle style) {
  using Duration = std::chrono::steady_clock::duration;
  return style == ProgressStyle::kBar ? std::chrono::duration_cast<Duration>(kBarInterval)
                                      : std::chrono::duration_cast<Duration>(kLineInterval);
}

std::string reportSeconds(double s) {
  char text[48];
  if (!(s < 1e12)) return "more than 30,000 years";
  if (s >= 2 * 86400.0) {
    std::snprintf(text, sizeof text, "%.0f days", s / 86400.0);
  } else if (s >= 3600.0) {
    std::snprintf(text, sizeof text, "%.1f h", s / 3600.0);
  } else {
    std::snprintf(text, sizeof text, s < 10 ? "%.1f s" : "%.0f s", s);
  }
  return text;
}

Progress::Progress(std::ostream& out, ProgressStyle style, int total, std::string label)
    : out_(out),
      style_(style),
      total_(total),
      label_(std::move(label)),
      start_(Clock::now()),
      last_drawn_(start_) {}

std::string Progress::describe(int done, int total, double elapsed_s) {
  std::string text = std::to_string(done) + "/" + std::to_string(total) + " frames (" +
                     std::to_string(total > 0 ? 100 * done / total : 100) + "%), " +
                     reportSeconds(elapsed_s) + " elapsed";
  if (done > 0 && done < total) {
    text += ", about " + reportSeconds(elapsed_s / done * (total - done)) + " left";
  }
  return text;
}

void Progress::update(int done) {
  done_ = done;
  if (style_ == ProgressStyle::kSilent) return;
  const Clock::time_point now = Clock::now();
  if (now - last_drawn_ < reportInterval(style_)) return;
  draw(done, now);
}

void Progress::draw(int done, Clock::time_point now) {
  last_drawn_ = now;
  drawn_ = true;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (style_ == ProgressStyle::kBar) {
    const int filled = total_ > 0 ? kBarWidth * done / total_ : kBarWidth;
    // \r and the erase-to-end-of-line code redraw the line in place.
    out_ << "\r" << label_ << " [" << std::string(static_cast<std::size_t>(filled), '#')
         << std::string(static_cast<std::size_t>(kBarWidth - filled), '-') << "] "
         << describe(done, total_, elapsed) << "\x1b[K" << std::flush;
  } else {
    out_ << label_ << ": " << describe(done, total_, elapsed) << "\n" << std::flush;
  }
}

void Progress::finish() {
  if (style_ == ProgressStyle::kSilent) return;
  // A short run that never drew a line stays silent in logs; the bar always shows its end.
  if (style_ == ProgressStyle::kLines && !drawn_) return;
  draw(done_, Clock::now());
  if (style_ == ProgressStyle::kBar) out_ << "\n" << std::flush;
}

}  // namespace collide::core
