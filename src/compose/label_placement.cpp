#include "compose/label_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "compose/dimension_placement.hpp"
#include "compose/label_arrangement.hpp"
#include "compose/label_candidates.hpp"
#include "compose/label_cost.hpp"
#include "compose/label_legend.hpp"
#include "compose/label_scene.hpp"
#include "compose/placement_obstacles.hpp"
#include "compose/tag_placement.hpp"
#include "frame/layout.hpp"
#include "frame/mark_sizes.hpp"

namespace collide::compose {
namespace {

// How many of a panel's labels it states, by their bodies or in its legend (a wrapped one's two
// lines once).
int statedTexts(const frame::PanelModel& panel) {
  std::vector<std::pair<int, bool>> stated;
  for (const frame::ReadoutLegend::Entry& entry : panel.legend.entries) {
    const std::pair<int, bool> what{entry.body, entry.mass};
    if (std::find(stated.begin(), stated.end(), what) == stated.end()) stated.push_back(what);
  }
  int placed = 0;
  for (const frame::BodyModel& body : panel.bodies) {
    placed += (body.label_at ? 1 : 0) + (body.velocity_label_at ? 1 : 0);
  }
  return placed + static_cast<int>(stated.size());
}

// A panel's plan: the slots to keep (none: place afresh) and the slots its placement chose.
struct PanelPlan {
  const LabelSlots* keep = nullptr;
  std::size_t panel = 0;
  LabelSlots chosen;
};

// The slot `plan` keeps for `label`, if any.
const LabelSlot* keptSlot(const Label& label, const PanelPlan& plan) {
  if (plan.keep == nullptr) return nullptr;
  for (const LabelSlot& slot : *plan.keep) {
    if (slot.panel == plan.panel && slot.body == label.body && slot.velocity == label.velocity) {
      return &slot;
    }
  }
  return nullptr;
}

// The candidate of `label` whose top left corner is nearest `at_px`.
std::size_t nearestCandidate(const Label& label, const core::Vec2& at_px) {
  std::size_t nearest = 0;
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < label.candidates.size(); ++k) {
    const double apart =
        std::hypot(label.candidates[k].x0 - at_px.x(), label.candidates[k].y0 - at_px.y());
    if (apart < least) {
      least = apart;
      nearest = k;
    }
  }
  return nearest;
}

}  // namespace

core::Vec2 wantedCorner(const LabelSlot& slot, const core::Vec2& size_px, double body_x0_px) {
  core::Vec2 corner = slot.wanted_px.value_or(core::Vec2{0.0, 0.0});
  const double narrower_px = slot.planned_width_px - size_px.x();
  if (narrower_px > 0.0 && corner.x() + slot.planned_width_px <= body_x0_px) {
    corner.x() += narrower_px;
  }
  return corner;
}

