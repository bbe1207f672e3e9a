// SPDX-License-Identifier: MIT
#pragma once
// The search that places one panel's labels by their bodies (label_placement.cpp): greedy in
// priority order, then rounds of local improvement, then pairs of labels moved together.
#include <vector>

#include "compose/label_candidates.hpp"
#include "compose/label_cost.hpp"

namespace collide::compose {

class LabelArrangement {
 public:
  // `lines_hard`: two labels on one line too near to read as two (readsAsOneLine) count as an
  // overlap, so one of them gives way to the legend. `labels` and `scene` are the panel's, kept
  // by reference: the arrangement sets each label's `chosen` against the scene's obstacles.
  LabelArrangement(std::vector<Label>& labels, LabelScene& scene, bool lines_hard);

  // Greedy, then rounds of local improvement, then pairs.
  void arrange();
  // Settled: what gave way is in the legend. The labels left may take the places it freed, and
  // none continues another's line: rounds of improvement again, standing on another label's line
  // now costing what LineCosts says (two mass labels nearer than kApartOnOneLineEm
  // `short_of_apart_per_px` for each pixel).
  void settle(double short_of_apart_per_px = kShortOfApartPerPx);
  // Whether a label has a place that runs into nothing.
  bool fits(const Label& label);

 private:
  // Takes the cheapest place for `label` (none, chosen -1, when it is in the legend); its cost.
  double best(Label& label);
  // Rounds of local improvement: each label in turn takes its cheapest place, until a round
  // changes nothing. Once `settled` (the legend holds what gave way), only labels by their
  // bodies move, and only to a place that fits: a label that fitted never gives way later.
  void improve(bool settled);
  // A label with no free place may find one where a neighbour moves aside: `other` and `label`
  // to the pair of places that costs least, where one fits both (true); else `label` back to its
  // cheapest place.
  void makeRoom(Label& label);
  bool moveAsPair(Label& label, Label& other);

  std::vector<Label>& labels_;
  LabelScene& scene_;
  bool lines_hard_;
  OwnCosts own_;
  // What standing on another label's line costs: nothing until what gives way has given way (so
  // that it never changes which labels find room), then kOneLine where the two read as one line
  // and kShortOfApartPerPx for each pixel they stand nearer than kApartOnOneLineEm; an overlap's
  // weight throughout where the first left two labels on one line.
  LineCosts lines_;
};

}  // namespace collide::compose
