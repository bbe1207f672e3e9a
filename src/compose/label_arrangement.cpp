// SPDX-License-Identifier: MIT
#include "compose/label_arrangement.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace collide::compose {
namespace {

constexpr int kImprovementRounds = 4;

// The box around every candidate place of a label: what moving it may reach.
Box reachOf(const Label& label) {
  Box reach = label.candidates.front();
  for (const Box& box : label.candidates) {
    reach = {std::min(reach.x0, box.x0), std::min(reach.y0, box.y0), std::max(reach.x1, box.x1),
             std::max(reach.y1, box.y1)};
  }
  return reach;
}

}  // namespace

LabelArrangement::LabelArrangement(std::vector<Label>& labels, LabelScene& scene, bool lines_hard)
    : labels_(labels),
      scene_(scene),
      lines_hard_(lines_hard),
      lines_{lines_hard ? kHard : 0.0, 0.0} {}

double LabelArrangement::best(Label& label) {
  double lowest = std::numeric_limits<double>::infinity();
  int pick = -1;
  label.chosen = -1;
  if (label.in_legend) return lowest;
  for (int k = 0; k < static_cast<int>(label.candidates.size()); ++k) {
    const double c = cost(label, k, labels_, scene_, own_, lines_, lowest);
    if (c < lowest) lowest = c, pick = k;
  }
  label.chosen = pick;
  return lowest;
}

bool LabelArrangement::fits(const Label& label) {
  return label.chosen >= 0 &&
         cost(label, label.chosen, labels_, scene_, own_, lines_, kHard) < kHard;
}

void LabelArrangement::improve(bool settled) {
  for (int round = 0; round < kImprovementRounds; ++round) {
    bool changed = false;
    for (Label& label : labels_) {
      if (settled && (label.chosen < 0 || label.in_legend)) continue;
      const int before = label.chosen;
      // What best() found is what fits() would find again for the place it took.
      const double lowest = best(label);
      if (settled && !(label.chosen >= 0 && lowest < kHard)) label.chosen = before;
      changed = changed || label.chosen != before;
    }
    if (!changed) break;
  }
}

bool LabelArrangement::moveAsPair(Label& label, Label& other) {
  const int other_was = other.chosen;
  double lowest = std::numeric_limits<double>::infinity();
  std::pair<int, int> pick{-1, -1};
  for (int j = 0; j < static_cast<int>(other.candidates.size()); ++j) {
    label.chosen = -1;
    other.chosen = j;
    const double moved = cost(other, j, labels_, scene_, own_, lines_, std::min(kHard, lowest));
    if (moved >= kHard || moved >= lowest) continue;
    for (int k = 0; k < static_cast<int>(label.candidates.size()); ++k) {
      const double total =
          moved + cost(label, k, labels_, scene_, own_, lines_, std::min(kHard, lowest), moved);
      if (total < lowest && total < kHard) lowest = total, pick = {j, k};
    }
  }
  if (pick.first >= 0) {
    other.chosen = pick.first;
    label.chosen = pick.second;
    return true;
  }
  other.chosen = other_was;
  best(label);
  return false;
}

void LabelArrangement::makeRoom(Label& label) {
  // Only labels whose boxes come within the label's reach are moved, each pair to the places
  // that cost least.
  const Box reach = reachOf(label);
  for (Label& other : labels_) {
    if (&other == &label || other.chosen < 0) continue;
    if (!reach.intersects(other.candidates[static_cast<std::size_t>(other.chosen)])) continue;
    if (moveAsPair(label, other)) break;
  }
}

void LabelArrangement::arrange() {
  for (Label& label : labels_) best(label);
  improve(false);
  // A label with no free place may find one where a neighbour moves aside (two long readouts
  // over two close arrows: one flush with each edge of the scene).
  for (Label& label : labels_) {
    if (label.in_legend || fits(label)) continue;
    makeRoom(label);
  }
}

void LabelArrangement::settle(double short_of_apart_per_px) {
  lines_ = {lines_hard_ ? kHard : kOneLine, short_of_apart_per_px};
  improve(true);
}

}  // namespace collide::compose