namespace {

// Makes every candidate but the one `plan` keeps for `label` cost its leaves_lines more (its
// kept slot half that), and adds the place it wants, costing what its slot costs.
void preferKeptSlot(Label& label, const PanelPlan& plan, const LabelScene& scene) {
  const LabelSlot* slot = keptSlot(label, plan);
  if (slot != nullptr) {
    label.wanted_legend = slot->legend;
    label.listed_before = slot->candidate < 0 && slot->legend.has_value();
  }
  // Listed where the layout over time lists it (LabelSlot::holds): by its body it would push a
  // label off its way (air-drag-throw's m₂ leaving the legend a frame before its way starts put
  // m₁ in the legend and elsewhere, there and back).
  // So is one it lists for a whole shot with no line yet (LabelTimeline::listJumping): a new
  // line where the legend has room.
  if (slot != nullptr && slot->candidate < 0 && slot->holds && (slot->legend || !slot->wanted_px)) {
    for (double& cost : label.base_cost) cost += kHard;
    return;
  }
  if (slot == nullptr || slot->candidate < 0 || label.candidates.empty()) return;
  // Its slot names a place of its kind only while it has as many candidates; where that changed
  // (an arrow grew past its body's edge between two steps of the layout over time), a label
  // asked to stand somewhere keeps the candidate nearest that place as its slot.
  std::size_t kept = static_cast<std::size_t>(slot->candidate);
  if (slot->candidates != label.candidates.size()) {
    if (!slot->wanted_px) return;
    kept = nearestCandidate(label, *slot->wanted_px);
  }
  label.kept = static_cast<int>(kept);
  // Where it stands costs what its slot costs: a label kept far out returns where that gains
  // more than that.
  const double kept_cost = label.base_cost[kept];
  // One hung on a leader keeps no place: it returns by its body as soon as there is room; but
  // one asked to stand where the layout over time planned its way stands there.
  const double leaves =
      label.needs_leader[kept] && !slot->wanted_px ? 0.0 : slot->leaves_lines * label.size.y();
  // One that holds a free way (LabelSlot::holds) leaves it only where it runs into something.
  const double held = slot->holds && slot->wanted_px ? kHard : 0.0;
  for (std::size_t k = 0; k < label.base_cost.size(); ++k) {
    label.base_cost[k] += (k == kept ? 0.5 * leaves : leaves) + held;
  }
  if (!slot->wanted_px) return;
  const Box& body = scene.obstacles.bodies()[label.body].bounds;
  const core::Vec2 at = wantedCorner(*slot, label.size, body.x0);
  const Box box{at.x(), at.y(), at.x() + label.size.x(), at.y() + label.size.y()};
  // Farther from its body than a line and a half (gliding past it): a leader shows whose it is.
  const double apart_x = std::max({0.0, body.x0 - box.x1, box.x0 - body.x1});
  const double apart_y = std::max({0.0, body.y0 - box.y1, box.y0 - body.y1});
  label.candidates.push_back(box);
  label.base_cost.push_back(kept_cost);
  label.needs_leader.push_back(label.needs_leader[kept] ||
                               std::hypot(apart_x, apart_y) > 1.5 * label.size.y());
  label.wanted = true;
}

// The slots the labels took: a label at its wanted place keeps its slot.
LabelSlots slotsOf(const std::vector<Label>& labels, std::size_t panel) {
  LabelSlots slots;
  for (const Label& label : labels) {
    const std::size_t own = label.candidates.size() - (label.wanted ? 1 : 0);
    const bool at_wanted = label.wanted && label.chosen == static_cast<int>(own);
    LabelSlot slot{panel,
                   label.body,
                   label.velocity,
                   at_wanted ? label.kept : label.chosen,
                   own,
                   kLeavesItsSlotLines,
                   {}};
    // Where it is listed now, else where it was: it returns there if it is listed again.
    slot.legend = label.legend ? label.legend : label.wanted_legend;
    slots.push_back(slot);
  }
  return slots;
}

// Whether a panel's texts keep the frame's margin (the title's, from every edge: label_scene.cpp).
enum class Margin {
  kKeep,
  // Placed again in the margin where keeping it loses a value (a long translation in a small
  // frame, a block by the frame's edge): a label near the edge reads worse than one clear of it,
  // but better than none.
  kKeepUnlessLost,
  kUse,
};

// A frame placed before (at another size) gets its legend's texts back by their bodies.
void takeBackLegend(frame::PanelModel& panel) {
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    frame::BodyModel& body = panel.bodies[i];
    body.label = frame::statedLabel(panel, i, true);
    body.velocity_label = frame::statedLabel(panel, i, false);
  }
  panel.legend = {};
}

// The panel's labels with their candidate places, none placed yet, in the order the greedy pass
// places them: fastest bodies' readouts first (their arrows leave the least room), then masses.
std::vector<Label> panelLabels(const PanelText& text, const LabelScene& scene,
                               const frame::WorldToPixel& to_px, const PanelPlan& plan) {
  frame::PanelModel& panel = text.panel;
  std::vector<Label> labels;
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    frame::BodyModel& body = panel.bodies[i];
    body.label_at.reset();
    body.velocity_label_at.reset();
    body.tag_at.reset();
    body.arrow_tag_at.reset();
    for (bool velocity : {true, false}) {
      std::string& label_text = velocity ? body.velocity_label : body.label;
      if (label_text.empty()) continue;
      Label label{
          i,  velocity, &label_text, {text.metrics.width(label_text, text.size_px), text.line_px},
          {}, {},       {},          -1};
      addCandidates(label, panel, scene, text.layout, to_px);
      preferKeptSlot(label, plan, scene);
      labels.push_back(std::move(label));
    }
  }
  std::stable_sort(labels.begin(), labels.end(), [&](const Label& a, const Label& b) {
    if (a.velocity != b.velocity) return a.velocity;
    return panel.bodies[a.body].velocity_mps.norm() > panel.bodies[b.body].velocity_mps.norm();
  });
  return labels;
}

