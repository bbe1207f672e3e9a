// SPDX-License-Identifier: MIT
#include "compose/label_ways.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "compose/label_cost.hpp"
#include "compose/label_way_moves.hpp"

namespace collide::compose {

namespace {

// What cheapestWay asks of the steps for every pair of candidates at every step, kept at hand:
// when each step stands, and each place's offset from its body in one array (the steps' boxes
// lie in a vector per step).
class GlideTimer {
 public:
  explicit GlideTimer(const WaySteps& steps)
      : steps_(steps), count_(steps.boxes.front().size()), times_(timesOf(steps)) {
    const std::size_t n = steps.boxes.size();
    offsets_.reserve(n * count_);
    for (std::size_t k = 0; k < n; ++k) {
      for (const Box& box : steps.boxes[k]) offsets_.push_back(cornerOf(box) - steps.body_px[k]);
    }
    out_of_reach2_.assign(n, std::numeric_limits<double>::infinity());
    stands_.assign(n * count_, false);
    for (std::size_t k = 1; k < n; ++k) {
      // As stepsFor times a way that needs more than k steps where the steps up to k are even.
      const double span = static_cast<double>(k) * (times_[k] - times_[k - 1]);
      if (std::abs(times_[k] - times_[0] - span) <= 1e-9 * span) {
        // A margin far above the rounding of the root and the quotient.
        const double most_px =
            static_cast<double>(k + 1) * std::max(steps.reach_px[k], 1e-12) * (1.0 + 1e-9);
        out_of_reach2_[k] = most_px * most_px;
      }
      for (std::size_t c = 0; c < count_ && steps.glides_on_page; ++c) {
        stands_[k * count_ + c] = standsOnPage(steps, c, k - 1, k);
      }
    }
  }

  // The steps a glide from candidate `from` to `to`, ending at step k, takes at step k's speed
  // (from where `from` stood that many steps before); 0 where it cannot get there.
  std::size_t glideSteps(std::size_t k, std::size_t from, std::size_t to) const {
    // Most pairs of places stand farther apart than a glide gets from the first step: told from
    // the squared way from the step before, without its root and the steps it takes.
    if (squaredFromStepBefore(k, from, to) > out_of_reach2_[k]) return 0;
    std::size_t needs = 1;
    for (int round = 0; round < 3; ++round) {
      const std::size_t more = stepsFor(k, glideWayPx(k - needs, k, from, to));
      if (more > k) return 0;
      if (more <= needs) return needs;
      needs = more;
    }
    return stepsFor(k, glideWayPx(k - needs, k, from, to)) <= needs ? needs : 0;
  }

 private:
  // When each step stands, in steps.t_s's units (the index where it has none): a step halfway
  // between two, where an arrow changes rows, stands half a step from each.
  static std::vector<double> timesOf(const WaySteps& steps) {
    if (steps.t_s.size() == steps.boxes.size()) return steps.t_s;
    std::vector<double> times(steps.boxes.size());
    for (std::size_t k = 0; k < times.size(); ++k) times[k] = static_cast<double>(k);
    return times;
  }

  // The fewest steps ending at step k over which a label moves `way_px` at step k's speed (its
  // reach over the time since the step before); more than k where it cannot.
  std::size_t stepsFor(std::size_t k, double way_px) const {
    const double step = times_[k] - times_[k - 1];
    const double reach = std::max(steps_.reach_px[k], 1e-12);
    // Steps evenly apart (all but those halfway where an arrow changes rows): its whole reaches.
    const auto even = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(way_px / reach)));
    const std::size_t back = std::min(even, k);
    const double span = static_cast<double>(back) * step;
    if (std::abs(times_[k] - times_[k - back] - span) <= 1e-9 * span) return even;
    // Else the last step that stands long enough before step k (a hair less: a way of whole
    // steps' reach takes those steps, whatever the rounding of the times).
    const double takes = way_px / reach * step - 1e-9 * step;
    const auto after = std::upper_bound(times_.begin(), times_.begin() + static_cast<long>(k) + 1,
                                        times_[k] - takes);
    if (after == times_.begin()) return k + 1;
    const auto from = static_cast<std::size_t>(after - times_.begin()) - 1;
    return std::max<std::size_t>(1, k - from);
  }

