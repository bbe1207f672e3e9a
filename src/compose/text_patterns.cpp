// SPDX-License-Identifier: MIT
#include "compose/text_patterns.hpp"

#include <algorithm>
#include <cmath>

#include "compose/label_timeline.hpp"
#include "text/wrap_pattern.hpp"

namespace collide::compose {
namespace {

// The video is sampled at a video's frame rate (simulated time), at most kMostSamples times (a
// long calm run's numbers change slowly), and at the first and last instant of each of its first
// kMostShots shots (a short shot may fall between two samples).
constexpr double kSample_s = 1.0 / 60.0;
constexpr int kMostSamples = 240;
constexpr std::size_t kMostShots = 200;
// A shot's last instant: this far before the next shot's start.
constexpr double kBeforeNext_s = 1e-6;

}  // namespace

TextPatterns::TextPatterns(std::vector<double> shot_starts_s, double duration_s,
                           std::function<frame::FrameModel(double t_s)> compose,
                           text::TextWidth width, double size_px)
    : shot_starts_s_(std::move(shot_starts_s)),
      duration_s_(duration_s),
      compose_(std::move(compose)),
      width_(std::move(width)),
      size_px_(size_px) {
  if (shot_starts_s_.empty()) shot_starts_s_.push_back(0.0);
}

std::vector<double> TextPatterns::sampleTimes() const {
  const int steps =
      std::clamp(static_cast<int>(std::ceil(duration_s_ / kSample_s)), 1, kMostSamples);
  std::vector<double> times;
  for (int j = 0; j <= steps; ++j) times.push_back(duration_s_ * j / steps);
  for (std::size_t shot = 0; shot < shot_starts_s_.size() && shot < kMostShots; ++shot) {
    times.push_back(shot_starts_s_[shot]);
    if (shot + 1 < shot_starts_s_.size()) times.push_back(shot_starts_s_[shot + 1] - kBeforeNext_s);
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

void TextPatterns::widen(TextPlan& plan, const std::string& text, std::size_t shot) const {
  if (text.empty()) return;
  const std::string shape = text::wordShape(text);
  plan.shot_by_shape.resize(shot_starts_s_.size());
  for (std::string* pattern : {&plan.by_shape[shape], &plan.shot_by_shape[shot][shape]}) {
    // Texts of one shape have as many words (a number is one word or a part of one).
    const std::string wider = text::widerWords(*pattern, text, size_px_, width_);
    if (!wider.empty()) *pattern = wider;
  }
  plan.shot_shapes.resize(shot_starts_s_.size());
  std::vector<std::string>& shapes = plan.shot_shapes[shot];
  if (std::find(shapes.begin(), shapes.end(), shape) == shapes.end()) shapes.push_back(shape);
}

std::string TextPatterns::widestOf(const TextPlan& plan,
                                   const std::vector<std::string>& shapes) const {
  std::string out;
  double out_px = -1.0;
  for (const std::string& shape : shapes) {
    const std::string& pattern = plan.by_shape.at(shape);
    const double px = width_(pattern, size_px_);
    if (px > out_px) {
      out = pattern;
      out_px = px;
    }
  }
  return out;
}

void TextPatterns::settle(TextPlan& plan) const {
  std::vector<std::string> all, patterns;
  for (const auto& [shape, pattern] : plan.by_shape) {
    all.push_back(shape);
    patterns.push_back(pattern);
  }
  plan.widest = widestOf(plan, all);
  if (!patterns.empty()) plan.shapes = std::make_shared<const text::MostLines>(std::move(patterns));
  if (!plan.widest.empty()) {
    plan.widest_alone = std::make_shared<const text::MostLines>(std::vector{plan.widest});
  }
  plan.shot_shapes.resize(shot_starts_s_.size());
  for (const std::vector<std::string>& shapes : plan.shot_shapes) {
    plan.shot_widest.push_back(widestOf(plan, shapes));
  }
}

void TextPatterns::sample() {
  for (const double t_s : sampleTimes()) {
    const frame::FrameModel frame = compose_(t_s);
    const std::size_t shot = shotOf(shot_starts_s_, t_s);
    panels_.resize(std::max(panels_.size(), frame.panels.size()));
    for (std::size_t p = 0; p < frame.panels.size(); ++p) {
      widen(panels_[p].info, frame.panels[p].info, shot);
      widen(panels_[p].caption, frame.panels[p].caption, shot);
    }
  }
  for (PanelPlan& panel : panels_) {
    settle(panel.info);
    settle(panel.caption);
  }
}

void TextPatterns::set(const TextPlan& plan, const std::string& text, std::size_t shot,
                       std::string& pattern, std::string& like, std::string& in_shot) const {
  pattern = plan.widest;
  const std::string shape = text::wordShape(text);
  // Broken like the widest of its shape in its shot: one shot's breaks hold still, and a vector
  // that fits a line through the shot stays whole ("(2.00, 0) kg·m/s" at 480x270 before
  // ballistic-pendulum's impact was broken "(2.00," | "0) kg·m/s" like the swing's widest).
  // A shape the shot's samples missed: its widest in the video.
  const std::string* own = nullptr;
  if (shot < plan.shot_by_shape.size()) {
    const auto found = plan.shot_by_shape[shot].find(shape);
    if (found != plan.shot_by_shape[shot].end()) own = &found->second;
  }
  if (own == nullptr) {
    const auto found = plan.by_shape.find(shape);
    if (found != plan.by_shape.end()) own = &found->second;
  }
  like = own != nullptr ? *own : std::string();
  in_shot = shot < plan.shot_widest.size() ? plan.shot_widest[shot] : std::string();
}

void TextPatterns::apply(frame::FrameModel& frame, double t_s) {
  std::call_once(sampled_, &TextPatterns::sample, this);
  const std::size_t shot = shotOf(shot_starts_s_, t_s);
  for (std::size_t p = 0; p < frame.panels.size() && p < panels_.size(); ++p) {
    frame::PanelModel& panel = frame.panels[p];
    set(panels_[p].info, panel.info, shot, panel.info_pattern, panel.info_like, panel.info_shot);
    set(panels_[p].caption, panel.caption, shot, panel.caption_pattern, panel.caption_like,
        panel.caption_shot);
    panel.caption_shapes = panels_[p].caption.shapes;
    panel.info_widest = panels_[p].info.widest_alone;
  }
}

}  // namespace collide::compose
