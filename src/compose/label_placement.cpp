#include "compose/label_placement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "compose/dimension_placement.hpp"
#include "compose/label_candidates.hpp"
#include "compose/label_cost.hpp"
#include "compose/label_scene.hpp"
#include "compose/legend_placement.hpp"
#include "compose/placement_obstacles.hpp"
#include "compose/tag_placement.hpp"
#include "frame/layout.hpp"
#include "frame/mark_sizes.hpp"

namespace collide::compose {
namespace {

constexpr int kImprovementRounds = 4;

// The texts of the `listed` labels.
std::vector<std::string> textsOf(const std::vector<Label>& labels,
                                 const std::vector<std::size_t>& listed) {
  std::vector<std::string> texts;
  for (std::size_t k : listed) texts.push_back(*labels[k].text);
  return texts;
}

// The widths of the `listed` labels.
std::vector<double> widthsOf(const std::vector<Label>& labels,
                             const std::vector<std::size_t>& listed) {
  std::vector<double> widths;
  for (std::size_t k : listed) widths.push_back(labels[k].size.x());
  return widths;
}

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

// Whether a panel's texts keep the frame's margin (the title's, from every edge: label_scene.cpp).
enum class Margin {
  kKeep,
  // Placed again in the margin where keeping it loses a value (a long translation in a small
  // frame, a block by the frame's edge): a label near the edge reads worse than one clear of it,
  // but better than none.
  kKeepUnlessLost,
  kUse,
};

// `lines_hard`: two labels on one line too near to read as two (readsAsOneLine) count as an
// overlap, so one of them gives way to the legend.
void placePanel(frame::PanelModel& panel, const frame::PanelLayout& where,
                const frame::FrameLayout& layout, text::TextMeasure& metrics, Margin margin,
                bool lines_hard = false) {
  const frame::PanelModel unplaced = panel;
  const frame::PixelRect area = frame::worldArea(panel, where, layout);
  const frame::WorldToPixel to_px = frame::fitView(panel.view, area);
  LabelScene scene =
      describePanel(panel, where, layout, to_px, area,
                    metrics.ascender(layout.small_px) + metrics.descender(layout.small_px),
                    margin == Margin::kUse);
  const double size = layout.text_px;
  // A frame placed before (at another size) gets its legend's texts back by their bodies.
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    frame::BodyModel& body = panel.bodies[i];
    body.label = frame::statedLabel(panel, i, true);
    body.velocity_label = frame::statedLabel(panel, i, false);
  }
  panel.legend = {};
  const double line = metrics.ascender(size) + metrics.descender(size);

  // A dimension's text first (it belongs to its line); the bodies' labels keep clear of it.
  placeDimensionTexts(panel.suspension, layout, to_px, metrics, scene.obstacles);