// Labels that found no free place give way (chosen -1); whether one of them is a readout by its
// arrow (`readout_gives_way`).
std::vector<bool> labelsGivingWay(std::vector<Label>& labels, const LabelScene& scene,
                                  LabelArrangement& arrangement, bool& readout_gives_way) {
  std::vector<bool> gives_way(labels.size(), false);
  readout_gives_way = false;
  for (std::size_t k = 0; k < labels.size(); ++k) {
    Label& label = labels[k];
    if (arrangement.fits(label)) continue;
    gives_way[k] = true;
    readout_gives_way = readout_gives_way || (label.velocity && scene.arrows[label.body]);
  }
  for (std::size_t k = 0; k < labels.size(); ++k) {
    if (gives_way[k]) labels[k].chosen = -1;
  }
  return gives_way;
}

// The readouts by arrows that the frame before listed in a legend and that found room by their
// arrows now: they stay listed where the legend keeps its place, or rides on with its body.
// Along a track only where the legend stays (a label gives way to it): readouts that leave the
// legend for their arrows at one event and come back at the next move the lines left in it
// (air-track's m₂ at 7.75 s, pi-blocks' m₁ at 2.6 s), and a legend no label needs goes. In a 2D
// panel a legend no label needs stays too: a ball in flight finds room by its turning arrow for
// a while and loses it again, its readout jumping between the legend and the ball each time
// (ballistic-pendulum's swing, stick-2d's flight).
std::vector<bool> readoutsStayingListed(const std::vector<Label>& labels, const LabelScene& scene,
                                        const std::vector<bool>& gives_way, bool two_d) {
  std::vector<bool> staying(labels.size(), false);
  const bool legend_stays =
      two_d || std::find(gives_way.begin(), gives_way.end(), true) != gives_way.end();
  for (std::size_t k = 0; k < labels.size() && legend_stays; ++k) {
    const Label& label = labels[k];
    staying[k] = !gives_way[k] && label.velocity && scene.arrows[label.body] &&
                 label.listed_before && label.wanted_legend;
  }
  return staying;
}

// The box of a legend's line of text.
Box legendBox(const frame::ReadoutLegend::Entry& entry, const PanelText& text) {
  const core::Vec2& at = entry.top_left_px;
  return {at.x(), at.y(), at.x() + text.metrics.width(entry.text, text.size_px),
          at.y() + text.line_px};
}

// Whether two labels placed by their bodies read as one line.
bool twoOnOneLine(const std::vector<Label>& labels, double em_px) {
  bool on_one_line = false;
  for (const Label& a : labels) {
    for (const Label& b : labels) {
      if (&a == &b || a.chosen < 0 || b.chosen < 0) continue;
      on_one_line =
          on_one_line || readsAsOneLine(a.candidates[static_cast<std::size_t>(a.chosen)],
                                        b.candidates[static_cast<std::size_t>(b.chosen)], em_px);
    }
  }
  return on_one_line;
}

// Writes the places found into the panel: the labels that gave way cleared (their bodies carry
// their numbers), the others placed by their bodies, and each an obstacle to the tags.
void writePlaces(frame::PanelModel& panel, std::vector<Label>& labels,
                 const std::vector<bool>& gives_way, LabelScene& scene) {
  for (std::size_t k = 0; k < labels.size(); ++k) {
    if (!gives_way[k]) continue;
    labels[k].text->clear();
    panel.bodies[labels[k].body].tag = std::to_string(labels[k].body + 1);
  }
  for (const Label& label : labels) {
    if (label.chosen < 0) continue;
    const std::size_t k = static_cast<std::size_t>(label.chosen);
    const Box& box = label.candidates[k];
    frame::PlacedText placed{{box.x0, box.y0}, {box.x1 - box.x0, box.y1 - box.y0}, std::nullopt};
    if (label.needs_leader[k]) placed.leader_to_px = leaderOf(label, box, scene).to;
    frame::BodyModel& body = panel.bodies[label.body];
    (label.velocity ? body.velocity_label_at : body.label_at) = placed;
    scene.obstacles.addText(box);
    if (placed.leader_to_px)
      scene.obstacles.addLeader(nearestOnBox(box, *placed.leader_to_px), *placed.leader_to_px);
  }
}

