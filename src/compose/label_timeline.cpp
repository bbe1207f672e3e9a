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

// How long after a shot's start (at most, and at most this share of it) its places are chosen.
constexpr double kSettle_s = 0.25;
constexpr double kSettleShare = 0.25;
// A shot's last step stands this long before its end (the next event).
constexpr double kEndGuard_s = 1e-6;
// How firmly a label holds its place in a shot, in lines of distance (a better place gains less
// than that): more than any slide along its row, far less than an overlap or two labels reading
// as one line, so where it must move, it moves.
constexpr double kHeldLines = 12.0;

// The slots of `keep` listed in a legend (LabelSlot::legend, by no body) that `chosen` has no
// slot for: their labels are not shown now. Without them a readout that comes back (its block
// hit again) was listed as a new line, wherever the legend had room for one, and a legend whose
// shot was planned again from its end came apart at the event (granular-chain at 2.82 s).
LabelSlots goneListed(const LabelSlots& keep, const LabelSlots& chosen) {
  LabelSlots gone;
  for (const LabelSlot& slot : keep) {
    if (slot.candidate >= 0 || !slot.legend || findLabel(chosen, slot) != nullptr) continue;
    gone.push_back(slot);
    gone.back().wanted_px.reset();
    gone.back().holds = false;
  }
  return gone;
}

bool samePoint(const core::Vec2& a, const core::Vec2& b) {
  return a.x() == b.x() && a.y() == b.y();
}

bool sameLine(const std::optional<LegendLine>& a, const std::optional<LegendLine>& b) {
  if (!a || !b) return a.has_value() == b.has_value();
  return samePoint(a->px, b->px) && a->width_px == b->width_px && a->by == b->by &&
         samePoint(a->by_px, b->by_px) && samePoint(a->first_px, b->first_px);
}

// Whether two plans hold the same slots, every field alike.
bool samePlaces(const LabelSlots& a, const LabelSlots& b) {
  return std::equal(
      a.begin(), a.end(), b.begin(), b.end(), [](const LabelSlot& x, const LabelSlot& y) {
        const bool same_want = x.wanted_px && y.wanted_px
                                   ? samePoint(*x.wanted_px, *y.wanted_px)
                                   : x.wanted_px.has_value() == y.wanted_px.has_value();
        return x.panel == y.panel && x.body == y.body && x.velocity == y.velocity &&
               x.candidate == y.candidate && x.candidates == y.candidates &&
               x.leaves_lines == y.leaves_lines && same_want && x.holds == y.holds &&
               sameLine(x.legend, y.legend) && x.planned_width_px == y.planned_width_px;
      });
}

}  // namespace

LabelSlots LabelTimeline::Step::remembered() const {
  LabelSlots all = slots;
  all.insert(all.end(), gone.begin(), gone.end());
  return all;
}

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
    // The frames of the shots walked are not composed again.
    const std::size_t next = walks_.size();
    composed_.erase(composed_.begin(), next < shot_starts_s_.size()
                                           ? composed_.lower_bound(shot_starts_s_[next])
                                           : composed_.end());
  }
  return walks_[shot];
}

frame::FrameModel LabelTimeline::composedAt(double t_s) const {
  auto found = composed_.find(t_s);
  if (found == composed_.end()) found = composed_.emplace(t_s, picture_.compose(t_s)).first;
  return found->second;
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
        label.size_px = at->size_px;
        label.two_d = frame.panels[p].two_d;
        placed.push_back(label);
      }
    }
  }
  return placed;
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
  const LabelSlots before_slots = before != nullptr ? before->remembered() : LabelSlots{};
  LabelSlots plan = planAt(settled_s, before != nullptr ? &before_slots : nullptr);
  const bool ends_at_event = shot + 1 < shot_starts_s_.size();
  std::vector<Step> steps = walkFrom(start, end, plan, ends_at_event);
  // Planned again from the places the labels took at the shot's end, held firmly: bodies that
  // close in end the shot where their labels have least room, and labels that stand there from
  // the start need not move while the video plays.
  if (steps.size() > 1) {
    LabelSlots held = steps.back().remembered();
    for (LabelSlot& slot : held) slot.leaves_lines = kHeldLines;
    LabelSlots again = planAt(settled_s, &held);
    // A walk is the same from the same places: where the shot's end chose them again, the first
    // walk stands.
    if (!samePlaces(again, plan)) {
      plan = std::move(again);
      steps = walkFrom(start, end, plan, ends_at_event);
    }
  }
  std::optional<AfterEnd> after;
  if (ends_at_event) {
    const double next_end =
        shot + 2 < shot_starts_s_.size() ? shot_starts_s_[shot + 2] : duration_s_;
    after = afterEnd(end, end + kStep_s < next_end ? end + kStep_s : -1.0);
  }
  const std::optional<LabelProbe::Fixed> unfixed =
      after ? std::optional(after->probe.fixed()) : std::nullopt;
  planWays(steps, before, after ? &*after : nullptr);
  listJumping(steps, start, end, ends_at_event, plan, before, after ? &*after : nullptr, unfixed);
  return steps;
}

