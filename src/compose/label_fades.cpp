// SPDX-License-Identifier: MIT
#include "compose/label_fades.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "compose/label_timeline.hpp"

namespace collide::compose {
namespace {

// Where a frame shows a label: by its body or in its legend, and which of its places by its body.
struct Where {
  LabelPlace at = LabelPlace::kNowhere;
  int place = 0;
  bool hidden = false;
};

bool isAt(const PlaceAtStep& step, const Where& shown) {
  return step.at == shown.at && step.place == shown.place && step.hidden == shown.hidden;
}

bool isOther(const PlaceAtStep& step, const Where& shown) {
  return step.at != LabelPlace::kNowhere && !isAt(step, shown);
}

// The opacity within the run of steps first..last at `shown`, at playback_s (fades and stays
// are as long as a video shows them: slow motion stretches them in simulated time).
double inRun(const std::vector<PlaceAtStep>& steps, std::size_t first, std::size_t last,
             bool from_start, const Where& shown, double playback_s) {
  if (shown.hidden) return 0.0;
  const bool comes = first > 0 && isOther(steps[first - 1], shown);
  const bool goes = last + 1 < steps.size() && isOther(steps[last + 1], shown);
  const double first_s = steps[first].playback_s, last_s = steps[last].playback_s;
  if (!comes && !goes) {
    // Shown nowhere before and after it for less than a fade (a readout at an event whose body
    // stops a step later): a blink that nobody reads, not seen.
    const bool blinks =
        first > 0 && last + 1 < steps.size() && steps[last + 1].playback_s - first_s < kFade_s;
    return blinks ? 0.0 : 1.0;
  }
  // A run that starts whole (where it is shown nowhere before, at the video's start, or reached
  // at an event) and fades out, or fades in and vanishes whole (shown nowhere after): where the
  // fade would not be over before it vanishes, or begin only after it appeared, it would come
  // or go half seen.
  const bool fades_in = comes && !steps[first].shot_start;
  const bool appears = first > 0 ? !fades_in : from_start;
  const bool vanishes = last + 1 < steps.size() && !goes;
  if (appears && goes && last_s - kFadeGap_s - first_s < kFade_s) return 0.0;
  if (fades_in && vanishes && steps[last + 1].playback_s - kFadeGap_s - first_s < kFade_s) {
    return 0.0;
  }
  double opacity = 1.0;
  // Reached at an event it stands there from the event on (faded out before it at its old one).
  if (fades_in) opacity = std::min(opacity, (playback_s - first_s) / kFade_s);
  // Gone a frame before its last step: no frame shows it at one place and the next at the other.
  if (goes) opacity = std::min(opacity, (last_s - kFadeGap_s - playback_s) / kFade_s);
  return std::clamp(opacity, 0.0, 1.0);
}

}  // namespace

double placeOpacity(const std::vector<PlaceAtStep>& steps, bool from_start, LabelPlace shown,
                    double t_s, double playback_s) {
  if (steps.empty()) return 1.0;
  // The last step at or before t_s (a frame at a step's instant may fall a rounding error before
  // it), but not an event's after it: that frame still shows the shot before (shotOf).
  const auto after =
      std::upper_bound(steps.begin(), steps.end(), t_s + kStepRounding_s,
                       [](double t, const PlaceAtStep& step) { return t < step.t_s; });
  if (after == steps.begin()) return 1.0;
  auto k = static_cast<std::size_t>(after - steps.begin()) - 1;
  if (steps[k].shot_start && t_s < steps[k].t_s) {
    if (k == 0) return 1.0;
    --k;
  }
  const auto runFrom = [&](std::size_t at_k, double when_s) {
    const Where where{steps[at_k].at, steps[at_k].place, steps[at_k].hidden};
    std::size_t first = at_k, last = at_k;
    while (first > 0 && isAt(steps[first - 1], where)) --first;
    while (last + 1 < steps.size() && isAt(steps[last + 1], where)) ++last;
    return inRun(steps, first, last, from_start, where, when_s);
  };
  if (steps[k].at != shown) {
    // Between a step at the other place and the next at this one (the frame took the next
    // step's places early): not seen until its fade in starts. After one where it is shown
    // nowhere: as the next step's run starts (not seen where that run is not).
    const bool early = k + 1 < steps.size() && steps[k + 1].at == shown && !steps[k + 1].shot_start;
    if (early) {
      return steps[k].at != LabelPlace::kNowhere ? 0.0 : runFrom(k + 1, steps[k + 1].playback_s);
    }
    // Where the frame could not place it as planned (the plan has it at its other place): seen
    // only where the plan shows it whole, not where the plan hides it or fades it out (a fade
    // goes on where it was planned, not at a place it takes for a frame or two).
    return steps[k].at == LabelPlace::kNowhere || runFrom(k, playback_s) >= 1.0 ? 1.0 : 0.0;
  }
  return runFrom(k, playback_s);
}

void hideShortStays(std::vector<PlaceAtStep>& places, bool from_start, bool to_end) {
  // The runs at one place (by its body or in its legend): [first, last] index pairs in order.
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  for (std::size_t k = 0; k < places.size(); ++k) {
    if (places[k].at == LabelPlace::kNowhere) continue;
    // A stay is measured within its shot (the steps seen hold every shot whole), so that every
    // frame that sees a jump judges it alike.
    const bool same = !runs.empty() && runs.back().second + 1 == k && !places[k].shot_start &&
                      places[runs.back().second].at == places[k].at &&
                      places[runs.back().second].place == places[k].place;
    if (same) {
      runs.back().second = k;
    } else {
      runs.push_back({k, k});
    }
  }
  // Long enough to be read between its fades; one at the video's start or end has one fade.
  const auto tooShort = [&](const std::pair<std::size_t, std::size_t>& run) {
    const double stay_s = places[run.second].playback_s - places[run.first].playback_s;
    const bool one_fade =
        (from_start && run.first == 0) || (to_end && run.second + 1 == places.size());
    return stay_s < (one_fade ? kShortestStay_s - kFade_s : kShortestStay_s);
  };
  // A jump within a shot: from one place to another of the same kind at the next step, as
  // planned (a stay the frames take off the plan is hidden where short; the planned stay beside
  // it fades out or in there as at any other change, however short).
  const auto jumps = [&](std::size_t r) {
    const PlaceAtStep &before = places[runs[r - 1].second], &after = places[runs[r].first];
    return runs[r - 1].second + 1 == runs[r].first && before.at == after.at && !after.shot_start &&
           !before.off_plan && !after.off_plan;
  };
  std::vector<bool> hide(runs.size(), false);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    if (places[runs[r].first].off_plan && tooShort(runs[r])) hide[r] = true;
  }
  for (std::size_t r = 1; r < runs.size(); ++r) {
    if (!jumps(r)) continue;
    if (tooShort(runs[r - 1])) hide[r - 1] = true;
    if (tooShort(runs[r])) hide[r] = true;
  }
  for (std::size_t r = 0; r < runs.size(); ++r) {
    if (!hide[r]) continue;
    for (std::size_t k = runs[r].first; k <= runs[r].second; ++k) places[k].hidden = true;
  }
}