// The bodies' numbers: beside a body the legend names by a number too small to show inside it,
// and by the arrows.
void placeTags(const PanelText& text, LabelScene& scene, const frame::WorldToPixel& to_px) {
  frame::PanelModel& panel = text.panel;
  std::vector<bool> named(panel.bodies.size(), false);
  for (const frame::ReadoutLegend::Entry& entry : panel.legend.entries) {
    scene.obstacles.addText(legendBox(entry, text));
    if (entry.body >= 0 && entry.body < static_cast<int>(named.size())) {
      named[static_cast<std::size_t>(entry.body)] = true;
    }
  }
  placeTagsBeside(panel, named, scene.arrows, scene.moves_with, text.layout, to_px, text.metrics,
                  scene.obstacles);
  placeArrowTags(panel, scene.arrows, scene.moves_with, text.layout, to_px, text.metrics,
                 scene.obstacles);
}

// `lines_hard`: two labels on one line too near to read as two (readsAsOneLine) count as an
// overlap, so one of them gives way to the legend.
void placePanel(frame::PanelModel& panel, const frame::PanelLayout& where,
                const frame::FrameLayout& layout, text::TextMeasure& metrics, Margin margin,
                PanelPlan& plan, bool lines_hard = false) {
  const frame::PanelModel unplaced = panel;
  const frame::PixelRect area = frame::worldArea(panel, where, layout);
  const frame::WorldToPixel to_px = frame::fitView(panel.view, area);
  LabelScene scene =
      describePanel(panel, where, layout, to_px, area,
                    metrics.ascender(layout.small_px) + metrics.descender(layout.small_px),
                    margin == Margin::kUse);
  const double size = layout.text_px;
  takeBackLegend(panel);
  const PanelText text{panel,   where, layout,
                       metrics, size,  metrics.ascender(size) + metrics.descender(size)};
  // A dimension's text first (it belongs to its line); the bodies' labels keep clear of it.
  placeDimensionTexts(panel, layout, to_px, metrics, scene.obstacles);
  std::vector<Label> labels = panelLabels(text, scene, to_px, plan);
  LabelArrangement arrangement(labels, scene, lines_hard);
  arrangement.arrange();
  const Obstacles without_any_label = scene.obstacles;
  bool readout_gives_way = false;
  std::vector<bool> gives_way = labelsGivingWay(labels, scene, arrangement, readout_gives_way);
  listInLegend(labels, scene, arrangement, text, gives_way, readout_gives_way,
               readoutsStayingListed(labels, scene, gives_way, panel.two_d));
  // Settled: what gave way is in the legend. The labels left may take the places it freed (m₂
  // under its block once m₁ went to the legend, not on a leader beside it), and none continues
  // another's line: rounds of improvement again, the legend's lines obstacles like any text.
  scene.obstacles = without_any_label;
  for (const frame::ReadoutLegend::Entry& entry : panel.legend.entries) {
    scene.obstacles.addText(legendBox(entry, text));
  }
  arrangement.settle(plan.keep != nullptr ? kKeptShortOfApartPerPx : kShortOfApartPerPx);
  // Two labels still on one line with no place apart (long readouts over close arrows in a
  // narrow panel): placed again, one of them giving way as where it found no room, unless that
  // states fewer texts (the legend has no room for them).
  if (twoOnOneLine(labels, scene.em_px) && !lines_hard) {
    int stated = 0;
    for (const Label& label : labels) stated += label.chosen >= 0 ? 1 : 0;
    frame::PanelModel apart = unplaced;
    PanelPlan apart_plan{plan.keep, plan.panel, {}};
    placePanel(apart, where, layout, metrics, margin, apart_plan, true);
    if (statedTexts(apart) >= stated + statedTexts(panel)) {
      panel = std::move(apart);
      plan.chosen = std::move(apart_plan.chosen);
      return;
    }
  }
  writePlaces(panel, labels, gives_way, scene);
  plan.chosen = slotsOf(labels, plan.panel);
  placeTags(text, scene, to_px);
  panel.placed_for_width_px = layout.width_px;
  panel.placed_for_height_px = layout.height_px;
  panel.placed_for_scale_px = layout.scale_px;
  if (margin == Margin::kKeepUnlessLost && statedTexts(panel) < static_cast<int>(labels.size())) {
    frame::PanelModel in_margin = unplaced;
    PanelPlan margin_plan{plan.keep, plan.panel, {}};
    placePanel(in_margin, where, layout, metrics, Margin::kUse, margin_plan, lines_hard);
    if (statedTexts(in_margin) > statedTexts(panel)) {
      panel = std::move(in_margin);
      plan.chosen = std::move(margin_plan.chosen);
    }
  }
}

