// SPDX-License-Identifier: MIT
#include "compose/arrow_forms.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace collide::compose {
namespace {

// The stretches are sampled at the frames of a 60 fps video where it plays at simulated speed:
// a form that lasts one frame there is seen.
constexpr double kSample_s = 1.0 / 60.0;
// A sample this near a grid instant or an event falls at it (k / 60 in its last bits).
constexpr double kRounding_s = 1e-9;
// The longest run of breaks drawn beside instead: a form shown for a few frames flickers, where
// a break that stands for longer reads, and drawn beside for long its arrow stands still while its
// ball creeps on under it, and labels that keep clear of it jump (billiards-glancing 640x360's
// cue ball broken from 0.167 s to its impact at 0.367 s).
constexpr double kLongestBreak_s = 3.5 * kSample_s;

ArrowForm formOf(const frame::BodyModel& body, const frame::PanelModel& panel,
                 const frame::FrameLayout& layout, const frame::WorldToPixel& to_px) {
  const frame::ArrowShape shape = frame::bodyArrowShape(body, panel, layout, to_px);
  if (shape.length_px <= 0.0 || shape.under_scale) return ArrowForm::kNone;
  if (shape.beside_px != 0.0) return ArrowForm::kBeside;
  if (!shape.off_scale) return ArrowForm::kStraight;
  // Off its scale: with a break for want of room where the whole arrow is on its scale.
  const frame::ArrowShape whole = frame::arrowShape(body.velocity_mps.norm(), panel, layout, to_px);
  return whole.off_scale ? ArrowForm::kStraight : ArrowForm::kBreak;
}

}  // namespace

std::vector<std::vector<ArrowForm>> arrowForms(const frame::FrameModel& frame,
                                               const frame::FrameLayout& layout) {
  std::vector<std::vector<ArrowForm>> forms(frame.panels.size());
  for (std::size_t p = 0; p < frame.panels.size() && p < layout.panels.size(); ++p) {
    const frame::PanelModel& panel = frame.panels[p];
    if (!panel.two_d) continue;
    const frame::WorldToPixel to_px = frame::panelMapping(panel, layout.panels[p], layout);
    for (const frame::BodyModel& body : panel.bodies) {
      forms[p].push_back(formOf(body, panel, layout, to_px));
    }
  }
  return forms;
}

ArrowFormPlan::ArrowFormPlan(std::vector<double> event_times_s, double duration_s, Sample sample)
    : duration_s_(duration_s), sample_(std::move(sample)) {
  std::sort(event_times_s.begin(), event_times_s.end());
  starts_s_.push_back(0.0);
  for (const double t : event_times_s) {
    if (t > starts_s_.back()) starts_s_.push_back(t);
  }
  windows_.resize(starts_s_.size());
  planned_.assign(starts_s_.size(), false);
}

const std::vector<ArrowFormPlan::Window>& ArrowFormPlan::windowsOf(std::size_t stretch) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!planned_[stretch]) {
    windows_[stretch] = plan(stretch);
    planned_[stretch] = true;
  }
  return windows_[stretch];
}

std::vector<ArrowFormPlan::Window> ArrowFormPlan::plan(std::size_t stretch) const {
  const double start = starts_s_[stretch];
  const double end = stretch + 1 < starts_s_.size() ? starts_s_[stretch + 1] : duration_s_;
  // Per body: the last sample not in a run of breaks (before the first: the stretch's start, the
  // window taking it in), and whether the samples since are breaks.
  struct Seen {
    double straight_s;
    double breaking_s = -1.0;  // the run's first break; < 0: none
    bool done = false;
  };
  std::vector<std::vector<Seen>> seen;
  std::vector<Window> windows;
  for (double k = std::ceil(start / kSample_s - kRounding_s);; k += 1.0) {
    const double t = k * kSample_s;
    if (t >= end - kRounding_s || t > duration_s_ + kRounding_s) break;
    const std::vector<std::vector<ArrowForm>> forms = sample_(t);
    seen.resize(std::max(seen.size(), forms.size()));
    for (std::size_t p = 0; p < forms.size(); ++p) {
      seen[p].resize(std::max(seen[p].size(), forms[p].size()), Seen{start - 1.0});
      for (std::size_t b = 0; b < forms[p].size(); ++b) {
        Seen& body = seen[p][b];
        if (body.done) continue;
        if (forms[p][b] == ArrowForm::kBreak) {
          if (body.breaking_s < 0.0) body.breaking_s = t;
        } else if (forms[p][b] == ArrowForm::kBeside && body.breaking_s >= 0.0 &&
                   t - body.breaking_s < kLongestBreak_s) {
          windows.push_back({p, b, body.straight_s});
          body.done = true;
        } else {
          body.breaking_s = -1.0;
          body.straight_s = t;
        }
      }
    }
  }
  return windows;
}

void ArrowFormPlan::apply(frame::FrameModel& frame, double t_s) {
  const auto after = std::upper_bound(starts_s_.begin() + 1, starts_s_.end(), t_s);
  const auto stretch = static_cast<std::size_t>(after - starts_s_.begin()) - 1;
  for (const Window& window : windowsOf(stretch)) {
    if (window.panel < frame.panels.size() &&
        window.body < frame.panels[window.panel].bodies.size() && t_s > window.after_s) {
      frame.panels[window.panel].bodies[window.body].arrow_beside_first = true;
    }
  }
}

}  // namespace collide::compose
