// SPDX-License-Identifier: MIT
// LabelTimeline's fades: a label changing places between its body and its legend fades out at
// the one and then in at the other (label_fades.hpp).
#include <algorithm>
#include <vector>

#include "compose/label_fades.hpp"
#include "compose/label_timeline.hpp"

namespace collide::compose {
namespace {

struct LabelKey {
  std::size_t panel = 0, body = 0;
  bool velocity = false;
};

// The labels `frame` shows, by their bodies or in their legends.
std::vector<LabelKey> labelsShown(const frame::FrameModel& frame) {
  std::vector<LabelKey> keys;
  const auto add = [&keys](std::size_t panel, std::size_t body, bool velocity) {
    if (findLabel(keys, LabelKey{panel, body, velocity}) == nullptr) {
      keys.push_back({panel, body, velocity});
    }
  };
  for (std::size_t p = 0; p < frame.panels.size(); ++p) {
    const frame::PanelModel& panel = frame.panels[p];
    for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
      if (panel.bodies[i].label_at) add(p, i, false);
      if (panel.bodies[i].velocity_label_at) add(p, i, true);
    }
    for (const frame::ReadoutLegend::Entry& entry : panel.legend.entries) {
      add(p, static_cast<std::size_t>(std::max(0, entry.body)), !entry.mass);
    }
  }
  return keys;
}

// Where `frame` shows the label of `key`.
LabelPlace shownAt(const frame::FrameModel& frame, const LabelKey& key) {
  const frame::BodyModel& body = frame.panels[key.panel].bodies[key.body];
  if (key.velocity ? body.velocity_label_at.has_value() : body.label_at.has_value()) {
    return LabelPlace::kBody;
  }
  return LabelPlace::kLegend;
}

}  // namespace

void LabelTimeline::place(frame::FrameModel& frame, double t_s) {
  placeOnWays(frame, t_s);
  // The steps from two fades before t_s to two after: far enough to see whether a run at one
  // place next to a change lasts a fade.
  const std::size_t first = shotAt(std::max(0.0, t_s - 2.0 * kFade_s));
  const std::size_t last = shotAt(std::min(duration_s_, t_s + 2.0 * kFade_s));
  for (const LabelKey& key : labelsShown(frame)) {
    if (key.panel >= frame.panels.size() || key.body >= frame.panels[key.panel].bodies.size()) {
      continue;
    }
    std::vector<PlaceAtStep> places;
    for (std::size_t shot = first; shot <= last; ++shot) {
      const std::vector<Step>& steps = walkOf(shot);
      for (std::size_t k = 0; k < steps.size(); ++k) {
        const LabelPlace at = findLabel(steps[k].placed, key) != nullptr ? LabelPlace::kBody
                              : listedAt(steps, k, key)                  ? LabelPlace::kLegend
                                                                         : LabelPlace::kNowhere;
        places.push_back({steps[k].t_s, at, k == 0 && shot > 0});
      }
    }
    const double opacity = placeOpacity(places, first == 0, shownAt(frame, key), t_s);
    if (opacity < 1.0) {
      fadeLabel(frame, key.panel, key.body, key.velocity, static_cast<float>(opacity));
    }
  }
  fadeNumbers(frame);
}

}  // namespace collide::compose
