// SPDX-License-Identifier: MIT
#include "compose/label_fades.hpp"

#include <algorithm>
#include <cmath>

#include "compose/label_timeline.hpp"

namespace collide::compose {
namespace {

// Where a frame shows a label: by its body or in its legend, and which of its places by its body.
struct Where {
  LabelPlace at = LabelPlace::kNowhere;
  int place = 0;
};

bool isAt(const PlaceAtStep& step, const Where& shown) {
  return step.at == shown.at && step.place == shown.place;
}

bool isOther(const PlaceAtStep& step, const Where& shown) {
  return step.at != LabelPlace::kNowhere && !isAt(step, shown);
}

// The opacity within the run of steps first..last at `shown`, at t_s.
double inRun(const std::vector<PlaceAtStep>& steps, std::size_t first, std::size_t last,
             bool from_start, const Where& shown, double t_s) {
  const bool comes = first > 0 && isOther(steps[first - 1], shown);
  const bool goes = last + 1 < steps.size() && isOther(steps[last + 1], shown);
  if (!comes && !goes) return 1.0;
  // A run that starts whole (where it is shown nowhere before, at the video's start, or reached
  // at an event) and fades out, or fades in and vanishes whole (shown nowhere after): where the
  // fade would not be over before it vanishes, or begin only after it appeared, it would come
  // or go half seen.
  const bool fades_in = comes && !steps[first].shot_start;
  const bool appears = first > 0 ? !fades_in : from_start;
  const bool vanishes = last + 1 < steps.size() && !goes;
  if (appears && goes && steps[last].t_s - kFadeGap_s - steps[first].t_s < kFade_s) return 0.0;
  if (fades_in && vanishes && steps[last + 1].t_s - kFadeGap_s - steps[first].t_s < kFade_s) {
    return 0.0;
  }
  double opacity = 1.0;
  // Reached at an event it stands there from the event on (faded out before it at its old one).
  if (fades_in) opacity = std::min(opacity, (t_s - steps[first].t_s) / kFade_s);
  // Gone a frame before its last step: no frame shows it at one place and the next at the other.
  if (goes) opacity = std::min(opacity, (steps[last].t_s - kFadeGap_s - t_s) / kFade_s);
  return std::clamp(opacity, 0.0, 1.0);
}

}  // namespace

double placeOpacity(const std::vector<PlaceAtStep>& steps, bool from_start, LabelPlace shown,
                    double t_s) {
  if (steps.empty()) return 1.0;
  // The last step at or before t_s.
  const auto after =
      std::upper_bound(steps.begin(), steps.end(), t_s + kStepRounding_s,
                       [](double t, const PlaceAtStep& step) { return t < step.t_s; });
  if (after == steps.begin()) return 1.0;
  const auto k = static_cast<std::size_t>(after - steps.begin()) - 1;
  if (steps[k].at != shown) {
    // Between a step at the other place and the next at this one (the frame took the next
    // step's places early): not seen until its fade in starts.
    const bool early = k + 1 < steps.size() && steps[k + 1].at == shown && !steps[k + 1].shot_start;
    return early && steps[k].at != LabelPlace::kNowhere ? 0.0 : 1.0;
  }
  const Where where{shown, steps[k].place};
  std::size_t first = k, last = k;
  while (first > 0 && isAt(steps[first - 1], where)) --first;
  while (last + 1 < steps.size() && isAt(steps[last + 1], where)) ++last;
  return inRun(steps, first, last, from_start, where, t_s);
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
