#pragma once
// Progress of a long render on stderr: a bar redrawn in place on a terminal (frames done, elapsed,
// remaining), a plain line every few seconds otherwise (logs, CI), nothing under --quiet.
#include <chrono>
#include <ostream>
#include <string>

namespace collide::core {

enum class ProgressStyle { kBar, kLines, kSilent };

// kSilent when `quiet`; kBar when `stream` is std::cerr and stderr is a terminal; else kLines.
ProgressStyle chooseProgressStyle(const std::ostream& stream, bool quiet);

// How often a report of either kind (frames, simulation) is drawn at most: 10 times a second as
// a bar redrawn in place, every 5 s as plain lines.
std::chrono::steady_clock::duration reportInterval(ProgressStyle style);

// A time as reports state it: "1.2 s" under 10 s, "57 s" from there on.
std::string reportSeconds(double s);

class Progress {
 public:
  using Clock = std::chrono::steady_clock;

  // `total` units of work (frames), named by `unit` ("frames") after `label` ("rendering").
  Progress(std::ostream& out, ProgressStyle style, int total, std::string label);
  // `done` units are complete. Cheap: redraws at most 10 times a second (bar) or every 5 s (lines).
  void update(int done);
  // Ends the bar's line (or writes a last line) with the total time.
  void finish();

  // The text of one report, for tests: "120/240 frames (50%), 1.2 s elapsed, about 1.2 s left".
  static std::string describe(int done, int total, double elapsed_s);

 private:
  void draw(int done, Clock::time_point now);

  std::ostream& out_;
  ProgressStyle style_;
  int total_;
  std::string label_;
  Clock::time_point start_;
  Clock::time_point last_drawn_;
  bool drawn_ = false;
  int done_ = 0;
};

}  // namespace collide::core