  // How far a glide from candidate `from` at step `was` to `to` at step k moves: beyond its
  // body, or on the page where both places stand still there (glidingWay glides between them on
  // the page: a standing label moves down out of the way while its body runs on under it).
  double glideWayPx(std::size_t was, std::size_t k, std::size_t from, std::size_t to) const {
    if (steps_.glides_on_page && standsOnPage(steps_, from, was, k) &&
        standsOnPage(steps_, to, was, k)) {
      return (cornerOf(steps_.boxes[k][to]) - cornerOf(steps_.boxes[was][from])).norm();
    }
    return (offsets_[k * count_ + to] - offsets_[was * count_ + from]).norm();
  }

  // The square of glideWayPx(k - 1, k, from, to).
  double squaredFromStepBefore(std::size_t k, std::size_t from, std::size_t to) const {
    if (steps_.glides_on_page && stands_[k * count_ + from] && stands_[k * count_ + to]) {
      return (cornerOf(steps_.boxes[k][to]) - cornerOf(steps_.boxes[k - 1][from])).squaredNorm();
    }
    return (offsets_[k * count_ + to] - offsets_[(k - 1) * count_ + from]).squaredNorm();
  }

  const WaySteps& steps_;
  std::size_t count_;
  std::vector<double> times_;
  std::vector<core::Vec2> offsets_;  // step k's candidate c at k * count_ + c
  // Per step k: the squared way beyond which a glide from the step before needs more steps than
  // there are before k (infinite where the steps up to k are not even).
  std::vector<double> out_of_reach2_;
  // Step k's candidate c (at k * count_ + c) stands on the page from the step before.
  std::vector<bool> stands_;
};

}  // namespace

namespace {

// The `count` cheapest candidates of step k below `free_below`, cheapest first.
std::vector<std::size_t> cheapestAt(const WaySteps& steps, std::size_t k, std::size_t count,
                                    double free_below) {
  std::vector<std::size_t> order;
  const std::size_t own = steps.boxes[k].size() - (steps.starts_on_last ? 1 : 0);
  for (std::size_t c = 0; c < own; ++c) {
    if (steps.costs[k][c] < free_below) order.push_back(c);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return steps.costs[k][a] < steps.costs[k][b];
  });
  if (order.size() > count) order.resize(count);
  return order;
}

}  // namespace

void addStandingPlaces(WaySteps& steps, std::size_t every, std::size_t per_step, double free_below,
                       const std::function<double(std::size_t, const Box&)>& cost_at) {
  const std::size_t n = steps.boxes.size();
  std::vector<core::Vec2> corners;
  std::size_t counted = 0;
  for (std::size_t s = 0; s < n; ++s) {
    // Steps halfway between two are not counted: the same places as without them.
    if (s < steps.halfway.size() && steps.halfway[s]) continue;
    if (counted++ % std::max<std::size_t>(every, 1) != 0) continue;
    for (const std::size_t c : cheapestAt(steps, s, per_step, free_below)) {
      corners.push_back(cornerOf(steps.boxes[s][c]));
    }
  }
  for (std::size_t k = 0; k < n; ++k) {
    // The place it stood at the shot before stays the last candidate.
    const auto at = steps.boxes[k].end() - (steps.starts_on_last ? 1 : 0);
    const auto costs_at = steps.costs[k].end() - (steps.starts_on_last ? 1 : 0);
    std::vector<Box> boxes;
    std::vector<double> costs;
    for (const core::Vec2& corner : corners) {
      boxes.push_back(movedTo(steps.boxes[k].front(), corner));
      costs.push_back(cost_at(k, boxes.back()));
    }
    steps.boxes[k].insert(at, boxes.begin(), boxes.end());
    steps.costs[k].insert(costs_at, costs.begin(), costs.end());
  }
}

namespace {

Box shifted(const Box& box, const core::Vec2& by) {
  return {box.x0 + by.x(), box.y0 + by.y(), box.x1 + by.x(), box.y1 + by.y()};
}

// The least shift of candidate `c`'s place at the last step that makes it free there (none:
// nullopt).
std::optional<core::Vec2> freeingShift(
    const WaySteps& steps, std::size_t c, double most_px, int tries, double free_below,
    const std::function<double(std::size_t, const Box&)>& cost_at) {
  const std::size_t last = steps.boxes.size() - 1;
  for (int t = 1; t <= tries; ++t) {
    const double by = most_px * t / tries;
    for (const core::Vec2& shift :
         {core::Vec2{0.0, by}, core::Vec2{0.0, -by}, core::Vec2{by, 0.0}, core::Vec2{-by, 0.0}}) {
      if (cost_at(last, shifted(steps.boxes[last][c], shift)) < free_below) return shift;
    }
  }
  return std::nullopt;
}

}  // namespace

