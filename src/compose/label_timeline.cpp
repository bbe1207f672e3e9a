// SPDX-License-Identifier: MIT
#include "compose/label_timeline.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

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
// A label that moves this much more than its body from one step to the next changed its place
// (more than one pressed against the frame's edge slides along its body in a step).
constexpr double kChangePx = 1.0;
// The fastest a smooth step moves, as a share of its mean speed.
constexpr double kGlidePeak = 1.5;
// How firmly a label holds its place in a shot, in lines of distance (a better place gains less
// than that): more than any slide along its row, far less than an overlap or two labels reading
// as one line, so where it must move, it moves.
constexpr double kHeldLines = 12.0;

double largest(const core::Vec2& v) {
  return std::max(std::abs(v.x()), std::abs(v.y()));
}

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
        label.placed_px = label.shown_px = at->top_left_px;
        label.body_px = body_px[p][i];
        placed.push_back(label);
      }
    }
  }
  return placed;
}

namespace {

// The label of `key` in `placed`, if placed.
template <typename LabelAt>
const LabelAt* findLabel(const std::vector<LabelAt>& placed, const LabelAt& key) {
  for (const LabelAt& label : placed) {
    if (label.panel == key.panel && label.body == key.body && label.velocity == key.velocity) {
      return &label;
    }
  }
  return nullptr;
}

double smoothStep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

}  // namespace

core::Vec2 LabelTimeline::shownAt(const LabelAt& glide, const core::Vec2& placed_px,
                                  const core::Vec2& body_px, double t_s) {
  // A frame at a step's instant may fall a rounding error before it.
  const double since = std::max(0.0, t_s - glide.glide_start_s);
  if (!(glide.glide_length_s > 0.0) || !(since < glide.glide_length_s) ||
      t_s < glide.glide_start_s - kStepRounding_s) {
    return placed_px;
  }
  const core::Vec2 from = body_px + glide.glide_from_offset_px;
  return from + smoothStep(since / glide.glide_length_s) * (placed_px - from);
}

void LabelTimeline::glideOn(LabelAt& label, const LabelAt& before, double t_s, double px_per_s) {
  const core::Vec2 carried = label.body_px - before.body_px;
  if (largest(label.placed_px - (before.placed_px + carried)) > kChangePx) {
    // A new place: glide there from where the label is shown, carried along by its body.
    const core::Vec2 from = before.shown_px + carried;
    label.glide_from_offset_px = from - label.body_px;
    label.glide_start_s = t_s;
    label.glide_length_s =
        std::max(kGlide_s, kGlidePeak * (label.placed_px - from).norm() / px_per_s);
  } else {
    label.glide_from_offset_px = before.glide_from_offset_px;
    label.glide_start_s = before.glide_start_s;
    label.glide_length_s = before.glide_length_s;
  }
  label.shown_px = shownAt(label, label.placed_px, label.body_px, t_s);
}

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
  std::vector<Step> steps = walkFrom(start, end, plan, before);
  // Planned again from the places the labels took at the shot's end, held firmly: bodies that
  // close in end the shot where their labels have least room, and labels that stand there from
  // the start need not move while the video plays.
  if (steps.size() > 1) {
    LabelSlots held = steps.back().slots;
    for (LabelSlot& slot : held) slot.leaves_lines = kHeldLines;
    plan = planAt(settled_s, &held);
    steps = walkFrom(start, end, plan, before);
  }
  return steps;
}

LabelSlots LabelTimeline::planAt(double t_s, const LabelSlots* keep) {
  LabelSlots plan;
  frame::FrameModel sample = picture_.compose(t_s);
  picture_.place(sample, keep, &plan);
  return plan;
}

std::vector<LabelTimeline::Step> LabelTimeline::walkFrom(double start_s, double end_s,
                                                         const LabelSlots& plan,
                                                         const Step* before) {
  std::vector<Step> steps;
  for (int j = 0;; ++j) {
    const double t = start_s + j * kStep_s;
    if (j > 0 && t >= end_s) break;
    steps.push_back(
        step(t, steps.empty() ? nullptr : &steps.back(), plan, steps.empty() ? before : nullptr));
  }
  return steps;
}

LabelTimeline::Step LabelTimeline::step(double t_s, const Step* last, const LabelSlots& plan,
                                        const Step* shot_before) {
  frame::FrameModel frame = picture_.compose(t_s);
  const frame::FrameModel unplaced = frame;
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
  const Step* previous = last != nullptr ? last : shot_before;
  // Right after an event the labels may glide faster (the bodies jump too).
  const double px_per_s = t_s - shot_starts_s_[shotAt(t_s)] < kShortestShot_s && shotAt(t_s) > 0
                              ? kEventGlidePxPerS
                              : kGlidePxPerS;
  bool gliding = false;
  for (LabelAt& label : step.placed) {
    const LabelAt* was = previous != nullptr ? findLabel(previous->placed, label) : nullptr;
    if (was == nullptr) continue;
    glideOn(label, *was, t_s, px_per_s);
    gliding = gliding || largest(label.shown_px - label.placed_px) > 0.5;
  }
  if (!gliding) return step;
  // Shown where they glide, where that runs into nothing.
  frame::FrameModel glided = unplaced;
  const LabelSlots shown = wanting(
      step.slots, step.placed, [](const LabelAt& label) -> core::Vec2 { return label.shown_px; });
  picture_.place(glided, &shown, nullptr);
  for (const LabelAt& at : placedLabels(glided)) {
    for (LabelAt& label : step.placed) {
      if (label.panel != at.panel || label.body != at.body || label.velocity != at.velocity) {
        continue;
      }
      // Where the way is blocked it takes its new place at once, and glides no more.
      if (largest(at.placed_px - label.shown_px) > 0.5) label.glide_length_s = 0.0;
      label.shown_px = at.placed_px;
    }
  }
  return step;
}

core::Vec2 LabelTimeline::plannedAt(const LabelAt& planned, const core::Vec2& body_px, double t_s) {
  return shownAt(planned, planned.placed_px + (body_px - planned.body_px), body_px, t_s);
}

void LabelTimeline::place(frame::FrameModel& frame, double t_s) {
  const std::vector<Step>& steps = walkOf(shotAt(t_s));
  const double since = std::floor((t_s - steps.front().t_s + kStepRounding_s) / kStep_s);
  const Step& step =
      steps[std::min(steps.size() - 1, static_cast<std::size_t>(std::max(0.0, since)))];
  const std::vector<std::vector<core::Vec2>> body_px = picture_.body_px(frame);
  // Each label where its step put it, carried along by its body since, or gliding there.
  LabelSlots keep = wanting(step.slots, step.placed, [&](const LabelAt& planned) -> core::Vec2 {
    const core::Vec2 body =
        planned.panel < body_px.size() && planned.body < body_px[planned.panel].size()
            ? body_px[planned.panel][planned.body]
            : planned.body_px;
    return plannedAt(planned, body, t_s);
  });
  for (LabelSlot& slot : keep) slot.leaves_lines = kHeldLines;
  picture_.place(frame, &keep, nullptr);
}

}  // namespace collide::compose
