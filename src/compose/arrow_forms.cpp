// SPDX-License-Identifier: MIT
#include "compose/arrow_forms.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace collide::compose {
namespace {

// The stretches are sampled at the frames of a 60 fps video where it plays at simulated speed:
// a form that lasts one frame there is seen.
constexpr double kSample_s = 1.0 / 60.0;
// A sample this near a grid instant or an event falls at it (k / 60 in its last bits).
constexpr double kRounding_s = 1e-9;
// A form shown for fewer samples than this between two changes flickers (issue 37).
constexpr int kFewestFrames = 3;
// What a plan counts: a change of form; a form between two changes that lasts fewer than
// kFewestFrames samples; each sample asked for beside first or none (a share of a change: a form
// of up to three samples between two others is replaced, one of four or more kept; hiding an
// arrow costs a little more than drawing it beside).
constexpr double kChangeCost = 1.0;
constexpr double kFlickerCost = 10.0;
constexpr double kBesideCost = 0.3;
constexpr double kHiddenCost = 0.35;

ArrowForm formOf(const frame::BodyModel& body, const frame::PanelModel& panel,
                 const frame::FrameLayout& layout, const frame::WorldToPixel& to_px) {
  const frame::ArrowShape shape = frame::bodyArrowShape(body, panel, layout, to_px);
  if (shape.length_px <= 0.0) return ArrowForm::kNone;
  if (shape.under_scale) return ArrowForm::kMark;
  if (shape.beside_px != 0.0) return ArrowForm::kBeside;
  if (shape.tail_ahead_px > 0.0) return ArrowForm::kEdge;
  if (!shape.off_scale) return ArrowForm::kStraight;
  // Off its scale: with a break for want of room where the whole arrow is on its scale.
  const frame::ArrowShape whole = frame::arrowShape(body.velocity_mps.norm(), panel, layout, to_px);
  return whole.off_scale ? ArrowForm::kStraight : ArrowForm::kBreak;
}

using Ask = ArrowFormPlan::Ask;
constexpr std::array<Ask, 3> kAsks = {Ask::kOwn, Ask::kBesideFirst, Ask::kHidden};

ArrowForm drawn(const ArrowFormChoice& choice, Ask ask) {
  if (ask == Ask::kBesideFirst) return choice.beside_first;
  return ask == Ask::kHidden ? ArrowForm::kNone : choice.own;
}

double askCost(Ask ask) {
  if (ask == Ask::kBesideFirst) return kBesideCost;
  return ask == Ask::kHidden ? kHiddenCost : 0.0;
}

// A plan's state after a sample: the form drawn, how many samples it has lasted (at most
// kFewestFrames) and whether it has since the stretch's start (not begun by a change).
constexpr int kForms = 6;
constexpr int kStates = kForms * kFewestFrames * 2;
int stateOf(ArrowForm form, int run, bool from_start) {
  return (static_cast<int>(form) * kFewestFrames + (run - 1)) * 2 + (from_start ? 1 : 0);
}
ArrowForm formOfState(int state) {
  return static_cast<ArrowForm>(state / (2 * kFewestFrames));
}
int runOfState(int state) {
  return (state / 2) % kFewestFrames + 1;
}
bool fromStartOfState(int state) {
  return state % 2 == 1;
}

}  // namespace

std::vector<std::vector<ArrowFormChoice>> arrowForms(const frame::FrameModel& frame,
                                                     const frame::FrameLayout& layout) {
  std::vector<std::vector<ArrowFormChoice>> forms(frame.panels.size());
  for (std::size_t p = 0; p < frame.panels.size() && p < layout.panels.size(); ++p) {
    const frame::PanelModel& panel = frame.panels[p];
    if (!panel.two_d) continue;
    const frame::WorldToPixel to_px = frame::panelMapping(panel, layout.panels[p], layout);
    frame::PanelModel beside = panel;
    for (frame::BodyModel& body : beside.bodies) body.arrow_beside_first = true;
    for (std::size_t b = 0; b < panel.bodies.size(); ++b) {
      const frame::BodyModel& body = panel.bodies[b];
      const ArrowForm own = formOf(body, panel, layout, to_px);
      const bool asks_arrow =
          frame::arrowShape(body.velocity_mps.norm(), panel, layout, to_px).length_px > 0.0;
      forms[p].push_back({own, formOf(beside.bodies[b], beside, layout, to_px),
                          own == ArrowForm::kNone && asks_arrow});
    }
  }
  return forms;
}