void addEndingPlaces(WaySteps& steps, double most_px, int tries, double free_below,
                     const std::function<double(std::size_t, const Box&)>& cost_at) {
  const std::size_t n = steps.boxes.size();
  if (n < 2) return;
  const std::size_t own = steps.boxes.back().size() - (steps.starts_on_last ? 1 : 0);
  std::vector<std::pair<std::size_t, core::Vec2>> added;
  for (std::size_t c = 0; c < own; ++c) {
    if (steps.costs[n - 1][c] < free_below || !(steps.costs[n - 2][c] < free_below)) continue;
    if (const auto shift = freeingShift(steps, c, most_px, tries, free_below, cost_at)) {
      added.emplace_back(c, *shift);
    }
  }
  for (std::size_t k = 0; k < n; ++k) {
    std::vector<Box> boxes;
    std::vector<double> costs;
    for (const auto& [c, shift] : added) {
      boxes.push_back(shifted(steps.boxes[k][c], shift));
      costs.push_back(cost_at(k, boxes.back()));
    }
    const auto at = steps.boxes[k].end() - (steps.starts_on_last ? 1 : 0);
    const auto costs_at = steps.costs[k].end() - (steps.starts_on_last ? 1 : 0);
    steps.boxes[k].insert(at, boxes.begin(), boxes.end());
    steps.costs[k].insert(costs_at, costs.begin(), costs.end());
  }
}

namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();

// What cheapestWay finds step by step: total[k][c], the least a way to candidate c at step k
// costs; from[k][c], the step and candidate it came from (a glide where they differ).
struct Ways {
  std::vector<std::vector<double>> total;
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> from;
};

// Whether no step's cost of any candidate, nor a change, is negative: then a way costs no less
// than any way it continues (rounding never makes a sum of such terms smaller than a part).
bool neverNegative(const WaySteps& steps) {
  if (!(steps.change_cost >= 0.0)) return false;
  for (const std::vector<double>& costs : steps.costs) {
    for (const double c : costs) {
      if (!(c >= 0.0)) return false;
    }
  }
  return true;
}

// Whether candidates `a` and `b` stand in one place at step k: a standing place added where a
// candidate stood (addStandingPlaces), or the place kept from the step before, is that
// candidate's place again, and a glide between the same places runs the same way.
bool samePlace(const WaySteps& steps, std::size_t k, std::size_t a, std::size_t b) {
  constexpr double kSamePlacePx = 0.5;
  return a == b ||
         (cornerOf(steps.boxes[k][a]) - cornerOf(steps.boxes[k][b])).norm() < kSamePlacePx;
}

// Whether a glide from candidate `from` to `to` over steps first to last runs over the steps of
// one between the same places found to have no free way.
bool refused(const WaySteps& steps, std::size_t first, std::size_t last, std::size_t from,
             std::size_t to) {
  return std::any_of(steps.refused.begin(), steps.refused.end(), [&](const WaySteps::Glide& g) {
    return first <= g.last && g.first <= last && samePlace(steps, g.first, g.from, from) &&
           samePlace(steps, g.last, g.to, to);
  });
}

// The glides to step k: from candidate `was` (standing there `needs` steps ago) to `to`, both
// places free over the way (the places between are checked after, glidingWay). `summed`: each
// candidate's cost summed from the first step; `short_of_hard`: the same with each step's cost
// held below an overlap (kOneLine at most); `least`: where given, each candidate's least total
// over the steps before k, which no glide from it can cost less than.
void glidesTo(const WaySteps& steps, const GlideTimer& timer, std::size_t k,
              const std::vector<std::vector<double>>& summed,
              const std::vector<std::vector<double>>& short_of_hard,
              const std::vector<double>* least, Ways& ways) {
  const std::size_t count = summed.front().size();
  const auto stretch = [&](std::size_t c, std::size_t first, std::size_t last) {
    return summed[last + 1][c] - summed[first][c];
  };
  for (std::size_t to = 0; to < count; ++to) {
    if (steps.costs[k][to] >= kHard) continue;
    double& best = ways.total[k][to];
    for (std::size_t was = 0; was < count; ++was) {
      if (was == to || (least != nullptr && (*least)[was] >= best)) continue;
      const std::size_t needs = timer.glideSteps(k, was, to);
      if (needs == 0 || ways.total[k - needs][was] == kNone) continue;
      if (!steps.refused.empty() && refused(steps, k - needs, k, was, to)) continue;
      // Within a step's reach it only changes which candidate it stands on (its arrow lifted
      // into another row carries its readout's rows along).
      // Gliding to `to`, it stands there only at step k: before that, where `to` runs into
      // something (a body closing in on it), the label is on its way between, whose places
      // glidingWay finds free or not. Counted in full, such steps would keep it standing where
      // it runs into something at the end of the shot rather than setting off in time.
      const double way = needs == 1 ? ways.total[k - 1][was] + steps.costs[k][to]
                                    : ways.total[k - needs][was] + steps.change_cost +
                                          stretch(was, k - needs + 1, k) + short_of_hard[k][to] -
                                          short_of_hard[k - needs + 1][to] + steps.costs[k][to];
      if (way < best) {
        best = way;
        ways.from[k][to] = {k - needs, was};
      }
    }
  }
}

