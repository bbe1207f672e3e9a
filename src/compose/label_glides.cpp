// SPDX-License-Identifier: MIT
// A planned way's glides between its places: straight or round what stands across, and the way
// planned again without the glides that found no free path.
#include <algorithm>
#include <cmath>
#include <utility>

#include "compose/label_way_moves.hpp"
#include "compose/label_ways.hpp"

namespace collide::compose {

namespace {

// The way a glide takes between two offsets from its body, `share` of the way along: straight,
// or along one axis first and then the other (round something that stands across the straight
// way: another body's arrow where the label would read as its), at one speed.
enum class GlidePath { kStraight, kAcrossFirst, kUpOrDownFirst };

core::Vec2 alongPath(GlidePath path, const core::Vec2& from, const core::Vec2& to, double share) {
  const core::Vec2 d = to - from;
  if (path == GlidePath::kStraight) return from + share * d;
  const bool across_first = path == GlidePath::kAcrossFirst;
  const double first_leg = std::abs(across_first ? d.x() : d.y());
  const double length = std::abs(d.x()) + std::abs(d.y());
  const double done = share * length;
  const double on_first = std::min(done, first_leg), on_second = std::max(0.0, done - first_leg);
  const double first_share = first_leg > 0.0 ? on_first / first_leg : 1.0;
  const double second_leg = length - first_leg;
  const double second_share = second_leg > 0.0 ? on_second / second_leg : 1.0;
  return across_first ? from + core::Vec2{first_share * d.x(), second_share * d.y()}
                      : from + core::Vec2{second_share * d.x(), first_share * d.y()};
}

// The glide from step `first` (where the label stands at `from`, as an offset from its body) to
// step `last` (at `to`) along `path`: whether every place between is free and, where
// `check_reach`, no step moves it farther than its reach; if so shown set along it. `on_page`:
// `from` and `to` are places on the page (two that stand still), the glide between them too.
bool tryGlide(const WaySteps& steps, std::size_t first, std::size_t last, const core::Vec2& from,
              const core::Vec2& to, const Box& size, GlidePath path, bool check_reach,
              const std::function<double(std::size_t, const Box&)>& cost_at, double free_below,
              Way& way, bool by_reach = false, bool on_page = false) {
  std::vector<Box> along;
  core::Vec2 before = from;
  // Each step's share of the way as of its time (a step halfway between two, half a step's),
  // or, `by_reach`, as of its reach: a glide that sets off at an event moves faster while the
  // event's speed lasts.
  const bool timed = steps.t_s.size() == steps.boxes.size();
  const auto time = [&](std::size_t k) { return timed ? steps.t_s[k] : static_cast<double>(k); };
  std::vector<double> reached(last - first + 1, 0.0);
  for (std::size_t k = first + 1; k <= last; ++k) {
    reached[k - first] =
        reached[k - first - 1] + (by_reach ? steps.reach_px[k] : time(k) - time(k - 1));
  }
  for (std::size_t k = first; k <= last; ++k) {
    const double share = reached[k - first] / std::max(reached.back(), 1e-12);
    const core::Vec2 offset = alongPath(path, from, to, share);
    if (check_reach && k > first && (offset - before).norm() > steps.reach_px[k]) return false;
    before = offset;
    const Box box = movedTo(size, on_page ? offset : steps.body_px[k] + offset);
    if (k > first && k < last && !(cost_at(k, box) < free_below)) return false;
    along.push_back(box);
  }
  for (std::size_t k = first; k <= last; ++k) {
    way.shown[k] = along[k - first];
    way.rides[k] =
        !on_page ||
        (k > 0 &&
         moveBetween(way.shown[k - 1], steps.body_px[k - 1], way.shown[k], steps.body_px[k]).rides);
  }
  return true;
}

// Where the straight glide from `first` to `last` runs into something: one round it (along one
// axis, then the other), setting off up to as many steps earlier again from where the label stood
// (on `chosen[first]` since `earliest`), the fewest steps earlier that has a free way.
bool glideRound(const WaySteps& steps, const std::vector<int>& chosen, std::size_t earliest,
                std::size_t first, std::size_t last, const core::Vec2& to,
                const std::function<double(std::size_t, const Box&)>& cost_at, double free_below,
                Way& way) {
  for (std::size_t earlier = 0; earlier <= last - first && first >= earliest + earlier; ++earlier) {
    const std::size_t start = first - earlier;
    if (chosen[start] != chosen[first]) return false;
    const core::Vec2 from = cornerOf(way.shown[start]) - steps.body_px[start];
    for (const GlidePath path :
         {GlidePath::kStraight, GlidePath::kAcrossFirst, GlidePath::kUpOrDownFirst}) {
      if (earlier == 0 && path == GlidePath::kStraight) continue;
      if (tryGlide(steps, start, last, from, to, way.shown[last], path, true, cost_at, free_below,
                   way)) {
        return true;
      }
    }
  }
  return false;
}

// Where no glide round gets there by `last` (the way round is longer than the straight way the
// plan timed it by: a readout beyond its arrow's tip going up over the arrow after an event),
// one round it that arrives later, where the plan's way has got to by then (up to `latest`):
// the fewest steps later with a free way, twice as many each try. The step it arrives at, or 0
// where none is free.
std::size_t glideRoundLater(const WaySteps& steps, std::size_t first, std::size_t last,
                            std::size_t latest,
                            const std::function<double(std::size_t, const Box&)>& cost_at,
                            double free_below, Way& way) {
  const core::Vec2 from = cornerOf(way.shown[first]) - steps.body_px[first];
  for (std::size_t later = 1; last + later <= latest; later *= 2) {
    const std::size_t end = last + later;
    const core::Vec2 to = cornerOf(way.shown[end]) - steps.body_px[end];
    for (const GlidePath path : {GlidePath::kAcrossFirst, GlidePath::kUpOrDownFirst}) {
      if (tryGlide(steps, first, end, from, to, way.shown[end], path, true, cost_at, free_below,
                   way, true)) {
        return end;
      }
    }
  }
  return 0;
}

}  // namespace

Way glidingWay(const WaySteps& steps, const WayPlan& plan,
               const std::function<double(std::size_t, const Box&)>& cost_at, double free_below,
               bool arriving_later) {
  const std::vector<int>& chosen = plan.chosen;
  const std::size_t n = chosen.size();
  Way way{std::vector<Box>(n), std::vector<bool>(n, true), 0, {}};
  for (std::size_t k = 0; k < n; ++k) {
    way.shown[k] = steps.boxes[k][static_cast<std::size_t>(chosen[k])];
    if (k > 0) {
      way.rides[k] =
          moveBetween(way.shown[k - 1], steps.body_px[k - 1], way.shown[k], steps.body_px[k]).rides;
    }
  }
  std::size_t arrived = 0;  // where the glide before ended
  for (std::size_t g = 0; g < plan.glides.size(); ++g) {
    const auto [first, last] = plan.glides[g];
    const core::Vec2 from = cornerOf(way.shown[first]) - steps.body_px[first];
    const core::Vec2 to = cornerOf(way.shown[last]) - steps.body_px[last];
    // Arriving later, it may take the steps up to the next glide's start.
    const std::size_t latest = g + 1 < plan.glides.size() ? plan.glides[g + 1].first : n - 1;
    // Between two places that stand still on the page (label_ways.cpp's glideSteps timed it so)
    // it glides on the page.
    const bool on_page =
        steps.glides_on_page &&
        standsOnPage(steps, static_cast<std::size_t>(chosen[first]), first, last) &&
        standsOnPage(steps, static_cast<std::size_t>(chosen[last]), first, last);
    bool glides =
        (on_page ? tryGlide(steps, first, last, cornerOf(way.shown[first]),
                            cornerOf(way.shown[last]), way.shown[last], GlidePath::kStraight, false,
                            cost_at, free_below, way, false, true)
                 : tryGlide(steps, first, last, from, to, way.shown[last], GlidePath::kStraight,
                            false, cost_at, free_below, way)) ||
        glideRound(steps, chosen, arrived, first, last, to, cost_at, free_below, way);
    arrived = last;
    if (!glides && arriving_later) {
      const std::size_t later =
          glideRoundLater(steps, first, last, latest, cost_at, free_below, way);
      glides = later > 0;
      arrived = glides ? later : last;
    }
    if (!glides) {
      // No free way between: it keeps its place until the change.
      ++way.jumps;
      const auto was = static_cast<std::size_t>(chosen[first]);
      way.jumped.push_back({first, last, was, static_cast<std::size_t>(chosen[last])});
      for (std::size_t k = first + 1; k < last; ++k) {
        way.shown[k] = steps.boxes[k][was];
        way.rides[k] =
            moveBetween(way.shown[k - 1], steps.body_px[k - 1], way.shown[k], steps.body_px[k])
                .rides;
      }
    }
  }
  return way;
}

namespace {

// How many times a way that jumps is planned again without its jumps' glides.
constexpr int kReplans = 3;

// The gliding way of the cheapest; where it jumps, planned again without the glides that jumped,
// up to kReplans times: the first that jumps least.
Way fewestJumps(WaySteps& steps, const std::function<double(std::size_t, const Box&)>& cost_at,
                double free_below) {
  const std::vector<WaySteps::Glide> refused = steps.refused;
  WayPlan best_plan = cheapestWay(steps);
  Way best = glidingWay(steps, best_plan, cost_at, free_below);
  Way latest = best;
  // Where the way may jump within the shot anyway (WaySteps::jump_cost, a 2D label), it is not
  // planned again: the cheapest way jumps where it must.
  const int replans = std::isfinite(steps.jump_cost) ? 0 : kReplans;
  for (int round = 0; round < replans && latest.jumps > 0; ++round) {
    steps.refused.insert(steps.refused.end(), latest.jumped.begin(), latest.jumped.end());
    WayPlan plan = cheapestWay(steps);
    latest = glidingWay(steps, plan, cost_at, free_below);
    if (latest.jumps < best.jumps) {
      best = latest;
      best_plan = std::move(plan);
    }
  }
  steps.refused = refused;
  // Along a track, where it still jumps, a glide round what stands across may arrive later than
  // planned: only then, as a way that glides on time (planned again) reads better than one that
  // creeps. (In 2D it moved billiards-glancing's readout out onto a long leader.)
  if (best.jumps > 0 && !std::isfinite(steps.jump_cost)) {
    Way later = glidingWay(steps, best_plan, cost_at, free_below, true);
    if (later.jumps < best.jumps) best = std::move(later);
  }
  return best;
}

}  // namespace

Way endingWay(WaySteps& steps, const std::vector<double>& across_costs, double jump_cost,
              const std::function<double(std::size_t, const Box&)>& cost_at, double free_below) {
  if (across_costs.empty()) return fewestJumps(steps, cost_at, free_below);
  const std::vector<double> own_costs = steps.costs.back();
  for (std::size_t c = 0; c < own_costs.size() && c < across_costs.size(); ++c) {
    steps.costs.back()[c] += std::min(across_costs[c], jump_cost);
  }
  Way ending = fewestJumps(steps, cost_at, free_below);
  steps.costs.back() = own_costs;
  if (ending.jumps == 0) return ending;
  Way own = fewestJumps(steps, cost_at, free_below);
  return own.jumps < ending.jumps ? own : ending;
}

}  // namespace collide::compose
