// SPDX-License-Identifier: MIT
// LabelTimeline's ways through a shot: each label's widest text, the probes its steps are priced
// with, and which labels' ways (label_timeline_runs.cpp) are planned over which runs of steps.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "compose/label_cost.hpp"
#include "compose/label_timeline.hpp"
#include "compose/label_way_moves.hpp"
#include "compose/label_ways.hpp"

namespace collide::compose {

double LabelTimeline::LabelAt::movedFrom(const LabelAt& was) const {
  return moveBetween(was.shownBox(), was.body_px, shownBox(), body_px).px;
}

namespace {

// A label's widest text over a shot, and how wide it is.
struct WidestText {
  std::size_t panel = 0, body = 0;
  bool velocity = false;
  std::string text;
  double width_px = 0.0;
};

// Each label's widest text in `probes`.
std::vector<WidestText> widestTexts(const std::vector<LabelProbe>& probes, std::size_t panels,
                                    std::size_t bodies) {
  std::vector<WidestText> widest;
  for (const LabelProbe& probe : probes) {
    for (std::size_t p = 0; p < panels; ++p) {
      for (std::size_t i = 0; i < bodies; ++i) {
        for (const bool velocity : {false, true}) {
          const Label* label = probe.label(p, i, velocity);
          if (label == nullptr) continue;
          auto known = std::find_if(widest.begin(), widest.end(), [&](const WidestText& w) {
            return w.panel == p && w.body == i && w.velocity == velocity;
          });
          if (known == widest.end()) {
            widest.push_back({p, i, velocity, *label->text, label->size.x()});
          } else if (label->size.x() > known->width_px) {
            known->text = *label->text;
            known->width_px = label->size.x();
          }
        }
      }
    }
  }
  return widest;
}

// Sets the texts of `frame` narrower than their widest to the widest; whether any was.
bool widenTexts(frame::FrameModel& frame, const LabelProbe& probe,
                const std::vector<WidestText>& widest) {
  constexpr double kSameWidthPx = 0.5;
  bool widened = false;
  for (const WidestText& w : widest) {
    const Label* label = probe.label(w.panel, w.body, w.velocity);
    if (label == nullptr || label->size.x() >= w.width_px - kSameWidthPx) continue;
    frame::BodyModel& body = frame.panels[w.panel].bodies[w.body];
    (w.velocity ? body.velocity_label : body.label) = w.text;
    widened = true;
  }
  return widened;
}

}  // namespace

LabelTimeline::AfterEnd LabelTimeline::afterEnd(double end_s, double later_s) const {
  frame::FrameModel next = composedAt(end_s);
  AfterEnd after{picture_.probe(next), picture_.body_px(next), {}};
  if (later_s >= 0.0) {
    frame::FrameModel later = composedAt(later_s);
    after.later.push_back({picture_.probe(later), picture_.body_px(later), {}});
  }
  // Only along a track: in 2D, labels ended where they could stay on across a glancing
  // impact ran into the balls' new ways later in the next shot (billiards-glancing).
  for (std::size_t p = 0; p < next.panels.size() && p < after.body_px.size(); ++p) {
    if (!next.panels[p].two_d) continue;
    after.body_px[p].clear();
    if (!after.later.empty() && p < after.later.front().body_px.size()) {
      after.later.front().body_px[p].clear();
    }
  }
  return after;
}

std::vector<LabelProbe> LabelTimeline::probesOf(const std::vector<Step>& steps) const {
  std::vector<frame::FrameModel> frames;
  std::vector<LabelProbe> probes;
  std::size_t panels = 0, bodies = 0;
  for (const Step& step : steps) {
    frames.push_back(composedAt(step.t_s));
    probes.push_back(picture_.probe(frames.back()));
    panels = std::max(panels, frames.back().panels.size());
    for (const frame::PanelModel& panel : frames.back().panels) {
      bodies = std::max(bodies, panel.bodies.size());
    }
  }
  // A text whose value grows or shrinks is planned as wide as it gets in the shot: it keeps its
  // place (its side of its arrow, its row) while the number changes its count of digits.
  const std::vector<WidestText> widest = widestTexts(probes, panels, bodies);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    if (widenTexts(frames[k], probes[k], widest)) probes[k] = picture_.probe(frames[k]);
  }
  return probes;
}

