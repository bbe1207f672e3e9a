// SPDX-License-Identifier: MIT
#include "compose/text_patterns.hpp"

#include <algorithm>
#include <cmath>

#include "compose/label_timeline.hpp"
#include "text/wrap_pattern.hpp"

namespace collide::compose {
namespace {

// A shot is sampled at a video's frame rate (simulated time), at most kMostSamples times (a long
// calm shot's numbers change slowly), and at its last instant.
constexpr double kSample_s = 1.0 / 60.0;
constexpr int kMostSamples = 240;
// Its last instant: this far before the next shot's start.
constexpr double kBeforeNext_s = 1e-6;

}  // namespace

TextPatterns::TextPatterns(std::vector<double> shot_starts_s, double duration_s,
                           std::function<frame::FrameModel(double t_s)> compose,
                           text::TextWidth width, double size_px)
    : shot_starts_s_(std::move(shot_starts_s)),
      duration_s_(duration_s),
      compose_(std::move(compose)),
      width_(std::move(width)),
      size_px_(size_px),
      shots_(shot_starts_s_.size()),
      sampled_(shot_starts_s_.size(), false) {}

std::string TextPatterns::widest(const Patterns& patterns) const {
  std::string out;
  double out_px = -1.0;
  for (const std::string& pattern : patterns) {
    const double px = width_(pattern, size_px_);
    if (px > out_px) {
      out = pattern;
      out_px = px;
    }
  }
  return out;
}

void TextPatterns::widen(Patterns& patterns, const std::string& text) const {
  if (text.empty()) return;
  const std::size_t words = text::wordCount(text);
  for (std::string& pattern : patterns) {
    if (text::wordCount(pattern) == words) {
      pattern = text::widerWords(pattern, text, size_px_, width_);
      return;
    }
  }
  patterns.push_back(text);
}

TextPatterns::ShotPatterns TextPatterns::sample(std::size_t shot) const {
  const double start = shot_starts_s_[shot];
  const double end =
      shot + 1 < shot_starts_s_.size() ? shot_starts_s_[shot + 1] - kBeforeNext_s : duration_s_;
  const int steps =
      std::clamp(static_cast<int>(std::ceil((end - start) / kSample_s)), 1, kMostSamples);
  std::vector<Patterns> info, caption;  // by panel
  for (int j = 0; j <= steps; ++j) {
    const frame::FrameModel frame = compose_(start + (end - start) * j / steps);
    info.resize(std::max(info.size(), frame.panels.size()));
    caption.resize(info.size());
    for (std::size_t p = 0; p < frame.panels.size(); ++p) {
      widen(info[p], frame.panels[p].info);
      widen(caption[p], frame.panels[p].caption);
    }
  }
  ShotPatterns patterns(info.size());
  for (std::size_t p = 0; p < info.size(); ++p) {
    patterns[p] = {widest(info[p]), widest(caption[p])};
  }
  return patterns;
}

const TextPatterns::ShotPatterns& TextPatterns::patternsOf(std::size_t shot) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!sampled_[shot]) {
    shots_[shot] = sample(shot);
    sampled_[shot] = true;
  }
  return shots_[shot];
}

void TextPatterns::apply(frame::FrameModel& frame, double t_s) {
  if (shot_starts_s_.empty()) return;
  const ShotPatterns& patterns = patternsOf(shotOf(shot_starts_s_, t_s));
  for (std::size_t p = 0; p < frame.panels.size() && p < patterns.size(); ++p) {
    frame.panels[p].info_pattern = patterns[p].info;
    frame.panels[p].caption_pattern = patterns[p].caption;
  }
}

}  // namespace collide::compose
