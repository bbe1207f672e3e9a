// SPDX-License-Identifier: MIT
#pragma once
// Text wrapped once for a video (issue 37, docs/architecture.md's layout over time): the info
// line and the caption change their numbers from frame to frame, and wrapped anew in each frame
// they would move their breaks and change their number of lines while the video plays
// ("start (0," / "0) kg·m/s"). The video is sampled once, the first time a frame is asked for,
// and each text's words are kept at their widest (text/wrap_pattern.hpp), apart for each shape
// of its words (text::wordShape: the words but for their numbers): the widest text of all (the
// layout counts the text's lines and sizes its box from it, so no shot's text moves what stands
// under it), the widest of the text's own shape in its shot (the painter breaks it like that
// one, so its breaks never move while its words keep their shape through the shot, never fall
// inside a vector another shape's words would put there, and part a vector only where the
// shot's own widest of it needs: "(2.00, 0) kg·m/s" before an impact stays whole where the
// swing's "(−0.0476," | "−0.0356) kg·m/s" is parted) and the widest of each shot (the painter keeps
// at least its number of lines through the shot, so a text that changes its shape between two
// events keeps its number of lines). A narrower caption of another shape may break into more lines
// than the widest: the layout keeps the most the widest of any shape takes, counted once per size
// (text::MostLines, shared by the video's frames).
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "frame/frame_model.hpp"
#include "text/most_lines.hpp"
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
  // One text of one panel over the video: its patterns by shape (text::wordShape), each word
  // at its widest; the shapes each shot shows; and, found from those, the widest text of all and
  // of each shot.
  struct TextPlan {
    std::map<std::string, std::string> by_shape;
    // by_shape within each shot (by shot): the painter breaks a text like the widest of its shape
    // in its shot, so a vector that fits a line through its shot stays whole on it.
    std::vector<std::map<std::string, std::string>> shot_by_shape;
    std::vector<std::vector<std::string>> shot_shapes;  // by shot
    std::string widest;
    std::vector<std::string> shot_widest;  // by shot; empty: none sampled there
    // by_shape's patterns, and the widest alone, their lines counted once per size
    // (PanelModel::caption_shapes, info_widest).
    std::shared_ptr<const text::MostLines> shapes, widest_alone;
  };
  struct PanelPlan {
    TextPlan info, caption;
  };

  std::vector<double> sampleTimes() const;
  void sample();
  void widen(TextPlan& plan, const std::string& text, std::size_t shot) const;
  void settle(TextPlan& plan) const;
  std::string widestOf(const TextPlan& plan, const std::vector<std::string>& shapes) const;
  void set(const TextPlan& plan, const std::string& text, std::size_t shot, std::string& pattern,
           std::string& like, std::string& in_shot) const;

  std::vector<double> shot_starts_s_;
  double duration_s_;
  std::function<frame::FrameModel(double t_s)> compose_;
  text::TextWidth width_;
  double size_px_;
  std::once_flag sampled_;
  std::vector<PanelPlan> panels_;
};

}  // namespace collide::compose
