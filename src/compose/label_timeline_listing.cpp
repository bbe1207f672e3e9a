// SPDX-License-Identifier: MIT
// The layout over time's 2D labels whose ways still jump, listed in their legends for the shot.
#include <algorithm>
#include <optional>
#include <utility>

#include "compose/label_timeline.hpp"

namespace collide::compose {

std::pair<LabelSlots, std::size_t> LabelTimeline::jumpingWays(
    const std::vector<Step>& steps) const {
  std::pair<LabelSlots, std::size_t> jumping{{}, 0};
  for (std::size_t k = 1; k < steps.size(); ++k) {
    // As plannedAt shows the way: beyond its body by more than jump_px from one step to the next.
    const double jump_px = jumpPxAt(steps[k].t_s, true);
    for (const LabelAt& now : steps[k].placed) {
      const LabelAt* was = findLabel(steps[k - 1].placed, now);
      if (!now.two_d || was == nullptr) continue;
      if (now.movedFrom(*was) <= jump_px) continue;
      ++jumping.second;
      if (findLabel(jumping.first, now) != nullptr) continue;
      LabelSlot slot;
      slot.panel = now.panel;
      slot.body = now.body;
      slot.velocity = now.velocity;
      jumping.first.push_back(slot);
    }
    // A legend's lines jump too where they move farther than that (beyond the body they ride
    // with): counted, so that a plan listing a label where its legend moves is not taken.
    for (const LabelSlot& slot : steps[k].slots) {
      const std::optional<LabelSlot> now = listedAt(steps, k, slot);
      const std::optional<LabelSlot> was = listedAt(steps, k - 1, slot);
      if (!now || !was) continue;
      const LegendLine &then = *was->legend, &line = *now->legend;
      const core::Vec2 carried =
          then.by >= 0 && then.by == line.by ? then.px + (line.by_px - then.by_px) : then.px;
      if ((line.px - carried).norm() > jump_px) ++jumping.second;
    }
  }
  return jumping;
}

void LabelTimeline::listJumping(std::vector<Step>& steps, double start_s, double end_s,
                                bool ends_at_event, const LabelSlots& plan, const Step* before,
                                AfterEnd* after,
                                const std::optional<LabelProbe::Fixed>& after_unfixed) {
  // A glide slow enough not to jump (2 px a frame) takes seconds to change sides by a ball in
  // flight: a 2D label whose way still jumps (ballistic-pendulum's "m1 + m2" by its swinging
  // block has no place that lasts the swing) is listed in its legend for the shot instead, its
  // body tagged with its number, where that leaves the shot's ways fewer jumps.
  const std::pair<LabelSlots, std::size_t> jumping = jumpingWays(steps);
  if (jumping.first.empty()) return;
  std::vector<Step> again = walkFrom(start_s, end_s, plan, ends_at_event, &jumping.first);
  if (after != nullptr && after_unfixed) after->probe.restore(*after_unfixed);
  planWays(again, before, after);
  if (again.size() != steps.size() || jumpingWays(again).second >= jumping.second) return;
  // Only where each is listed throughout and every label listed before stays listed: a legend
  // with no room for it, or rearranged without another of its lines, moves in the frames.
  for (std::size_t k = 0; k < steps.size(); ++k) {
    for (const LabelSlot& slot : again[k].slots) {
      if (findLabel(jumping.first, slot) != nullptr && !listedAt(again, k, slot)) return;
    }
    for (const LabelSlot& slot : steps[k].slots) {
      if (listedAt(steps, k, slot) && !listedAt(again, k, slot)) return;
    }
  }
  steps = std::move(again);
}

}  // namespace collide::compose
