// SPDX-License-Identifier: MIT
// LabelTimeline's ways through a shot: each label's widest text, the probes its steps are priced
// with, and the way (label_ways.hpp) each label takes from step to step.
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
  const auto boxOf = [](const LabelAt& at) {
    return Box{at.shown_px.x(), at.shown_px.y(), at.shown_px.x() + at.size_px.x(),
               at.shown_px.y() + at.size_px.y()};
  };
  return moveBetween(boxOf(was), was.body_px, boxOf(*this), body_px).px;
}

namespace {

// What changing its place in a shot costs a label, in lines of its text farther off at every
// step: it keeps one place through the shot where that costs less.
constexpr double kChangeLines = 20.0;
// The same in a 2D panel, where a label keeps its side of its ball more firmly: beside a ball in
// flight a change of place is seldom a glide (the places between run into the ball's turning
// arrow) but a jump, so a place a little better must not draw it off (bouncing-ball 640x360's
// m₁ swapped under its readout after the last bounces, 42 and 77 px).
constexpr double kChangeLines2d = 60.0;
// Where a label may stand still while its body moves on (label_ways.hpp's addStandingPlaces):
// its kStandPerStep cheapest places every kStandEvery steps, at most kStandStarts times a run.
constexpr std::size_t kStandEvery = 3;
constexpr std::size_t kStandStarts = 12;
constexpr std::size_t kStandPerStep = 2;
// What starting a shot elsewhere than where a label stood at its event costs, in overlaps: taken
// where staying on runs into something for at least a step.
constexpr double kEventJumpHards = 0.5;
// What a jump within a shot costs a label in a 2D panel, in overlaps: taken only where every way
// that glides runs into something for longer (a place it runs into is no place at all: the frame
// places it elsewhere, one jump there and another back). A ball in flight crosses the picture
// faster than any glide takes a label around it; along a track, bodies close in slowly enough.
constexpr double kInShotJumpHards = 0.5;

// What placement prefers of a place between its candidates: what the nearest one prefers, and a
// pixel for each pixel farther (as a slide along a row costs, label_candidates.cpp).
double preferenceAt(const Label& label, const Box& box) {
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < label.candidates.size() && c < label.base_cost.size(); ++c) {
    // A distance is never negative: a candidate that prefers no less than the least so far
    // cannot lower it (and hypot is dear where this runs for every standing place and step).
    if (label.base_cost[c] >= least) continue;
    const Box& place = label.candidates[c];
    least = std::min(least, label.base_cost[c] + std::hypot(box.x0 - place.x0, box.y0 - place.y0));
  }
  return std::isfinite(least) ? least : 0.0;
}

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
  frame::FrameModel next = picture_.compose(end_s);
  AfterEnd after{picture_.probe(next), picture_.body_px(next), {}};
  if (later_s >= 0.0) {
    frame::FrameModel later = picture_.compose(later_s);
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
    frames.push_back(picture_.compose(step.t_s));
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

namespace {

// How many of the steps are not halfway between two.
std::size_t wholeSteps(const WaySteps& ways) {
  return static_cast<std::size_t>(std::count(ways.halfway.begin(), ways.halfway.end(), false));
}

// `box` carried by its body from `body_px` to `then_px`, as wide and high as `size`. Along a
// track (not `two_d`), a text that narrows (a readout whose arrow is gone at an event, "v₁′ =
// 0 m/s") in a place wholly left of its body keeps its right edge, by its block, where its left
// edge would leave it standing off on its own; else its left edge stays.
Box carriedBox(const Box& box, const core::Vec2& body_px, const core::Vec2& then_px,
               const core::Vec2& size, bool two_d) {
  core::Vec2 corner = core::Vec2{box.x0, box.y0} + (then_px - body_px);
  const double width = box.x1 - box.x0;
  if (!two_d && box.x1 <= body_px.x() && size.x() < width) corner.x() += width - size.x();
  return {corner.x(), corner.y(), corner.x() + size.x(), corner.y() + size.y()};
}

// Where label `was` (a LabelTimeline::LabelAt) stood, carried by its body to `body_px`, as wide
// and high as `size`.
template <typename LabelAt>
Box whereItStood(const LabelAt& was, const core::Vec2& body_px, const core::Vec2& size,
                 bool two_d) {
  const core::Vec2 corner = was.shown_px;
  return carriedBox(
      {corner.x(), corner.y(), corner.x() + was.size_px.x(), corner.y() + was.size_px.y()},
      was.body_px, body_px, size, two_d);
}

// Whether the label `was` (at the step before a run) runs into something carried along by its
// body to `now`, the run's first step, and nothing standing where it stood (`cost(0, box)`).
template <typename LabelAt, typename Cost>
bool standsWhereCarriedRunsInto(const LabelAt& was, const LabelAt& now, const Label& label,
                                const Cost& cost) {
  return cost(0, whereItStood(was, was.body_px, label.size, true)) < kHard &&
         cost(0, whereItStood(was, now.body_px, label.size, true)) >= kHard;
}

// Where `was` stood at the step before the run (the shot before's last step at a shot's start,
// `at_event`), carried along by its body, as each step's last candidate: it starts there.
template <typename LabelAt, typename Cost>
void startWhereItStood(WaySteps& ways, const std::vector<LabelAt*>& at,
                       const std::vector<const Label*>& label, const LabelAt& was, bool at_event,
                       bool two_d, const Cost& between_cost) {
  // In 2D, where its kind of places changes within the shot and the place it had runs into
  // something carried along, it stands where it stood if that is free: a bullet's readout where
  // its arrow vanishes in its last frame before the block (carried 145 px a frame into it).
  const bool stands = two_d && !at_event &&
                      standsWhereCarriedRunsInto(was, *at.front(), *label.front(), between_cost);
  for (std::size_t j = 0; j < at.size(); ++j) {
    const Box box = whereItStood(was, stands ? was.body_px : at[j]->body_px, label[j]->size, two_d);
    ways.boxes[j].push_back(box);
    ways.costs[j].push_back(between_cost(j, box));
  }
  ways.starts_on_last = true;
  // At the event that starts the shot it may start elsewhere instead, where staying on would
  // run into something: one jump at the event reads better than a label placed off its way
  // while it runs into something (elsewhere, frame by frame) and back.
  if (at_event) {
    ways.restart_cost = kEventJumpHards * kHard;
  } else if (two_d) {
    // Where its kind of places changes within the shot (its arrow grew past its ball's edge):
    // as anywhere in its shot, rather than a step where it stood running into something.
    ways.restart_cost = kInShotJumpHards * kHard;
  }
}

}  // namespace

void LabelTimeline::planRun(std::vector<Step>& steps, std::size_t first, std::size_t last,
                            const LabelAt* was, std::vector<LabelProbe>& probes, AfterEnd* after,
                            const LabelAt& key) const {
  std::vector<LabelAt*> at;
  std::vector<const Label*> label;
  WaySteps ways;
  for (std::size_t k = first; k <= last; ++k) {
    at.push_back(findLabel(steps[k].placed, key));
    label.push_back(probes[k].label(key.panel, key.body, key.velocity));
    ways.body_px.push_back(at.back()->body_px);
    ways.t_s.push_back(steps[k].t_s);
    ways.halfway.push_back(steps[k].halfway);
    ways.reach_px.push_back(k > first ? (steps[k].t_s - steps[k - 1].t_s) *
                                            glideSpeedAt(steps[k].t_s, key.two_d)
                                      : 0.0);
    ways.boxes.push_back(label.back()->candidates);
    std::vector<double> costs;
    for (std::size_t c = 0; c < label.back()->candidates.size(); ++c) {
      costs.push_back(probes[k].cost(key.panel, *label.back(), label.back()->candidates[c],
                                     static_cast<int>(c)));
    }
    ways.costs.push_back(std::move(costs));
  }
  ways.change_cost = (key.two_d ? kChangeLines2d : kChangeLines) * label.front()->size.y();
  const auto cost_at = [&](std::size_t j, const Box& box) {
    return probes[first + j].cost(key.panel, *label[j], box, -1);
  };
  // A place between its candidates costs what placement prefers there too: one kept where it
  // stood, or carried along from the run before, returns where placement prefers it.
  const auto between_cost = [&](std::size_t j, const Box& box) {
    return cost_at(j, box) + preferenceAt(*label[j], box);
  };
  if (key.two_d) ways.jump_cost = kInShotJumpHards * kHard;
  addStandingPlaces(ways, std::max<std::size_t>(kStandEvery, wholeSteps(ways) / kStandStarts),
                    kStandPerStep, kOneLine, between_cost);
  if (was != nullptr) startWhereItStood(ways, at, label, *was, first == 0, key.two_d, between_cost);
  // Where the shot ends at its next event, what each place at its last step costs carried
  // across it (the new arrows, bodies in contact), and on to the next shot's first step after
  // it: a readout whose text widens there (air-track's v₂′ through the wall bounce) leaves a
  // place it would not have there before the event, not at it (39 px at once).
  std::vector<AfterEnd*> instants;
  if (after != nullptr) instants.push_back(after);
  if (after != nullptr && !after->later.empty()) instants.push_back(&after->later.front());
  const auto then_of = [&](const AfterEnd& end) -> const Label* {
    const Label* then = end.probe.label(key.panel, key.body, key.velocity);
    return then != nullptr && key.panel < end.body_px.size() &&
                   key.body < end.body_px[key.panel].size()
               ? then
               : nullptr;
  };
  const auto carried = [&](const AfterEnd& end, const Box& box) {
    return carriedBox(box, at.back()->body_px, end.body_px[key.panel][key.body], then_of(end)->size,
                      key.two_d);
  };
  std::vector<double> across_costs;
  for (const AfterEnd* end : instants) {
    const Label* then = then_of(*end);
    if (then == nullptr) continue;
    across_costs.resize(ways.boxes.back().size(), 0.0);
    for (std::size_t c = 0; c < ways.boxes.back().size(); ++c) {
      across_costs[c] += end->probe.cost(key.panel, *then, carried(*end, ways.boxes.back()[c]), -1);
    }
  }
  const Way way = endingWay(ways, across_costs, kEventJumpHards * kHard, cost_at, kOneLine);
  for (std::size_t j = 0; j < at.size(); ++j) {
    at[j]->shown_px = core::Vec2{way.shown[j].x0, way.shown[j].y0};
    at[j]->rides = way.rides[j];
    at[j]->size_px = label[j]->size;
    const double cost = cost_at(j, way.shown[j]);
    at[j]->free = cost < kHard;
    at[j]->taken = cost < kOneLine;
    probes[first + j].fix(key.panel, *label[j], way.shown[j], -1);
  }
  for (AfterEnd* end : instants) {
    const Label* then = then_of(*end);
    if (then != nullptr) end->probe.fix(key.panel, *then, carried(*end, way.shown.back()), -1);
  }
}

}  // namespace collide::compose