// The most PanelModel::print_values_room asks for.
constexpr int kMostValuesRoom = 2;

// Whether placing `unplaced` into `placed` lost a value: a mass label or readout it had (by its
// body, or in a legend of an earlier placement) that `placed` states neither by its body nor in
// its panel's legend.
bool losesAValue(const frame::FrameModel& unplaced, const frame::FrameModel& placed) {
  const auto listed = [](const frame::PanelModel& panel, std::size_t body, bool mass) {
    return std::any_of(panel.legend.entries.begin(), panel.legend.entries.end(),
                       [&](const frame::ReadoutLegend::Entry& entry) {
                         return entry.body == static_cast<int>(body) && entry.mass == mass &&
                                !entry.text.empty();
                       });
  };
  for (std::size_t p = 0; p < placed.panels.size() && p < unplaced.panels.size(); ++p) {
    const frame::PanelModel &was = unplaced.panels[p], &now = placed.panels[p];
    for (std::size_t i = 0; i < now.bodies.size() && i < was.bodies.size(); ++i) {
      for (const bool mass : {true, false}) {
        const auto text = [mass](const frame::BodyModel& body) -> const std::string& {
          return mass ? body.label : body.velocity_label;
        };
        const bool had = !text(was.bodies[i]).empty() || listed(was, i, mass);
        if (had && text(now.bodies[i]).empty() && !listed(now, i, mass)) return true;
      }
    }
  }
  return false;
}

}  // namespace

void placeLabels(frame::FrameModel& frame, int width_px, int height_px, text::TextMeasure& metrics,
                 double text_floor_px, const LabelSlots* keep, LabelSlots* chosen) {
  // A printed figure's single 1D panel may need the room of the text that repeats its values
  // (PanelModel::print_values_room): asked for step by step, only where a value is lost without
  // it, and not at all where even all of it would not save every value.
  const std::optional<frame::FrameModel> unplaced =
      text_floor_px > 0.0 ? std::optional<frame::FrameModel>(frame) : std::nullopt;
  for (int room = 0;; ++room) {
    const int asked = room <= kMostValuesRoom ? room : 0;
    // The layout measures the labels as they are now, all by their bodies, and keeps that room
    // for the painters (PanelModel::placed_label_lines).
    for (frame::PanelModel& panel : frame.panels) {
      panel.placed_label_lines = -1;
      panel.print_values_room = asked;
    }
    const frame::FrameLayout layout = frame::layoutFrame(
        frame, width_px, height_px, text_floor_px,
        [&metrics](std::string_view text, double size) { return metrics.width(text, size); });
    const bool can_give = unplaced && layout.panels.size() == 1 && !frame.panels.front().two_d &&
                          layout.panels.front().label_lines_below == 0;
    const bool last = !can_give || room > kMostValuesRoom;
    // The texts stand in the frame's margin only where no room asked for keeps every value.
    const Margin margin = last ? Margin::kKeepUnlessLost : Margin::kKeep;
    if (chosen != nullptr) chosen->clear();
    for (std::size_t p = 0; p < frame.panels.size() && p < layout.panels.size(); ++p) {
      PanelPlan plan{keep, p, {}};
      placePanel(frame.panels[p], layout.panels[p], layout, metrics, margin, plan);
      if (chosen != nullptr) chosen->insert(chosen->end(), plan.chosen.begin(), plan.chosen.end());
      frame.panels[p].placed_label_lines =
          layout.panels[p].label_lines_below == 0 ? layout.panels[p].label_lines_above : 0;
    }
    if (last || !losesAValue(*unplaced, frame)) return;
    frame = *unplaced;
  }
}

}  // namespace collide::compose