std::vector<ArrowFormPlan::Ask> ArrowFormPlan::plan(const std::vector<ArrowFormChoice>& forms) {
  const std::size_t n = forms.size();
  if (n == 0) return {};
  constexpr double kNever = std::numeric_limits<double>::infinity();
  // cost[k][state]: the least cost of samples 0..k ending in `state`; from[k][state]: the state
  // before and the ask at k.
  // Hidden only within kFewestFrames - 1 samples of a crowded one.
  std::vector<bool> hideable(n, false);
  for (std::size_t k = 0; k < n; ++k) {
    if (!forms[k].crowded) continue;
    const std::size_t reach = kFewestFrames - 1;
    for (std::size_t j = k > reach ? k - reach : 0; j < n && j <= k + reach; ++j)
      hideable[j] = true;
  }
  std::vector<std::array<double, kStates>> cost(n);
  std::vector<std::array<std::pair<int, Ask>, kStates>> from(n);
  for (auto& row : cost) row.fill(kNever);
  for (const Ask ask : kAsks) {
    if (ask == Ask::kHidden && !hideable[0]) continue;
    const int state = stateOf(drawn(forms[0], ask), 1, true);
    cost[0][state] = std::min(cost[0][state], askCost(ask));
    if (cost[0][state] == askCost(ask)) from[0][state] = {-1, ask};
  }
  for (std::size_t k = 1; k < n; ++k) {
    for (int was = 0; was < kStates; ++was) {
      if (cost[k - 1][was] == kNever) continue;
      for (const Ask ask : kAsks) {
        if (ask == Ask::kHidden && !hideable[k]) continue;
        const ArrowForm form = drawn(forms[k], ask);
        double step = askCost(ask);
        int state = 0;
        if (form == formOfState(was)) {
          state =
              stateOf(form, std::min(runOfState(was) + 1, kFewestFrames), fromStartOfState(was));
        } else {
          const bool flicker = runOfState(was) < kFewestFrames && !fromStartOfState(was);
          step += kChangeCost + (flicker ? kFlickerCost : 0.0);
          state = stateOf(form, 1, false);
        }
        if (cost[k - 1][was] + step < cost[k][state]) {
          cost[k][state] = cost[k - 1][was] + step;
          from[k][state] = {was, ask};
        }
      }
    }
  }
  int state = static_cast<int>(std::min_element(cost[n - 1].begin(), cost[n - 1].end()) -
                               cost[n - 1].begin());
  std::vector<Ask> asks(n, Ask::kOwn);
  for (std::size_t k = n; k-- > 0;) {
    asks[k] = from[k][state].second;
    state = from[k][state].first;
  }
  return asks;
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
    windows_[stretch] = windows(stretch);
    planned_[stretch] = true;
  }
  return windows_[stretch];
}

std::vector<ArrowFormPlan::Window> ArrowFormPlan::windows(std::size_t stretch) const {
  const double start = starts_s_[stretch];
  const double end = stretch + 1 < starts_s_.size() ? starts_s_[stretch + 1] : duration_s_;
  std::vector<double> times_s;
  std::vector<std::vector<std::vector<ArrowFormChoice>>> by_body;  // panel, body, sample
  for (double k = std::ceil(start / kSample_s - kRounding_s);; k += 1.0) {
    const double t = k * kSample_s;
    if (t >= end - kRounding_s || t > duration_s_ + kRounding_s) break;
    const std::vector<std::vector<ArrowFormChoice>> forms = sample_(t);
    by_body.resize(std::max(by_body.size(), forms.size()));
    for (std::size_t p = 0; p < forms.size(); ++p) {
      by_body[p].resize(std::max(by_body[p].size(), forms[p].size()));
      for (std::size_t b = 0; b < forms[p].size(); ++b) {
        by_body[p][b].resize(times_s.size(), forms[p][b]);  // a body not seen before: as now
        by_body[p][b].push_back(forms[p][b]);
      }
    }
    times_s.push_back(t);
  }
  std::vector<Window> out;
  for (std::size_t p = 0; p < by_body.size(); ++p) {
    for (std::size_t b = 0; b < by_body[p].size(); ++b) {
      const std::vector<Ask> asks = plan(by_body[p][b]);
      // Each run of one ask other than the body's own, from the sample before it to the one
      // after it (exclusive), or the stretch's ends.
      for (std::size_t k = 0; k < asks.size(); ++k) {
        if (asks[k] == Ask::kOwn || (k > 0 && asks[k - 1] == asks[k])) continue;
        std::size_t last = k;
        while (last + 1 < asks.size() && asks[last + 1] == asks[k]) ++last;
        out.push_back({p, b, asks[k], k > 0 ? times_s[k - 1] : start - 1.0,
                       last + 1 < asks.size() ? times_s[last + 1] : end + 1.0});
      }
    }
  }
  return out;
}

void ArrowFormPlan::apply(frame::FrameModel& frame, double t_s) {
  const auto after = std::upper_bound(starts_s_.begin() + 1, starts_s_.end(), t_s);
  const auto stretch = static_cast<std::size_t>(after - starts_s_.begin()) - 1;
  for (const Window& window : windowsOf(stretch)) {
    if (window.panel < frame.panels.size() &&
        window.body < frame.panels[window.panel].bodies.size() && t_s > window.after_s &&
        t_s < window.before_s) {
      frame::BodyModel& body = frame.panels[window.panel].bodies[window.body];
      body.arrow_beside_first = body.arrow_beside_first || window.ask == Ask::kBesideFirst;
      body.arrow_hidden = body.arrow_hidden || window.ask == Ask::kHidden;
    }
  }
}

}  // namespace collide::compose
