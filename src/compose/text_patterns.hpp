// SPDX-License-Identifier: MIT
#pragma once
// Text wrapped once per span of a video (issue 37, docs/architecture.md's layout over time): the
// info line and the caption change their numbers from frame to frame, and wrapped anew in each
// frame they would move their breaks and change their number of lines while the video plays
// ("start (0," / "0) kg·m/s"). Each span (a "shot" here; FrameSource gives the whole video as
// one, so that no shot's pattern takes a line more and moves what stands under the text at its
// first frame) is sampled once, the first time a frame of it is asked for, and each text's words
// are kept at their widest there: the pattern (text/wrap_pattern.hpp) the layout counts the
// text's lines from and the painter breaks it like. A text that gains or loses words within a
// span (a clause that appears) keeps the number of lines of its widest pattern.
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "frame/frame_model.hpp"
#include "text/text_wrap.hpp"

namespace collide::compose {

class TextPatterns {
 public:
  // `compose`: the picture at simulated t_s, no pattern set; `width`: the painter's measure,
  // words compared at size_px; `shot_starts_s`: shotStarts of the picture's events.
  TextPatterns(std::vector<double> shot_starts_s, double duration_s,
               std::function<frame::FrameModel(double t_s)> compose, text::TextWidth width,
               double size_px);

  // Sets the info and caption patterns of `frame`, the picture at t_s. Safe to call from several
  // threads.
  void apply(frame::FrameModel& frame, double t_s);

 private:
  // A text's patterns in a shot while it is sampled, one for each number of words it has there.
  using Patterns = std::vector<std::string>;
  // Each text's widest pattern in the shot: the text breaks like it where it has as many words,
  // else keeps as many lines (text::wrapLike).
  struct PanelPatterns {
    std::string info, caption;
  };
  using ShotPatterns = std::vector<PanelPatterns>;

  const ShotPatterns& patternsOf(std::size_t shot);
  ShotPatterns sample(std::size_t shot) const;
  void widen(Patterns& patterns, const std::string& text) const;
  std::string widest(const Patterns& patterns) const;

  std::vector<double> shot_starts_s_;
  double duration_s_;
  std::function<frame::FrameModel(double t_s)> compose_;
  text::TextWidth width_;
  double size_px_;
  std::mutex mutex_;
  std::vector<ShotPatterns> shots_;  // sampled so far, by shot
  std::vector<bool> sampled_;
};

}  // namespace collide::compose