  std::vector<Label> labels;
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    frame::BodyModel& body = panel.bodies[i];
    body.label_at.reset();
    body.velocity_label_at.reset();
    body.tag_at.reset();
    body.arrow_tag_at.reset();
    for (bool velocity : {true, false}) {
      std::string& text = velocity ? body.velocity_label : body.label;
      if (text.empty()) continue;
      Label label{i, velocity, &text, {metrics.width(text, size), line}, {}, {}, {}, -1};
      addCandidates(label, panel, scene, layout, to_px);
      labels.push_back(std::move(label));
    }
  }
  // Greedy: fastest bodies' readouts first (their arrows leave the least room), then masses.
  std::stable_sort(labels.begin(), labels.end(), [&](const Label& a, const Label& b) {
    if (a.velocity != b.velocity) return a.velocity;
    return panel.bodies[a.body].velocity_mps.norm() > panel.bodies[b.body].velocity_mps.norm();
  });
  OwnCosts own;
  // What standing on another label's line costs: nothing until what gives way has given way (so
  // that it never changes which labels find room), then kOneLine where the two read as one line
  // and kShortOfApartPerPx for each pixel they stand nearer than kApartOnOneLineEm; an overlap's
  // weight throughout where the first left two labels on one line.
  LineCosts lines{lines_hard ? kHard : 0.0, 0.0};
  const auto best = [&](Label& label) {
    double lowest = std::numeric_limits<double>::infinity();
    int pick = -1;
    label.chosen = -1;
    if (label.in_legend) return lowest;
    for (int k = 0; k < static_cast<int>(label.candidates.size()); ++k) {
      const double c = cost(label, k, labels, scene, own, lines);
      if (c < lowest) lowest = c, pick = k;
    }
    label.chosen = pick;
    return lowest;
  };
  const auto fits = [&](const Label& label) {
    return label.chosen >= 0 && cost(label, label.chosen, labels, scene, own, lines) < kHard;
  };
  // Rounds of local improvement: each label in turn takes its cheapest place, until a round
  // changes nothing. Once `settled` (the legend holds what gave way), only labels by their
  // bodies move, and only to a place that fits: a label that fitted never gives way later.
  const auto improve = [&](bool settled) {
    for (int round = 0; round < kImprovementRounds; ++round) {
      bool changed = false;
      for (Label& label : labels) {
        if (settled && (label.chosen < 0 || label.in_legend)) continue;
        const int before = label.chosen;
        best(label);
        if (settled && !fits(label)) label.chosen = before;
        changed = changed || label.chosen != before;
      }
      if (!changed) break;
    }
  };
  // Greedy, then rounds of local improvement, then pairs.
  const auto arrange = [&] {
    for (Label& label : labels) best(label);
    improve(false);
    // A label with no free place may find one where a neighbour moves aside (two long readouts
    // over two close arrows: one flush with each edge of the scene). Only labels whose boxes
    // come within the label's reach are moved, each pair to the places that cost least.
    for (Label& label : labels) {
      if (label.in_legend || fits(label)) continue;
      Box reach = label.candidates.front();
      for (const Box& box : label.candidates) {
        reach = {std::min(reach.x0, box.x0), std::min(reach.y0, box.y0), std::max(reach.x1, box.x1),
                 std::max(reach.y1, box.y1)};
      }
      for (Label& other : labels) {
        if (&other == &label || other.chosen < 0) continue;
        if (!reach.intersects(other.candidates[static_cast<std::size_t>(other.chosen)])) continue;
        const int other_was = other.chosen;
        double lowest = std::numeric_limits<double>::infinity();
        std::pair<int, int> pick{-1, -1};
        for (int j = 0; j < static_cast<int>(other.candidates.size()); ++j) {
          label.chosen = -1;
          other.chosen = j;
          const double moved = cost(other, j, labels, scene, own, lines);
          if (moved >= kHard || moved >= lowest) continue;
          for (int k = 0; k < static_cast<int>(label.candidates.size()); ++k) {
            const double total = moved + cost(label, k, labels, scene, own, lines);
            if (total < lowest && total < kHard) lowest = total, pick = {j, k};
          }
        }
        if (pick.first >= 0) {
          other.chosen = pick.first;
          label.chosen = pick.second;
          break;
        }
        other.chosen = other_was;
        best(label);
      }
    }
  };
  arrange();
  const Obstacles without_any_label = scene.obstacles;
  // Labels that found no free place give way.
  std::vector<bool> gives_way(labels.size(), false);
  bool readout_gives_way = false;
  for (std::size_t k = 0; k < labels.size(); ++k) {
    Label& label = labels[k];
    if (fits(label)) continue;
    gives_way[k] = true;
    readout_gives_way = readout_gives_way || (label.velocity && scene.arrows[label.body]);
  }
  for (std::size_t k = 0; k < labels.size(); ++k) {
    if (gives_way[k]) labels[k].chosen = -1;
  }
  // An arrow's value is never lost: where a readout found no room by its arrow, every arrow's
  // readout goes into one legend in a free place of the scene (a table reads better than some
  // values by their arrows and the rest in a list), and the bodies carry their numbers. Nor is
  // a mass: a mass label with no room by its body joins the legend ("m₁ = 1.00 kg" beside the
  // block numbered 1).
  std::vector<std::size_t> listed;
  for (std::size_t k = 0; k < labels.size(); ++k) {
    const bool readout = labels[k].velocity && scene.arrows[labels[k].body];
    if ((readout && readout_gives_way) || (gives_way[k] && !labels[k].text->empty())) {
      listed.push_back(k);
    }
  }
  // By body, each body's readout before its mass.
  const auto byBody = [&](std::vector<std::size_t>& ks) {
    std::sort(ks.begin(), ks.end(), [&](std::size_t a, std::size_t b) {
      if (labels[a].body != labels[b].body) return labels[a].body < labels[b].body;
      return labels[a].velocity && !labels[b].velocity;
    });
  };
  byBody(listed);
  if (!listed.empty()) {
    const Obstacles without_labels = scene.obstacles;
    // The labels placed by their bodies, but for `except`, as obstacles to the legend.
    const auto keepPlaced = [&](const std::vector<std::size_t>& except) {
      scene.obstacles = without_labels;
      for (std::size_t k = 0; k < labels.size(); ++k) {
        const Label& label = labels[k];
        if (label.chosen < 0 || std::find(except.begin(), except.end(), k) != except.end())
          continue;
        const Box& box = label.candidates[static_cast<std::size_t>(label.chosen)];
        scene.obstacles.addText(box);
        if (label.needs_leader[static_cast<std::size_t>(label.chosen)]) {
          const Leader leader = leaderOf(label, box, scene);
          scene.obstacles.addLeader(leader.from, leader.to);
        }
      }
    };
    keepPlaced(listed);
    std::optional<std::vector<core::Vec2>> at =
        placeLegend(widthsOf(labels, listed), scene.obstacles, layout, line);
    // A printed figure's 1D scene keeps lines above its arrows for a legend of all its labels
    // (frame::printLabelLines): where the masses that gave way find no line left beside the
    // readouts, the readouts join them there, as those lines were measured.
    if (!at && !panel.two_d && where.label_lines_below == 0) {
      std::vector<std::size_t> all = listed;
      for (std::size_t k = 0; k < labels.size(); ++k) {
        const bool readout = labels[k].velocity && scene.arrows[labels[k].body];
        if (readout && std::find(all.begin(), all.end(), k) == all.end()) all.push_back(k);
      }
      byBody(all);
      keepPlaced(all);
      at = placeLegend(widthsOf(labels, all), scene.obstacles, layout, line);
      if (at) {
        listed = all;
      } else {
        keepPlaced(listed);
      }
    }
    if (!at) {
      // No room for it among the labels placed: the legend takes its place first, and the
      // labels by their bodies look for places around it (they have more than one).
      const Obstacles with_labels = scene.obstacles;
      std::vector<int> was;
      for (const Label& label : labels) was.push_back(label.chosen);
      scene.obstacles = without_labels;
      at = placeLegend(widthsOf(labels, listed), scene.obstacles, layout, line);
      if (at) {
        for (std::size_t n = 0; n < listed.size(); ++n) {
          const core::Vec2& corner = (*at)[n];
          scene.obstacles.addText(
              {corner.x(), corner.y(), corner.x() + labels[listed[n]].size.x(), corner.y() + line});
          labels[listed[n]].in_legend = true;
        }
        arrange();
        for (const Label& label : labels) {
          if (!label.in_legend && !fits(label)) at.reset();
        }
      }
      if (!at) {
        for (std::size_t k = 0; k < labels.size(); ++k) {
          labels[k].chosen = was[k];
          labels[k].in_legend = false;
        }
        scene.obstacles = with_labels;
      }
    }
    if (!at) {
      // No room for them all: the readouts that fit by their arrows stay there, the others go
      // to a smaller legend.
      std::vector<std::size_t> lost;
      for (std::size_t k : listed) {
        if (gives_way[k]) {
          lost.push_back(k);
        } else {
          const Box& box = labels[k].candidates[static_cast<std::size_t>(labels[k].chosen)];
          scene.obstacles.addText(box);
          if (labels[k].needs_leader[static_cast<std::size_t>(labels[k].chosen)]) {
            const Leader leader = leaderOf(labels[k], box, scene);
            scene.obstacles.addLeader(leader.from, leader.to);
          }
        }
      }
      listed = lost;
      at = placeLegend(widthsOf(labels, listed), scene.obstacles, layout, line);
    }
    if (at) {
      for (std::size_t n = 0; n < listed.size(); ++n) {
        Label& label = labels[listed[n]];
        panel.legend.entries.push_back(
            {static_cast<int>(label.body), *label.text, (*at)[n], !label.velocity});
        label.chosen = -1;
        gives_way[listed[n]] = true;
      }
    } else if (const std::optional<std::vector<WrappedText>> wrapped =
                   wrapInTwo(textsOf(labels, listed), metrics, size)) {
      // Still no room (long translated texts in a narrow scene): one column of the texts each
      // on two lines, the second indented by an em.
      std::vector<double> widths;
      for (const WrappedText& w : *wrapped) {
        widths.push_back(w.first_px);
        widths.push_back(size + w.second_px);
      }
      at = placeLegend(widths, scene.obstacles, layout, line, 1);
      for (std::size_t n = 0; at && n < listed.size(); ++n) {
        Label& label = labels[listed[n]];
        const int body = static_cast<int>(label.body);
        panel.legend.entries.push_back({body, (*wrapped)[n].first, (*at)[2 * n], !label.velocity});
        panel.legend.entries.push_back({body, (*wrapped)[n].second,
                                        (*at)[2 * n + 1] + core::Vec2{size, 0.0}, !label.velocity});
        label.chosen = -1;
        gives_way[listed[n]] = true;
      }
    }
  }
  // Settled: what gave way is in the legend. The labels left may take the places it freed (m₂
  // under its block once m₁ went to the legend, not on a leader beside it), and none continues
  // another's line: rounds of improvement again, the legend's lines obstacles like any text.
  scene.obstacles = without_any_label;
  for (const frame::ReadoutLegend::Entry& entry : panel.legend.entries) {
    const core::Vec2& at = entry.top_left_px;
    scene.obstacles.addText(
        {at.x(), at.y(), at.x() + metrics.width(entry.text, size), at.y() + line});
  }
  lines = {lines_hard ? kHard : kOneLine, kShortOfApartPerPx};
  improve(true);
  // Two labels still on one line with no place apart (long readouts over close arrows in a
  // narrow panel): placed again, one of them giving way as where it found no room, unless that
  // states fewer texts (the legend has no room for them).
  bool on_one_line = false;
  for (const Label& a : labels) {
    for (const Label& b : labels) {
      if (&a == &b || a.chosen < 0 || b.chosen < 0) continue;
      on_one_line = on_one_line ||
                    readsAsOneLine(a.candidates[static_cast<std::size_t>(a.chosen)],
                                   b.candidates[static_cast<std::size_t>(b.chosen)], scene.em_px);
    }
  }
  if (on_one_line && !lines_hard) {
    int stated = 0;
    for (const Label& label : labels) stated += label.chosen >= 0 ? 1 : 0;
    frame::PanelModel apart = unplaced;
    placePanel(apart, where, layout, metrics, margin, true);
    if (statedTexts(apart) >= stated + statedTexts(panel)) {
      panel = std::move(apart);
      return;
    }
  }
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
  // A body the legend names by a number too small to show it inside has it beside it.
  std::vector<bool> named(panel.bodies.size(), false);
  for (const frame::ReadoutLegend::Entry& entry : panel.legend.entries) {
    const Box box{entry.top_left_px.x(), entry.top_left_px.y(),
                  entry.top_left_px.x() + metrics.width(entry.text, size),
                  entry.top_left_px.y() + line};
    scene.obstacles.addText(box);
    if (entry.body >= 0 && entry.body < static_cast<int>(named.size())) {
      named[static_cast<std::size_t>(entry.body)] = true;
    }
  }
  placeTagsBeside(panel, named, scene.arrows, scene.moves_with, layout, to_px, metrics,
                  scene.obstacles);
  placeArrowTags(panel, scene.arrows, scene.moves_with, layout, to_px, metrics, scene.obstacles);
  panel.placed_for_width_px = layout.width_px;
  panel.placed_for_height_px = layout.height_px;
  panel.placed_for_scale_px = layout.scale_px;
  if (margin == Margin::kKeepUnlessLost && statedTexts(panel) < static_cast<int>(labels.size())) {
    frame::PanelModel in_margin = unplaced;
    placePanel(in_margin, where, layout, metrics, Margin::kUse, lines_hard);
    if (statedTexts(in_margin) > statedTexts(panel)) panel = std::move(in_margin);
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
                 double text_floor_px) {
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
    for (std::size_t p = 0; p < frame.panels.size() && p < layout.panels.size(); ++p) {
      placePanel(frame.panels[p], layout.panels[p], layout, metrics, margin);
      frame.panels[p].placed_label_lines =
          layout.panels[p].label_lines_below == 0 ? layout.panels[p].label_lines_above : 0;
    }
    if (last || !losesAValue(*unplaced, frame)) return;
    frame = *unplaced;
  }
}

}  // namespace collide::compose
