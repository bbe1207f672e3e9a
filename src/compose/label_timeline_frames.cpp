// SPDX-License-Identifier: MIT
// LabelTimeline's frames: a frame at any instant placed from the steps its shot was walked at,
// each label between its places at the step before and the step after.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "compose/label_cost.hpp"
#include "compose/label_timeline.hpp"
#include "compose/label_ways.hpp"

namespace collide::compose {
namespace {

// A label placed this near where its way says is on it.
constexpr double kOnItsWayPx = 0.5;
// How firmly a label keeps to its way once planned: more than two labels reading as one line
// (kOneLine), far less than an overlap.
constexpr double kOnItsWayLines = 1000.0;

// How far `label` stands from where `slot` wants it: at its corner, or a text narrower than
// planned at the planned box's right edge (placement's wantedCorner, by its body's left edge),
// whichever is nearer. `slot` wants it somewhere (wanted_px).
template <typename LabelAt>
double offItsWayPx(const LabelSlot& slot, const LabelAt& label) {
  const core::Vec2 right_kept =
      wantedCorner(slot, label.size_px, std::numeric_limits<double>::infinity());
  return std::min((label.placed_px - *slot.wanted_px).norm(),
                  (label.placed_px - right_kept).norm());
}

// Whether `label` stands where `slot` wants it.
template <typename LabelAt>
bool standsWanted(const LabelSlot& slot, const LabelAt& label) {
  return slot.wanted_px && offItsWayPx(slot, label) <= kOnItsWayPx;
}

// Whether `slot` is listed in its legend in the layout over time's plan (by no body, not asked
// to stand anywhere): it stays listed in the frames of its step, not taken out of the legend
// before its way by its body starts.
bool listedInAWay(const LabelSlot& slot) {
  return slot.candidate < 0 && slot.legend.has_value() && !slot.wanted_px;
}

// Whether every label `keep` lists (listedInAWay) stands in `frame`'s legend on its row where it
// stood (LabelSlot::legend) or there carried along by the body its legend stood by: within
// jump_px up or down, and left or right no more than half its width (a number that grows or
// shrinks keeps one edge). A legend placed afresh moves every line of it at once.
bool legendKept(const frame::FrameModel& frame, const LabelSlots& keep,
                const std::vector<std::vector<core::Vec2>>& body_px, double jump_px) {
  return std::all_of(keep.begin(), keep.end(), [&](const LabelSlot& slot) {
    if (!listedInAWay(slot) || slot.panel >= frame.panels.size()) return true;
    const LegendLine& was = *slot.legend;
    const auto by = static_cast<std::size_t>(was.by);
    const core::Vec2 carried =
        was.by >= 0 && slot.panel < body_px.size() && by < body_px[slot.panel].size()
            ? was.px + (body_px[slot.panel][by] - was.by_px)
            : was.px;
    const auto onItsRow = [&](const core::Vec2& at, const core::Vec2& there) {
      return std::abs(at.y() - there.y()) <= jump_px &&
             std::abs(at.x() - there.x()) <= jump_px + 0.5 * was.width_px;
    };
    const auto& entries = frame.panels[slot.panel].legend.entries;
    return std::any_of(entries.begin(), entries.end(), [&](const auto& entry) {
      return entry.body == static_cast<int>(slot.body) && entry.mass == !slot.velocity &&
             (onItsRow(entry.top_left_px, was.px) || onItsRow(entry.top_left_px, carried));
    });
  });
}

}  // namespace

LabelSlots LabelTimeline::placeOnWays(frame::FrameModel& frame, double t_s) {
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
  // (Only 2D ways jump: timed as in 2D.)
  const double jump_px = jumpPxAt(t_s, true);
  // Where something between the steps blocks the way (an arrow lifted into another row carries
  // its readout's rows along at once), the next step's place or this one's, a step's reach away.
  // In 2D, where that fails too, a text narrower than planned left of its body keeps the
  // planned box's right edge, by its body (placement's wantedCorner): at its left edge it stood
  // off on a leader across its body, refused, and was placed elsewhere, frame by frame as its
  // number narrowed (ballistic-pendulum's readout). Only then: a label that keeps its left edge
  // in one frame and its right edge in the next jumps by the difference.
  const frame::FrameModel unplaced = frame;
  for (const bool keep_right : {false, true}) {
    if (keep_right && !steps[k].two_d) break;
    for (const double at_share : {share, 1.0, 0.0}) {
      if (at_share != share && next == nullptr) break;
      frame = unplaced;
      const LabelSlots keep = plannedAt(steps[k], next, at_share, body_px, jump_px, keep_right);
      picture_.place(frame, &keep, nullptr);
      if (onTheirWays(frame, keep) && statesListed(frame, keep)) {
        if (next == nullptr || legendKept(frame, keep, body_px, jump_px)) return {};
        // Its legend placed afresh between two steps: the next step's places where they hold,
        // one change there rather than one here and another at the next step (stick-2d 640x360
        // at 1.18 s listed its readouts under the balls for one frame, then by their arrows).
        const frame::FrameModel afresh = frame;
        frame = unplaced;
        const Step* after_next = k + 2 < steps.size() ? &steps[k + 2] : nullptr;
        const LabelSlots then = plannedAt(*next, after_next, 0.0, body_px, jump_px, keep_right);
        picture_.place(frame, &then, nullptr);
        if (!(onTheirWays(frame, then) && statesListed(frame, then) &&
              legendKept(frame, then, body_px, jump_px))) {
          frame = afresh;
        }
        return {};
      }
    }
  }
  // Someone off its way: the labels on free ways hold them, and one whose way runs into
  // something finds a place elsewhere. At their planned corners: keeping right edges here too
  // swapped ballistic-pendulum 640x360's m1 above its readout for one frame (2.29 s).
  frame = unplaced;
  LabelSlots keep = plannedAt(steps[k], next, share, body_px, jump_px, false);
  picture_.place(frame, &keep, nullptr);
  if (allPlaced(frame, keep) && statesListed(frame, keep)) return {};
  // One refused there (it has no place but theirs) looks for another while every label placed
  // on its way holds it; where it finds none it is listed in the legend. Placing them all
  // afresh moved labels that had their places, there and back (billiards-follow's ball 2 before
  // its impact).
  holdOnTheirWays(frame, keep);
  frame = unplaced;
  picture_.place(frame, &keep, nullptr);
  return farOffTheirWays(frame, keep, jump_px);
}

LabelSlots LabelTimeline::plannedAt(const Step& step, const Step* next, double share,
                                    const std::vector<std::vector<core::Vec2>>& body_px,
                                    double jump_px, bool keep_right_edges) {
  LabelSlots keep = wanting(step.slots, step.placed, [&](const LabelAt& planned) -> core::Vec2 {
    const core::Vec2 body =
        planned.panel < body_px.size() && planned.body < body_px[planned.panel].size()
            ? body_px[planned.panel][planned.body]
            : planned.body_px;
    const core::Vec2 carried = planned.shown_px + (body - planned.body_px);
    const LabelAt* then = next != nullptr ? findLabel(next->placed, planned) : nullptr;
    // Not placed at the next step (listed in its legend there): one that came to its step
    // standing stands on, as its way planned it, not carried off with its body between (ball 2
    // of air-drag-throw landing under m₂, standing at 1.367 s and listed at 1.4 s: carried, it
    // ran into something at 1.383 s and was placed 6 px off).
    if (then == nullptr) return planned.rides ? carried : planned.shown_px;
    // A jump in a 2D panel (its way found no glide) happens at once, not spread over the frames
    // between.
    const core::Vec2 then_carried = then->shown_px + (body - then->body_px);
    if (planned.two_d && std::min((then_carried - carried).norm(),
                                  (then->shown_px - planned.shown_px).norm()) > jump_px) {
      return share < 0.5 ? carried : then_carried;
    }
    // Riding with its body, it moves beyond it by its share of the way; standing, by its share.
    if (then->rides) {
      return carried +
             share * ((then->shown_px - then->body_px) - (planned.shown_px - planned.body_px));
    }
    return planned.shown_px + share * (then->shown_px - planned.shown_px);
  });
  // A label that comes between the two steps (its body set moving by an event in the shot)
  // stands where the next step has it, carried along by its body, not wherever is free.
  if (next != nullptr) appendComing(keep, *next, body_px);
  for (LabelSlot& slot : keep) {
    // A label listed first at the next step is listed where that step lists it.
    const LabelSlot* listed_then = next != nullptr ? findLabel(next->slots, slot) : nullptr;
    if (!slot.legend && listed_then != nullptr) slot.legend = listed_then->legend;
    slot.leaves_lines = kOnItsWayLines;
    // Free at both steps around it (as the shot's probes saw them): it holds its way.
    const LabelAt* planned = findLabel(step.placed, slot);
    const LabelAt* then = next != nullptr ? findLabel(next->placed, slot) : nullptr;
    slot.holds = listedInAWay(slot) ||
                 (planned != nullptr && planned->free && (then == nullptr || then->free));
    if (keep_right_edges && planned != nullptr && planned->two_d) {
      slot.planned_width_px = planned->size_px.x();
    }
  }
  return keep;
}

void LabelTimeline::appendComing(LabelSlots& keep, const Step& next,
                                 const std::vector<std::vector<core::Vec2>>& body_px) {
  for (const LabelSlot& slot : next.slots) {
    const LabelAt* then = findLabel(next.placed, slot);
    if (then == nullptr || findLabel(keep, slot) != nullptr) continue;
    const core::Vec2 body = slot.panel < body_px.size() && slot.body < body_px[slot.panel].size()
                                ? body_px[slot.panel][slot.body]
                                : then->body_px;
    keep.push_back(slot);
    keep.back().wanted_px = then->shown_px + (body - then->body_px);
  }
}

void LabelTimeline::holdOnTheirWays(const frame::FrameModel& frame, LabelSlots& keep) {
  const std::vector<LabelAt> placed = placedLabels(frame);
  for (LabelSlot& slot : keep) {
    const LabelAt* at = findLabel(placed, slot);
    slot.holds = at != nullptr && standsWanted(slot, *at);
  }
}

bool LabelTimeline::statesListed(const frame::FrameModel& frame, const LabelSlots& keep) {
  const std::vector<LabelAt> placed = placedLabels(frame);
  return std::all_of(keep.begin(), keep.end(), [&](const LabelSlot& slot) {
    if (!listedInAWay(slot) || findLabel(placed, slot) != nullptr) return true;
    if (slot.panel >= frame.panels.size()) return true;
    const auto& entries = frame.panels[slot.panel].legend.entries;
    return std::any_of(entries.begin(), entries.end(), [&](const auto& entry) {
      return entry.body == static_cast<int>(slot.body) && entry.mass == !slot.velocity &&
             !entry.text.empty();
    });
  });
}

bool LabelTimeline::allPlaced(const frame::FrameModel& frame, const LabelSlots& keep) {
  const std::vector<LabelAt> placed = placedLabels(frame);
  return std::all_of(keep.begin(), keep.end(), [&placed](const LabelSlot& slot) {
    return !slot.wanted_px || findLabel(placed, slot) != nullptr;
  });
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
    if (at == nullptr || !standsWanted(slot, *at)) return false;
  }
  return true;
}

LabelSlots LabelTimeline::farOffTheirWays(const frame::FrameModel& frame, const LabelSlots& keep,
                                          double jump_px) {
  const std::vector<LabelAt> placed = placedLabels(frame);
  LabelSlots far;
  for (const LabelSlot& slot : keep) {
    if (!slot.wanted_px || listedInAWay(slot)) continue;
    const LabelAt* at = findLabel(placed, slot);
    if (at == nullptr) {
      far.push_back(slot);
      continue;
    }
    if (offItsWayPx(slot, *at) > jump_px) far.push_back(slot);
  }
  return far;
}

}  // namespace collide::compose