namespace {

// The steps where placement does not take a label's way (as the shot's probes saw them), over
// every label of the shot: each is a frame where the label is placed elsewhere, pushing others
// aside (a jump there and another back). First those where it runs into something, then those
// where it continues another label's line (one of the two goes to the legend there).
template <typename Steps>
std::pair<std::size_t, std::size_t> stepsNotTaken(const Steps& steps) {
  std::pair<std::size_t, std::size_t> count{0, 0};
  for (const auto& step : steps) {
    for (const auto& at : step.placed) {
      count.first += at.free ? 0 : 1;
      count.second += at.taken ? 0 : 1;
    }
  }
  return count;
}

// `keys` with those whose ways placement does not take at any of `steps` first.
template <typename Steps, typename Keys>
Keys runningIntoFirst(const Steps& steps, const Keys& keys) {
  Keys first, rest;
  for (const auto& key : keys) {
    const bool runs_into = std::any_of(steps.begin(), steps.end(), [&](const auto& step) {
      const auto* at = findLabel(step.placed, key);
      return at != nullptr && !at->taken;
    });
    (runs_into ? first : rest).push_back(key);
  }
  if (first.empty()) return {};
  first.insert(first.end(), rest.begin(), rest.end());
  return first;
}

// A move from one step to the next up to this much farther than the glide speeds allow is the
// rounding of its places, not a jump.
constexpr double kJumpSlackPx = 1.0;
// The frames a second a video is checked at: a label that leaves where it stood at the shot
// before's end moves within the first of them.
constexpr double kFramesPerS = 60.0;

// How many times labels jump on their ways through `steps`: from one step to the next one
// moves farther beyond its body, and on the page, than `reach_px(step)`, or it leaves where it
// stood at `before` (the shot before's last step; null: none) by more than `restart_px`.
template <typename Steps, typename Step, typename Reach>
std::size_t jumpsIn(const Steps& steps, const Step* before, double restart_px,
                    const Reach& reach_px) {
  std::size_t jumps = 0;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const Step* last = k > 0 ? &steps[k - 1] : before;
    if (last == nullptr) continue;
    const double reach = k > 0 ? reach_px(k) : restart_px;
    for (const auto& now : steps[k].placed) {
      const auto* was = findLabel(last->placed, now);
      if (was == nullptr) continue;
      if (now.movedFrom(*was) > reach) ++jumps;
    }
  }
  return jumps;
}

}  // namespace

namespace {

// `step` lists the label of `key` as `listed` (its slot at the step before) and places it by no
// body.
template <typename Step, typename LabelAt>
void keepListed(Step& step, const LabelSlot& listed, const LabelAt& key) {
  step.placed.erase(std::remove_if(step.placed.begin(), step.placed.end(),
                                   [&](const LabelAt& at) {
                                     return at.panel == key.panel && at.body == key.body &&
                                            at.velocity == key.velocity;
                                   }),
                    step.placed.end());
  LabelSlot* slot = findLabel(step.slots, key);
  if (slot != nullptr) {
    *slot = listed;
  } else {
    step.slots.push_back(listed);
  }
}

}  // namespace

