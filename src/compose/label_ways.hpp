// SPDX-License-Identifier: MIT
#pragma once
// One label's way through a shot (label_timeline.hpp): at each step of the shot it stands at
// one of its candidate places by its body, the sequence that costs least in all (what each place
// runs into, its preference, and each change of place), found by dynamic programming over (step,
// candidate); then each change of place is made a glide, moving no faster than the step allows
// beyond its body, over steps where the places between are free, so the label never jumps (but
// where the steps allow a jump, WaySteps::jump_cost, and every glide runs into something).
#include <cstddef>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "compose/placement_obstacles.hpp"
#include "core/vec.hpp"

namespace collide::compose {

struct WaySteps {
  std::vector<core::Vec2> body_px;         // per step, the label's body's centre
  std::vector<double> reach_px;            // how far it may move from the step before (k > 0)
  std::vector<std::vector<Box>> boxes;     // per step, its candidate places (as many each step)
  std::vector<std::vector<double>> costs;  // per step, what each costs
  // When each step stands (any unit; empty: steps evenly apart, as the index): a glide moves at
  // its last step's speed (its reach over the time since the step before), each step its share
  // of the way by time.
  std::vector<double> t_s;
  std::vector<bool> halfway;  // per step: one halfway between two (empty: none)
  double change_cost = 0.0;   // what a change of place costs
  // Whether a change between two places that stand still on the page glides on the page (along
  // a track: a readout standing over the track gets out of the way while its body runs on).
  bool glides_on_page = false;
  // Whether the last candidate is where it stood at the shot before's last step, carried along
  // by its body, where it starts.
  bool starts_on_last = false;
  // What starting elsewhere costs where it starts on the last (a jump at the event that starts
  // the shot): infinite, never; finite, taken where staying would run into something longer.
  double restart_cost = std::numeric_limits<double>::infinity();
  // What a jump to another place within the shot costs (infinite: never): taken where every way
  // that glides runs into something for longer.
  double jump_cost = std::numeric_limits<double>::infinity();
  // Glides from candidate `from` to candidate `to` over steps `first` to `last` found to have no
  // free way between (glidingWay): no glide between their places (any candidates standing
  // there) over any of those steps is taken.
  struct Glide {
    std::size_t first, last, from, to;
  };
  std::vector<Glide> refused;
};

// Adds places where the label stands still on the page while its body moves on, as one held by
// the frame's edge does, or one that makes way for bodies closing in: at the first step and every
// `every`-th step after (counting no step halfway), each of the `per_step` cheapest candidates
// below `free_below` is added as a candidate at every step where it stood then (its text's size
// each step's), costing what `cost_at(step, box)` says. Before the last candidate where
// steps.starts_on_last.
void addStandingPlaces(WaySteps& steps, std::size_t every, std::size_t per_step, double free_below,
                       const std::function<double(std::size_t, const Box&)>& cost_at);

// Where a shot ends at an event: each candidate free at the step before the last but not at the
// last (a readout standing by its arrow while another body's arrow tip closes in on it, read as
// that body's at the last step only) is added again shifted by the least of `tries` even steps
// of up to `most_px`, down, up, right or left, that makes it free at the last step (the same
// shift at every step, costing what `cost_at(step, box)` says there): the way planned back from
// the last step, so that it gets out of the way in time, before the event, not at it. Before the
// last candidate where steps.starts_on_last.
void addEndingPlaces(WaySteps& steps, double most_px, int tries, double free_below,
                     const std::function<double(std::size_t, const Box&)>& cost_at);

// The candidate each step takes, and the glides between them: the way that costs least, staying
// on a candidate free where it moves no farther than the step's reach beyond its body or
// standing still, a change of candidate a glide over as many steps as its reach needs.
struct WayPlan {
  std::vector<int> chosen;
  std::vector<std::pair<std::size_t, std::size_t>> glides;  // first and last step of each
};
WayPlan cheapestWay(const WaySteps& steps);

// Where the label is shown at each step, and whether from the step before it rides with its body
// (else it stands): each change of place in `chosen` glides instead, over the steps before it or
// around it where `cost_at(step, box)` finds every place between free (below `free_below`), or,
// `arriving_later`, round it over more steps, arriving later than planned; a change with no
// such steps stays a jump.
struct Way {
  std::vector<Box> shown;
  std::vector<bool> rides;
  std::size_t jumps = 0;                // changes of place with no free way between
  std::vector<WaySteps::Glide> jumped;  // those changes, as glides
};
Way glidingWay(const WaySteps& steps, const WayPlan& plan,
               const std::function<double(std::size_t, const Box&)>& cost_at, double free_below,
               bool arriving_later = false);

// The gliding way of the cheapest. Where it jumps, the cheapest without those glides, a few
// times over, and the one that jumps least; where that one still jumps, its glides arriving
// later where that finds them a free way. Where the steps end a shot at an event
// (`across_costs`: what each candidate of the last step costs carried over the event; empty: no
// event), a place that runs into something after the event costs up to `jump_cost` more, what a
// jump there costs, so the label ends where it can stay on across the event where it gets there
// in time; unless that way jumps within the shot more often than the one that does not look past
// its end.
Way endingWay(WaySteps& steps, const std::vector<double>& across_costs, double jump_cost,
              const std::function<double(std::size_t, const Box&)>& cost_at, double free_below);

}  // namespace collide::compose
