// SPDX-License-Identifier: MIT
// The layout over time's 2D labels whose ways still jump, listed in their legends for the shot.
#include <algorithm>
#include <optional>
#include <utility>

#include "compose/label_timeline.hpp"

namespace collide::compose {

namespace {

// The pinned legends listJumping tries: more would walk the shot again for each.
constexpr std::size_t kMostPinnedLegends = 3;
// A legend line that moved less than this since the step before stands where it stood.
constexpr double kSamePlacePx = 0.5;

}  // namespace

std::vector<LabelSlots> LabelTimeline::legendPlaces(const std::vector<Step>& steps,
                                                    const LabelSlots& listed, std::size_t most) {
  const auto same = [](const LabelSlots& a, const LabelSlots& b) {
    for (std::size_t n = 0; n < a.size(); ++n) {
      if ((a[n].legend->px - b[n].legend->px).norm() > kSamePlacePx) return false;
    }
    return true;
  };
  std::vector<LabelSlots> places;
  std::optional<LabelSlots> last;
  for (std::size_t k = 0; k < steps.size() && places.size() < most; ++k) {
    LabelSlots place = listed;
    bool whole = true;
    for (LabelSlot& slot : place) {
      const std::optional<LabelSlot> at = listedAt(steps, k, slot);
      whole = whole && at && at->legend;
      if (whole) slot.legend = at->legend;
    }
    if (!whole || (last && same(*last, place))) continue;
    // Its first place is where the listing walked it from: pinned there it walks the same.
    if (last) places.push_back(place);
    last = std::move(place);
  }
  return places;
}

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
  const auto walkListing = [&](const LabelSlots& listing) {
    std::vector<Step> walked = walkFrom(start_s, end_s, plan, ends_at_event, &listing);
    if (after != nullptr && after_unfixed) after->probe.restore(*after_unfixed);
    planWays(walked, before, after);
    return walked;
  };
  std::vector<Step> again = walkListing(jumping.first);
  std::size_t jumps = jumpingWays(again).second;
  // Where the legend moves during the shot (a ball flies through it), the shot again with it
  // pinned where it stood after each of its moves, kept where that jumps less. Not where the
  // listing jumps more than twice as often as the ways did: the balls cross its every place.
  const bool pin = jumps <= 2 * jumping.second;
  for (const LabelSlots& pinned :
       pin ? legendPlaces(again, jumping.first, kMostPinnedLegends) : std::vector<LabelSlots>{}) {
    if (jumps == 0) break;
    std::vector<Step> walked = walkListing(pinned);
    const std::size_t pinned_jumps = jumpingWays(walked).second;
    if (walked.size() != again.size() || pinned_jumps >= jumps) continue;
    again = std::move(walked);
    jumps = pinned_jumps;
  }
  if (again.size() != steps.size() || jumps >= jumping.second) return;
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