void LabelTimeline::planWays(std::vector<Step>& steps, const Step* before, AfterEnd* after) const {
  std::vector<LabelProbe> probes = probesOf(steps);
  // Readouts first, as placement places them (their arrows leave the least room), then masses.
  std::vector<LabelAt> keys;
  for (const Step& step : steps) {
    for (const LabelAt& label : step.placed) {
      if (findLabel(keys, label) == nullptr) keys.push_back(label);
    }
  }
  std::stable_sort(keys.begin(), keys.end(),
                   [](const LabelAt& a, const LabelAt& b) { return a.velocity && !b.velocity; });
  std::vector<LabelProbe::Fixed> unfixed;
  for (const LabelProbe& probe : probes) unfixed.push_back(probe.fixed());
  const std::optional<LabelProbe::Fixed> after_unfixed =
      after != nullptr ? std::optional(after->probe.fixed()) : std::nullopt;
  const std::optional<LabelProbe::Fixed> later_unfixed =
      after != nullptr && !after->later.empty() ? std::optional(after->later.front().probe.fixed())
                                                : std::nullopt;
  const std::vector<Step> unplanned = steps;
  for (const LabelAt& key : keys) planWay(steps, before, probes, after, key);
  // Where a label planned after others finds every way they left it running into something or
  // another's line (in 2D the bodies fly past each other's labels; along a track a mass label
  // riding with its block closes in on the other's, standing, until the two read as one line),
  // planned again first: the shot keeps the plan whose labels run into something at fewer steps,
  // then the one whose labels continue another's line at fewer.
  const auto replan = [&](const std::vector<LabelAt>& order) {
    for (std::size_t k = 0; k < probes.size(); ++k) probes[k].restore(unfixed[k]);
    if (after_unfixed) after->probe.restore(*after_unfixed);
    if (later_unfixed) after->later.front().probe.restore(*later_unfixed);
    std::vector<Step> again = unplanned;
    for (const LabelAt& key : order) planWay(again, before, probes, after, key);
    return again;
  };
  const std::vector<LabelAt> again_keys = runningIntoFirst(steps, keys);
  if (!again_keys.empty()) {
    std::vector<Step> again = replan(again_keys);
    if (stepsNotTaken(again) < stepsNotTaken(steps)) steps = std::move(again);
  }
  // Where a label jumps on its way (bouncing-ball 640x360 at its bounces: the readout, planned
  // first, glides up into the place its mass label stood on across the event, and the mass label
  // leaves it in one jump, 130-184 px), the shot is planned again with the mass labels first.
  // It keeps that plan where it jumps fewer times and every label takes its way at every step:
  // a step not taken is a frame placed afresh, a jump the plan does not count (billiards-follow's
  // m₂ pushed into its legend, the legend's lines moving 159 px).
  const auto reach_px = [&](std::size_t k) {
    return (unplanned[k].t_s - unplanned[k - 1].t_s) *
               glideSpeedAt(unplanned[k].t_s, unplanned[k].two_d) +
           kJumpSlackPx;
  };
  const double restart_px = kEventGlidePxPerS / kFramesPerS + kJumpSlackPx;
  const std::size_t jumps = jumpsIn(steps, before, restart_px, reach_px);
  if (jumps > 0) {
    std::vector<LabelAt> masses_first = keys;
    std::stable_sort(masses_first.begin(), masses_first.end(),
                     [](const LabelAt& a, const LabelAt& b) { return !a.velocity && b.velocity; });
    std::vector<Step> other = replan(masses_first);
    if (stepsNotTaken(other) == std::pair<std::size_t, std::size_t>{0, 0} &&
        jumpsIn(other, before, restart_px, reach_px) < jumps) {
      steps = std::move(other);
    }
  }
  keepListedUntilTaken(steps);
}

void LabelTimeline::keepListedUntilTaken(std::vector<Step>& steps) {
  for (std::size_t k = 1; k < steps.size(); ++k) {
    const std::vector<LabelAt> placed = steps[k].placed;
    for (const LabelAt& at : placed) {
      if (at.taken) continue;
      if (const std::optional<LabelSlot> listed = listedAt(steps, k - 1, at)) {
        keepListed(steps[k], *listed, at);
      }
    }
  }
}

void LabelTimeline::planWay(std::vector<Step>& steps, const Step* before,
                            std::vector<LabelProbe>& probes, AfterEnd* after,
                            const LabelAt& key) const {
  // Planned in runs of steps where its places are of one kind (as many candidates: an arrow that
  // appears or vanishes changes them), each run starting where the one before left it, so that
  // it never jumps where its kind of places changes.
  const LabelAt* was = before != nullptr ? findLabel(before->placed, key) : nullptr;
  const auto kindAt = [&](std::size_t k) -> std::size_t {
    const Label* label = probes[k].label(key.panel, key.body, key.velocity);
    return label != nullptr && findLabel(steps[k].placed, key) != nullptr ? label->candidates.size()
                                                                          : 0;
  };
  for (std::size_t first = 0; first < steps.size();) {
    const std::size_t kind = kindAt(first);
    if (kind == 0) {
      // Where it gives way it stands nowhere: the run after starts afresh.
      was = nullptr;
      ++first;
      continue;
    }
    std::size_t last = first;
    while (last + 1 < steps.size() && kindAt(last + 1) == kind) ++last;
    planRun(steps, first, last, was, probes, last + 1 == steps.size() ? after : nullptr, key);
    was = findLabel(steps[last].placed, key);
    first = last + 1;
  }
}

}  // namespace collide::compose