LabelSlots LabelTimeline::planAt(double t_s, const LabelSlots* keep) {
  LabelSlots plan;
  frame::FrameModel sample = composedAt(t_s);
  picture_.place(sample, keep, &plan);
  if (keep != nullptr) {
    const LabelSlots gone = goneListed(*keep, plan);
    plan.insert(plan.end(), gone.begin(), gone.end());
  }
  return plan;
}

std::vector<LabelTimeline::Step> LabelTimeline::walkFrom(double start_s, double end_s,
                                                         const LabelSlots& plan, bool ends_at_event,
                                                         const LabelSlots* listing) {
  std::vector<Step> steps;
  addStep(steps, start_s, plan, listing);
  // In 2D the steps after the first stand on the grid of kStep_s from t = 0, the first at least
  // half a step after the shot's start: a label that stops riding with its ball and stands still
  // (or sets off with it) at a step moves part of the frame one way and part the other (3-5 px
  // beyond its ball and on the page where the ball crosses 9 px a frame), unless the step is a
  // frame's instant. On the grid every step is one of the frames of a video at 30 or 60 fps
  // where its playback is not slowed down.
  if (steps.front().two_d) {
    const double first = std::ceil(start_s / kStep_s + 0.5);
    for (int j = 0;; ++j) {
      const double t = (first + j) * kStep_s;
      if (t >= end_s) break;
      addStep(steps, t, plan, listing);
    }
  } else {
    for (int j = 1;; ++j) {
      const double t = start_s + j * kStep_s;
      if (t >= end_s) break;
      addStep(steps, t, plan, listing);
    }
  }
  // And its very end, just before the next event, where the frames after the last step go; the
  // video's last shot at the video's end itself: its last frame stands there, and a label
  // carried along by its body from a hair before, flush with the frame's edge, came out past
  // it and was placed elsewhere with every label it pushed (car-crash 640x360 at 4 s: 60 px).
  const double last_s = ends_at_event ? end_s - kEndGuard_s : end_s;
  if (last_s > steps.back().t_s + kEndGuard_s) addStep(steps, last_s, plan, listing);
  return steps;
}

void LabelTimeline::addStep(std::vector<Step>& steps, double t_s, const LabelSlots& plan,
                            const LabelSlots* listing) {
  Step next = step(t_s, steps.empty() ? nullptr : &steps.back(), plan, listing);
  // Where an arrow is lifted into another row (or set down) between two steps, the frames
  // between have one step's rows and neither step's bodies: a readout over the lifted arrow
  // that comes to read as another's there is placed elsewhere for a frame. A step halfway lets
  // the plan see them (the step after it stays as walked from the one before: placing it again
  // from the step halfway costs time and changed no plan).
  if (!steps.empty() && next.arrow_rows != steps.back().arrow_rows) {
    steps.push_back(step(0.5 * (steps.back().t_s + t_s), &steps.back(), plan, listing));
    steps.back().halfway = true;
  }
  steps.push_back(std::move(next));
}

LabelTimeline::Step LabelTimeline::step(double t_s, const Step* last, const LabelSlots& plan,
                                        const LabelSlots* listing) {
  frame::FrameModel frame = composedAt(t_s);
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
  if (last != nullptr) keep.insert(keep.end(), last->gone.begin(), last->gone.end());
  // In a shot a label leaves its place only where it must.
  for (LabelSlot& slot : keep) {
    slot.leaves_lines = kHeldLines;
    // Listed throughout (listJumping): by no body, held in its legend where that has room.
    if (listing != nullptr && findLabel(*listing, slot) != nullptr) {
      slot.candidate = -1;
      slot.wanted_px.reset();
      slot.holds = true;
    }
  }
  Step step;
  step.t_s = t_s;
  picture_.place(frame, &keep, &step.slots);
  step.gone = goneListed(keep, step.slots);
  step.placed = placedLabels(frame);
  for (const frame::PanelModel& panel : frame.panels) {
    step.two_d = step.two_d || panel.two_d;
    for (const frame::BodyModel& body : panel.bodies) step.arrow_rows.push_back(body.arrow_row);
  }
  return step;
}

double LabelTimeline::glideSpeedAt(double t_s, bool two_d) const {
  const std::size_t shot = shotAt(t_s);
  // Right after an event the labels may move faster (the bodies jump too). Along a track, in the
  // steps that end a step before kShortestShot_s has passed: a step that ends later spreads its
  // glide over the frames after it too, where a frame more than kShortestShot_s after the event
  // moved it faster than 2 px (pi-blocks' m₂, 4 px at 4.0 s; clay's v₁, 5 px at 0.97 s). In 2D
  // (steps on a grid of their own, not from the event) the whole kShortestShot_s: there the
  // shorter span left labels no time to get round a ball (stick-2d's m₂, 143 and 181 px).
  const double fast_for_s = two_d ? kShortestShot_s : kShortestShot_s - kStep_s + kStepRounding_s;
  return shot > 0 && t_s - shot_starts_s_[shot] < fast_for_s ? kEventGlidePxPerS : kGlidePxPerS;
}

}  // namespace collide::compose
