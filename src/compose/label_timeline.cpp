// SPDX-License-Identifier: MIT
#include "compose/label_timeline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "compose/label_cost.hpp"
#include "compose/label_ways.hpp"

namespace collide::compose {
namespace {

// The step a shot is walked at (simulated time): a frame takes the places of the step it falls in.
constexpr double kStep_s = 1.0 / 30.0;
// How long after a shot's start (at most, and at most this share of it) its places are chosen.
constexpr double kSettle_s = 0.25;
constexpr double kSettleShare = 0.25;
// A frame this near a step's instant falls at it (frame k / fps and the step's time differ in
// their last bits).
constexpr double kStepRounding_s = 1e-9;
// A shot's last step stands this long before its end (the next event).
constexpr double kEndGuard_s = 1e-6;
// A label placed this near where its way says is on it.
constexpr double kOnItsWayPx = 0.5;
// How firmly a label holds its place in a shot, in lines of distance (a better place gains less
// than that): more than any slide along its row, far less than an overlap or two labels reading
// as one line, so where it must move, it moves.
constexpr double kHeldLines = 12.0;
// How firmly a label keeps to its way once planned: more than two labels reading as one line
// (kOneLine), far less than an overlap.
constexpr double kOnItsWayLines = 1000.0;
// What changing its place in a shot costs a label, in lines of its text farther off at every
// step: it keeps one place through the shot where that costs less.
constexpr double kChangeLines = 20.0;
// Where a label may stand still while its body moves on (label_ways.hpp's addStandingPlaces):
// its kStandPerStep cheapest places every kStandEvery steps, at most kStandStarts times a run.
constexpr std::size_t kStandEvery = 3;
constexpr std::size_t kStandStarts = 12;
constexpr std::size_t kStandPerStep = 2;
// What starting a shot elsewhere than where a label stood at its event costs, in overlaps: taken
// where staying on runs into something for at least a step.
constexpr double kEventJumpHards = 0.5;

}  // namespace

std::vector<double> shotStarts(std::vector<double> event_times_s) {
  std::sort(event_times_s.begin(), event_times_s.end());
  std::vector<double> starts{0.0};
  for (double t : event_times_s) {
    // The picture before the first impact is a shot of its own however short (a bullet's flight
    // to its block): its texts are not wrapped like the impact's results.
    if (t - starts.back() >= kShortestShot_s || (starts.size() == 1 && t > 0.0)) {
      starts.push_back(t);
    }
  }
  return starts;
}

std::size_t shotOf(const std::vector<double>& shot_starts_s, double t_s) {
  const auto after = std::upper_bound(shot_starts_s.begin() + 1, shot_starts_s.end(), t_s);
  return static_cast<std::size_t>(after - shot_starts_s.begin()) - 1;
}

LabelTimeline::LabelTimeline(std::vector<double> event_times_s, double duration_s, Picture picture)
    : shot_starts_s_(shotStarts(std::move(event_times_s))),
      duration_s_(duration_s),
      picture_(std::move(picture)) {}

std::size_t LabelTimeline::shotAt(double t_s) const {
  return shotOf(shot_starts_s_, t_s);
}

const std::vector<LabelTimeline::Step>& LabelTimeline::walkOf(std::size_t shot) {
  const std::lock_guard<std::mutex> lock(mutex_);
  // Each shot starts where the last one left its labels: walked in order.
  while (walks_.size() <= shot) {
    const Step* before = walks_.empty() ? nullptr : &walks_.back().back();
    std::vector<Step> steps = walk(walks_.size(), before);
    walks_.push_back(std::move(steps));
  }
  return walks_[shot];
}

// The labels `frame` places by their bodies, with the bodies' pixel centres.
std::vector<LabelTimeline::LabelAt> LabelTimeline::placedLabels(const frame::FrameModel& frame) {
  const std::vector<std::vector<core::Vec2>> body_px = picture_.body_px(frame);
  std::vector<LabelAt> placed;
  for (std::size_t p = 0; p < frame.panels.size() && p < body_px.size(); ++p) {
    const std::vector<frame::BodyModel>& bodies = frame.panels[p].bodies;
    for (std::size_t i = 0; i < bodies.size() && i < body_px[p].size(); ++i) {
      for (const bool velocity : {false, true}) {
        const std::optional<frame::PlacedText>& at =
            velocity ? bodies[i].velocity_label_at : bodies[i].label_at;
        if (!at) continue;
        LabelAt label;
        label.panel = p;
        label.body = i;
        label.velocity = velocity;
        label.placed_px = at->top_left_px;
        label.body_px = body_px[p][i];
        label.shown_px = label.placed_px;
        placed.push_back(label);
      }
    }
  }
  return placed;
}

namespace {

// The label of `key` in `placed` (const or not), if placed.
template <typename Labels, typename LabelAt>
auto findLabel(Labels& placed, const LabelAt& key) -> decltype(&placed.front()) {
  for (auto& label : placed) {
    if (label.panel == key.panel && label.body == key.body && label.velocity == key.velocity) {
      return &label;
    }
  }
  return nullptr;
}

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

}  // namespace

// `slots` with each label's wanted place: where `shown` says for the label of the same body.
LabelSlots LabelTimeline::wanting(LabelSlots slots, const std::vector<LabelAt>& labels,
                                  const std::function<core::Vec2(const LabelAt&)>& shown) {
  for (LabelSlot& slot : slots) {
    for (const LabelAt& label : labels) {
      if (label.panel == slot.panel && label.body == slot.body && label.velocity == slot.velocity) {
        slot.wanted_px = shown(label);
      }
    }
  }
  return slots;
}

std::vector<LabelTimeline::Step> LabelTimeline::walk(std::size_t shot, const Step* before) {
  const double start = shot_starts_s_[shot];
  const double end = shot + 1 < shot_starts_s_.size() ? shot_starts_s_[shot + 1] : duration_s_;
  // The places the shot starts from: placed a little after its event, where the bodies stand
  // clear of each other again, each label on the side of its body it stood on before the event
  // where that is free.
  const double settled_s = start + std::min(kSettle_s, kSettleShare * (end - start));
  LabelSlots plan = planAt(settled_s, before != nullptr ? &before->slots : nullptr);
  std::vector<Step> steps = walkFrom(start, end, plan);
  // Planned again from the places the labels took at the shot's end, held firmly: bodies that
  // close in end the shot where their labels have least room, and labels that stand there from
  // the start need not move while the video plays.
  if (steps.size() > 1) {
    LabelSlots held = steps.back().slots;
    for (LabelSlot& slot : held) slot.leaves_lines = kHeldLines;
    plan = planAt(settled_s, &held);
    steps = walkFrom(start, end, plan);
  }
  std::optional<AfterEnd> after;
  if (shot + 1 < shot_starts_s_.size()) {
    frame::FrameModel next = picture_.compose(end);
    after.emplace(AfterEnd{picture_.probe(next), picture_.body_px(next)});
    // Only along a track: in 2D, labels ended where they could stay on across a glancing
    // impact ran into the balls' new ways later in the next shot (billiards-glancing).
    for (std::size_t p = 0; p < next.panels.size() && p < after->body_px.size(); ++p) {
      if (next.panels[p].two_d) after->body_px[p].clear();
    }
  }
  planWays(steps, before, after ? &*after : nullptr);
  return steps;
}

LabelSlots LabelTimeline::planAt(double t_s, const LabelSlots* keep) {
  LabelSlots plan;
  frame::FrameModel sample = picture_.compose(t_s);
  picture_.place(sample, keep, &plan);
  return plan;
}

std::vector<LabelTimeline::Step> LabelTimeline::walkFrom(double start_s, double end_s,
                                                         const LabelSlots& plan) {
  std::vector<Step> steps;
  for (int j = 0;; ++j) {
    const double t = start_s + j * kStep_s;
    if (j > 0 && t >= end_s) break;
    steps.push_back(step(t, steps.empty() ? nullptr : &steps.back(), plan));
  }
  // And its very end, just before the next event, where the frames after the last step go.
  const double last_s = end_s - kEndGuard_s;
  if (last_s > steps.back().t_s + kEndGuard_s) steps.push_back(step(last_s, &steps.back(), plan));
  return steps;
}

LabelTimeline::Step LabelTimeline::step(double t_s, const Step* last, const LabelSlots& plan) {
  frame::FrameModel frame = picture_.compose(t_s);
  const std::vector<std::vector<core::Vec2>> body_px = picture_.body_px(frame);
  const auto bodyAt = [&body_px](const LabelAt& label) -> core::Vec2 {
    return label.panel < body_px.size() && label.body < body_px[label.panel].size()
               ? body_px[label.panel][label.body]
               : label.body_px;
  };
  // Where it was, carried along by its body: in a shot, its slot as it stood a step ago; at a
  // shot's start, the shot's plan.
  LabelSlots keep = last != nullptr ? wanting(last->slots, last->placed,
                                              [&](const LabelAt& was) -> core::Vec2 {
                                                return was.placed_px + (bodyAt(was) - was.body_px);
                                              })
                                    : plan;
  // In a shot a label leaves its place only where it must.
  for (LabelSlot& slot : keep) slot.leaves_lines = kHeldLines;
  Step step;
  step.t_s = t_s;
  picture_.place(frame, &keep, &step.slots);
  step.placed = placedLabels(frame);
  return step;
}

double LabelTimeline::glideSpeedAt(double t_s) const {
  const std::size_t shot = shotAt(t_s);
  // Right after an event the labels may move faster (the bodies jump too).
  return shot > 0 && t_s - shot_starts_s_[shot] < kShortestShot_s ? kEventGlidePxPerS
                                                                  : kGlidePxPerS;
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
  for (const LabelAt& key : keys) planWay(steps, before, probes, after, key);
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

// `box` carried by its body from `body_px` to `then_px`, as wide and high as `size`.
Box carriedBox(const Box& box, const core::Vec2& body_px, const core::Vec2& then_px,
               const core::Vec2& size) {
  const core::Vec2 corner = core::Vec2{box.x0, box.y0} + (then_px - body_px);
  return {corner.x(), corner.y(), corner.x() + size.x(), corner.y() + size.y()};
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
    ways.reach_px.push_back(
        k > first ? (steps[k].t_s - steps[k - 1].t_s) * glideSpeedAt(steps[k].t_s) : 0.0);
    ways.boxes.push_back(label.back()->candidates);
    std::vector<double> costs;
    for (std::size_t c = 0; c < label.back()->candidates.size(); ++c) {
      costs.push_back(probes[k].cost(key.panel, *label.back(), label.back()->candidates[c],
                                     static_cast<int>(c)));
    }
    ways.costs.push_back(std::move(costs));
  }
  ways.change_cost = kChangeLines * label.front()->size.y();
  const auto cost_at = [&](std::size_t j, const Box& box) {
    return probes[first + j].cost(key.panel, *label[j], box, -1);
  };
  // A place between its candidates costs what placement prefers there too: one kept where it
  // stood, or carried along from the run before, returns where placement prefers it.
  const auto between_cost = [&](std::size_t j, const Box& box) {
    return cost_at(j, box) + preferenceAt(*label[j], box);
  };
  addStandingPlaces(ways, std::max<std::size_t>(kStandEvery, ways.boxes.size() / kStandStarts),
                    kStandPerStep, kOneLine, between_cost);
  // Where it stood at the step before the run (the shot before's last step at a shot's start),
  // carried along by its body: it starts there.
  if (was != nullptr) {
    for (std::size_t j = 0; j < at.size(); ++j) {
      const core::Vec2 corner = at[j]->body_px + (was->shown_px - was->body_px);
      const Box box{corner.x(), corner.y(), corner.x() + label[j]->size.x(),
                    corner.y() + label[j]->size.y()};
      ways.boxes[j].push_back(box);
      ways.costs[j].push_back(between_cost(j, box));
    }
    ways.starts_on_last = true;
    // At the event that starts the shot it may start elsewhere instead, where staying on would
    // run into something: one jump at the event reads better than a label placed off its way
    // while it runs into something (elsewhere, frame by frame) and back.
    if (first == 0) ways.restart_cost = kEventJumpHards * kHard;
  }
  // Where the shot ends at its next event, what each place at its last step costs carried
  // across it (the new arrows, bodies in contact).
  const Label* then =
      after != nullptr ? after->probe.label(key.panel, key.body, key.velocity) : nullptr;
  const bool across = then != nullptr && key.panel < after->body_px.size() &&
                      key.body < after->body_px[key.panel].size();
  const auto carried = [&](const Box& box) {
    return carriedBox(box, at.back()->body_px, after->body_px[key.panel][key.body], then->size);
  };
  std::vector<double> across_costs;
  for (std::size_t c = 0; across && c < ways.boxes.back().size(); ++c) {
    across_costs.push_back(after->probe.cost(key.panel, *then, carried(ways.boxes.back()[c]), -1));
  }
  const Way way = endingWay(ways, across_costs, kEventJumpHards * kHard, cost_at, kOneLine);
  for (std::size_t j = 0; j < at.size(); ++j) {
    at[j]->shown_px = core::Vec2{way.shown[j].x0, way.shown[j].y0};
    at[j]->rides = way.rides[j];
    probes[first + j].fix(key.panel, *label[j], way.shown[j], -1);
  }
  if (across) after->probe.fix(key.panel, *then, carried(way.shown.back()), -1);
}

void LabelTimeline::place(frame::FrameModel& frame, double t_s) {
  const std::vector<Step>& steps = walkOf(shotAt(t_s));
  // The last step at or before t_s (a frame at a step's instant may fall a rounding error
  // before it).
  const auto after = std::upper_bound(steps.begin() + 1, steps.end(), t_s + kStepRounding_s,
                                      [](double t, const Step& step) { return t < step.t_s; });
  const auto k = static_cast<std::size_t>(after - steps.begin()) - 1;
  const Step* next = k + 1 < steps.size() ? &steps[k + 1] : nullptr;
  // Between its step's place and the next one's, where the label glides.
  const double share = next != nullptr
                           ? std::clamp((t_s - steps[k].t_s) / (next->t_s - steps[k].t_s), 0.0, 1.0)
                           : 0.0;
  const std::vector<std::vector<core::Vec2>> body_px = picture_.body_px(frame);
  // Where something between the steps blocks the way (an arrow lifted into another row carries
  // its readout's rows along at once), the next step's place or this one's, a step's reach away.
  const frame::FrameModel unplaced = frame;
  for (const double at_share : {share, 1.0, 0.0}) {
    if (at_share != share && next == nullptr) break;
    frame = unplaced;
    const LabelSlots keep = plannedAt(steps[k], next, at_share, body_px);
    picture_.place(frame, &keep, nullptr);
    if (onTheirWays(frame, keep)) return;
  }
  frame = unplaced;
  const LabelSlots keep = plannedAt(steps[k], next, share, body_px);
  picture_.place(frame, &keep, nullptr);
}

LabelSlots LabelTimeline::plannedAt(const Step& step, const Step* next, double share,
                                    const std::vector<std::vector<core::Vec2>>& body_px) {
  LabelSlots keep = wanting(step.slots, step.placed, [&](const LabelAt& planned) -> core::Vec2 {
    const core::Vec2 body =
        planned.panel < body_px.size() && planned.body < body_px[planned.panel].size()
            ? body_px[planned.panel][planned.body]
            : planned.body_px;
    const core::Vec2 carried = planned.shown_px + (body - planned.body_px);
    const LabelAt* then = next != nullptr ? findLabel(next->placed, planned) : nullptr;
    if (then == nullptr) return carried;
    // Riding with its body, it moves beyond it by its share of the way; standing, by its share.
    if (then->rides) {
      return carried +
             share * ((then->shown_px - then->body_px) - (planned.shown_px - planned.body_px));
    }
    return planned.shown_px + share * (then->shown_px - planned.shown_px);
  });
  for (LabelSlot& slot : keep) slot.leaves_lines = kOnItsWayLines;
  return keep;
}

bool LabelTimeline::onTheirWays(const frame::FrameModel& frame, const LabelSlots& keep) {
  const std::vector<LabelAt> placed = placedLabels(frame);
  for (const LabelSlot& slot : keep) {
    if (!slot.wanted_px) continue;
    const LabelAt* at = nullptr;
    for (const LabelAt& label : placed) {
      if (label.panel == slot.panel && label.body == slot.body && label.velocity == slot.velocity)
        at = &label;
    }
    if (at == nullptr || (at->placed_px - *slot.wanted_px).norm() > kOnItsWayPx) return false;
  }
  return true;
}

}  // namespace collide::compose