void fadeLabel(frame::FrameModel& frame, std::size_t panel, std::size_t body, bool velocity,
               float opacity) {
  if (panel >= frame.panels.size()) return;
  frame::PanelModel& shown = frame.panels[panel];
  if (body < shown.bodies.size()) {
    frame::BodyModel& at_body = shown.bodies[body];
    std::optional<frame::PlacedText>& at = velocity ? at_body.velocity_label_at : at_body.label_at;
    if (at) at->opacity = opacity;
  }
  for (frame::ReadoutLegend::Entry& entry : shown.legend.entries) {
    if (entry.body == static_cast<int>(body) && entry.mass == !velocity) entry.opacity = opacity;
  }
}

void fadeNumbers(frame::FrameModel& frame) {
  for (frame::PanelModel& panel : frame.panels) {
    for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
      float most = -1.0f;
      for (const frame::ReadoutLegend::Entry& entry : panel.legend.entries) {
        if (entry.body == static_cast<int>(i)) most = std::max(most, entry.opacity);
      }
      if (most < 0.0f) continue;
      frame::BodyModel& body = panel.bodies[i];
      body.tag_opacity = most;
      if (body.tag_at) body.tag_at->opacity = most;
    }
  }
}

void showWhole(frame::FrameModel& frame) {
  for (frame::PanelModel& panel : frame.panels) {
    for (frame::BodyModel& body : panel.bodies) {
      for (auto* at : {&body.label_at, &body.velocity_label_at, &body.tag_at, &body.arrow_tag_at}) {
        if (*at) (*at)->opacity = 1.0f;
      }
      body.tag_opacity = 1.0f;
    }
    for (frame::ReadoutLegend::Entry& entry : panel.legend.entries) entry.opacity = 1.0f;
  }
}

}  // namespace collide::compose
