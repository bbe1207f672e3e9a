// SPDX-License-Identifier: MIT
#include "compose/label_probe.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "compose/dimension_placement.hpp"
#include "compose/label_cost.hpp"
#include "compose/label_scene.hpp"
#include "frame/layout.hpp"

namespace collide::compose {

struct LabelProbe::Panel {
  LabelScene scene;
  std::vector<Label> labels;
  std::vector<std::pair<Box, bool>> fixed;  // the labels fixed so far, and whether readouts
};

namespace {

// The panel's labels with their candidate places, as label_placement.cpp finds them.
std::vector<Label> labelsOf(frame::PanelModel& panel, const LabelScene& scene,
                            const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                            text::TextMeasure& metrics) {
  const double size = layout.text_px;
  const double line = metrics.ascender(size) + metrics.descender(size);
  std::vector<Label> labels;
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    for (const bool velocity : {true, false}) {
      std::string& text = velocity ? panel.bodies[i].velocity_label : panel.bodies[i].label;
      if (text.empty()) continue;
      Label label{i, velocity, &text, {metrics.width(text, size), line}, {}, {}, {}, -1};
      addCandidates(label, panel, scene, layout, to_px);
      labels.push_back(std::move(label));
    }
  }
  return labels;
}

// What a place `box` of `label` costs before the other labels are looked at, and whether it
// needs a leader: what candidate `candidate` does (nothing for a place between candidates), with
// a leader where that needs one or where it stands farther from its body than a line and a half.
// Kept apart from a Label of its own (no vectors to allocate: probes ask it for every candidate
// and standing place of every step).
struct Alone {
  double base_cost = 0.0;
  bool needs_leader = false;
};
Alone alone(const Label& label, const Box& box, int candidate, const LabelScene& scene) {
  Alone one;
  if (candidate >= 0) {
    const auto k = static_cast<std::size_t>(candidate);
    one.base_cost = label.base_cost[k];
    one.needs_leader = label.needs_leader[k];
  }
  const Box& body = scene.obstacles.bodies()[label.body].bounds;
  const double apart_x = std::max({0.0, body.x0 - box.x1, box.x0 - body.x1});
  const double apart_y = std::max({0.0, body.y0 - box.y1, box.y0 - body.y1});
  if (std::hypot(apart_x, apart_y) > 1.5 * label.size.y()) one.needs_leader = true;
  return one;
}

}  // namespace

LabelProbe::LabelProbe(frame::FrameModel frame, int width_px, int height_px,
                       text::TextMeasure& metrics, double text_floor_px)
    : frame_(std::move(frame)) {
  for (frame::PanelModel& panel : frame_.panels) {
    panel.placed_label_lines = -1;
    panel.print_values_room = 0;
  }
  const frame::FrameLayout layout = frame::layoutFrame(
      frame_, width_px, height_px, text_floor_px,
      [&metrics](std::string_view text, double px) { return metrics.width(text, px); });
  for (std::size_t p = 0; p < frame_.panels.size() && p < layout.panels.size(); ++p) {
    frame::PanelModel& panel = frame_.panels[p];
    const frame::PanelLayout& where = layout.panels[p];
    const frame::PixelRect area = frame::worldArea(panel, where, layout);
    const frame::WorldToPixel to_px = frame::fitView(panel.view, area);
    auto probe = std::make_unique<Panel>(
        Panel{describePanel(panel, where, layout, to_px, area,
                            metrics.ascender(layout.small_px) + metrics.descender(layout.small_px)),
              {},
              {}});
    placeDimensionTexts(panel, layout, to_px, metrics, probe->scene.obstacles);
    probe->labels = labelsOf(panel, probe->scene, layout, to_px, metrics);
    panels_.push_back(std::move(probe));
  }
}

LabelProbe::~LabelProbe() = default;
LabelProbe::LabelProbe(LabelProbe&&) noexcept = default;
LabelProbe& LabelProbe::operator=(LabelProbe&&) noexcept = default;

const Label* LabelProbe::label(std::size_t panel, std::size_t body, bool velocity) const {
  if (panel >= panels_.size()) return nullptr;
  for (const Label& label : panels_[panel]->labels) {
    if (label.body == body && label.velocity == velocity) return &label;
  }
  return nullptr;
}

bool LabelProbe::needsLeader(std::size_t panel, const Label& label, const Box& box,
                             int candidate) const {
  return alone(label, box, candidate, panels_[panel]->scene).needs_leader;
}

double LabelProbe::cost(std::size_t panel, const Label& label, const Box& box,
                        int candidate) const {
  const Panel& probe = *panels_[panel];
  const Alone one = alone(label, box, candidate, probe.scene);
  std::optional<Leader> leader;
  if (one.needs_leader) leader = leaderOf(label, box, probe.scene);
  double total = costAlone(label, box, one.base_cost, leader, probe.scene);
  for (const auto& [other, readout] : probe.fixed) {
    if (readsAsOneLine(box, other, probe.scene.em_px)) total += kOneLine;
    // Two mass labels on one baseline stand well apart, as placement keeps them.
    if (!label.velocity && !readout) {
      total += kKeptShortOfApartPerPx * shortOfApart(box, other, probe.scene.em_px);
    }
  }
  return total;
}

void LabelProbe::fix(std::size_t panel, const Label& label, const Box& box, int candidate) {
  Panel& probe = *panels_[panel];
  const Alone one = alone(label, box, candidate, probe.scene);
  probe.scene.obstacles.addText(box);
  if (one.needs_leader) {
    const Leader leader = leaderOf(label, box, probe.scene);
    probe.scene.obstacles.addLeader(leader.from, leader.to);
  }
  probe.fixed.emplace_back(box, label.velocity);
}

LabelProbe::Fixed LabelProbe::fixed() const {
  Fixed fixed;
  for (const std::unique_ptr<Panel>& panel : panels_) {
    fixed.panels_.emplace_back(panel->scene.obstacles, panel->fixed);
  }
  return fixed;
}

void LabelProbe::restore(const Fixed& fixed) {
  for (std::size_t p = 0; p < panels_.size() && p < fixed.panels_.size(); ++p) {
    panels_[p]->scene.obstacles = fixed.panels_[p].first;
    panels_[p]->fixed = fixed.panels_[p].second;
  }
}

}  // namespace collide::compose