// The jumps to step k from the cheapest way to step k - 1, where a jump costs steps.jump_cost.
void jumpsTo(const WaySteps& steps, std::size_t k, Ways& ways) {
  if (!std::isfinite(steps.jump_cost)) return;
  const std::vector<double>& before = ways.total[k - 1];
  const auto cheapest =
      static_cast<std::size_t>(std::min_element(before.begin(), before.end()) - before.begin());
  if (!(before[cheapest] < kNone)) return;
  for (std::size_t to = 0; to < before.size(); ++to) {
    const double way = before[cheapest] + steps.jump_cost + steps.costs[k][to];
    if (to != cheapest && way < ways.total[k][to]) {
      ways.total[k][to] = way;
      ways.from[k][to] = {k - 1, cheapest};
    }
  }
}

}  // namespace

WayPlan cheapestWay(const WaySteps& steps) {
  const std::size_t n = steps.boxes.size();
  if (n == 0) return {};
  const std::size_t count = steps.boxes.front().size();
  // Each candidate's cost summed from the first step: what a stretch of steps costs.
  std::vector<std::vector<double>> summed(n + 1, std::vector<double>(count, 0.0));
  std::vector<std::vector<double>> short_of_hard = summed;
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t c = 0; c < count; ++c) {
      summed[k + 1][c] = summed[k][c] + steps.costs[k][c];
      short_of_hard[k + 1][c] = short_of_hard[k][c] + std::min(steps.costs[k][c], kOneLine);
    }
  }
  Ways ways{std::vector<std::vector<double>>(n, std::vector<double>(count, kNone)),
            std::vector<std::vector<std::pair<std::size_t, std::size_t>>>(
                n, std::vector<std::pair<std::size_t, std::size_t>>(count))};
  std::vector<std::vector<double>>& total = ways.total;
  for (std::size_t c = 0; c < count; ++c) {
    if (!steps.starts_on_last || c + 1 == count) {
      total[0][c] = steps.costs[0][c];
    } else if (steps.costs[0][c] < kHard) {
      total[0][c] = steps.costs[0][c] + steps.restart_cost;
    }
    ways.from[0][c] = {0, c};
  }
  // A glide from a candidate whose ways so far all cost no less than the best way to `to`
  // found yet cannot be cheaper: most of the pairs, skipped before their steps are counted.
  std::vector<double> least(count, kNone);
  const GlideTimer timer(steps);
  const bool bounded = neverNegative(steps);
  for (std::size_t k = 1; k < n; ++k) {
    for (std::size_t c = 0; c < count; ++c) {
      least[c] = std::min(least[c], total[k - 1][c]);
      if (total[k - 1][c] < kNone &&
          movesWithin(steps.boxes[k - 1][c], steps.body_px[k - 1], steps.boxes[k][c],
                      steps.body_px[k], steps.reach_px[k])) {
        total[k][c] = total[k - 1][c] + steps.costs[k][c];
        ways.from[k][c] = {k - 1, c};
      }
    }
    glidesTo(steps, timer, k, summed, short_of_hard, bounded ? &least : nullptr, ways);
    jumpsTo(steps, k, ways);
  }
  const auto& from = ways.from;
  WayPlan plan{std::vector<int>(n, -1), {}};
  std::size_t c = static_cast<std::size_t>(
      std::min_element(total[n - 1].begin(), total[n - 1].end()) - total[n - 1].begin());
  for (std::size_t k = n - 1;;) {
    plan.chosen[k] = static_cast<int>(c);
    if (k == 0) break;
    const auto [before, was] = from[k][c];
    if (was != c && k - before > 1) plan.glides.push_back({before, k});
    // The steps of a glide stand on its destination until the places between are found.
    for (std::size_t j = before + 1; j < k; ++j) plan.chosen[j] = static_cast<int>(c);
    k = before;
    c = was;
  }
  std::reverse(plan.glides.begin(), plan.glides.end());
  return plan;
}

}  // namespace collide::compose
