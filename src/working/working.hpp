// SPDX-License-Identifier: MIT
#pragma once
// The working of one impact: the steps a teacher writes beside the video, made from the scene's
// simulation. The given values; the laws (momentum conservation and the definition of e along the
// line of impact, the normal/tangent split in 2D, the common velocity when e = 0, the energy lost
// 1/2 mu (1 - e^2) u^2, and what a kind of scene adds: the bouncing ball's heights, the ballistic
// pendulum's rise, an accident's skids, Newton's cradle, the pi-blocks' count, a soft contact's
// impulse); the laws solved; the numbers substituted; the result, which is what the simulation
// computed. Numbers are written as the picture's readouts write them (text/number_format.hpp, three
// figures).
#include <string>
#include <vector>

#include "physics/timeline.hpp"
#include "text/math.hpp"

namespace collide::working {

// One line: sides[0] = sides[1] = ..., then a note in words ("momentum is conserved").
struct Equation {
  std::vector<text::Math> sides;
  std::string note;
};

enum class StepKind { kGiven, kLaw, kSolved, kSubstituted, kResult };

struct Step {
  StepKind kind = StepKind::kGiven;
  std::string heading;  // in the active language
  std::vector<Equation> equations;
};

struct Working {
  std::string title;  // "Impact 1 of 1: cart 1 and cart 2 at t = 1.167 s"
  std::vector<Step> steps;
};

// The events a working can be asked for: the recorded impacts and releases (stored energy pushing
// two bodies apart), in the order they happen (a run records the first 100,000).
std::size_t impactCount(const physics::Timeline& timeline);

// The working of event `impact` (0-based, below impactCount()) of a simulated scene: an impact's
// laws, or a release's (momentum conserved, the kinetic energy grown by Q).
Working workingFor(const physics::Timeline& timeline, std::size_t impact);

}  // namespace collide::working
