#pragma once
// What a label's candidate place costs in label placement (label_placement.cpp): what it runs
// into, whether it reads as another body's or continues another label's line, its leader; with
// what each candidate costs alone kept while the obstacles stay as they are.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "compose/label_candidates.hpp"
#include "compose/placement_obstacles.hpp"
#include "core/vec.hpp"

namespace collide::compose {

inline constexpr double kHard = 1e6;  // one overlap outweighs any distance
// A place that continues another label's line (kOneLineLeastGapEm) outweighs any distance (a
// label a row lower, on a short leader, or slid along reads better), but not an overlap: it never
// sends a label to the legend.
inline constexpr double kOneLine = 1e-2 * kHard;

// Where a label's leader line runs, from the box to what the label names: a readout's to its
// arrow (the shaft's nearest point), a mass label's (or a readout's at rest) to its body's edge.
struct Leader {
  core::Vec2 from, to;
  bool to_arrow;
};
Leader leaderOf(const Label& label, const Box& box, const LabelScene& scene);

// What candidate `at` costs before the other labels are looked at: what it runs into, whether it
// reads as another body's, its leader (`leader`, where it needs one).
double costAlone(const Label& label, std::size_t at, const std::optional<Leader>& leader,
                 const LabelScene& scene);
// The same for a place `box` of `label` that prefers `base_cost` (a candidate's or not).
double costAlone(const Label& label, const Box& box, double base_cost,
                 const std::optional<Leader>& leader, const LabelScene& scene);

// What each candidate costs alone (costAlone, label_cost.cpp) and its leader, kept per label and
// candidate for one state of the obstacles (Obstacles::revision): the greedy pass, its rounds
// and the pair search ask for the same candidates many times over while the obstacles stay as
// they are (granular-chain's video spent about half of its CPU in cost()).
class OwnCosts {
 public:
  // Starts again where the obstacles or the labels changed since the last call.
  void keepFor(const std::vector<Label>& labels, const LabelScene& scene) {
    if (revision_ == scene.obstacles.revision() && cost_.size() == labels.size()) return;
    revision_ = scene.obstacles.revision();
    cost_.clear();
    leader_.clear();
    for (const Label& label : labels) {
      cost_.emplace_back(label.candidates.size(), std::numeric_limits<double>::quiet_NaN());
      leader_.emplace_back(label.candidates.size());
    }
  }
  // The part of label `index`'s candidate `at` cost that the other labels leave as it is, found
  // by `find` the first time it is asked for.
  template <typename Find>
  double cost(std::size_t index, std::size_t at, Find&& find) {
    double& kept = cost_[index][at];
    if (std::isnan(kept)) kept = find();
    return kept;
  }
  // The leader of label `index` from its candidate `at` (none where it needs none).
  const std::optional<Leader>& leader(const std::vector<Label>& labels, std::size_t index,
                                      std::size_t at, const LabelScene& scene) {
    const Label& label = labels[index];
    std::optional<Leader>& kept = leader_[index][at];
    if (!kept && label.needs_leader[at]) kept = leaderOf(label, label.candidates[at], scene);
    return kept;
  }

 private:
  std::uint64_t revision_ = 0;
  std::vector<std::vector<double>> cost_;  // NaN: not found yet
  std::vector<std::vector<std::optional<Leader>>> leader_;
};

// Whether two label boxes of one text size stand on one line too near to read as two.
bool readsAsOneLine(const Box& a, const Box& b, double em_px);
// How many pixels two label boxes on one baseline stand nearer than kApartOnOneLineEm (0 on
// different baselines or farther apart).
double shortOfApart(const Box& a, const Box& b, double em_px);

// What standing on another label's line costs: `one_line` where the two read as one line
// (readsAsOneLine), `per_px_short` for each pixel two mass labels stand nearer than
// kApartOnOneLineEm (a row of readouts over their arrows reads as such).
struct LineCosts {
  double one_line = 0.0;
  double per_px_short = 0.0;
};
// Moving a label a pixel along its row costs a pixel (label_candidates.cpp): two per pixel short
// makes sliding one label apart, or a row down where one has room, worth it.
inline constexpr double kShortOfApartPerPx = 2.0;
// Two labels kept in their places still move apart where they would read as a row.
inline constexpr double kKeptShortOfApartPerPx = 2.0 * kShortOfApartPerPx;

// What a candidate costs given the labels placed so far (chosen >= 0); `labels` holds `label`.
// Where `added_to` plus the cost reaches `stop_at`, it may stop short and return what it has
// summed so far: every term is never negative, so `added_to` plus that is at least `stop_at`
// too and compares with it as the whole would (a search that keeps only what costs less than
// its best so far skips most of the other labels of a candidate that costs more).
double cost(const Label& label, int k, const std::vector<Label>& labels, const LabelScene& scene,
            OwnCosts& own, const LineCosts& lines,
            double stop_at = std::numeric_limits<double>::infinity(), double added_to = 0.0);

}  // namespace collide::compose
