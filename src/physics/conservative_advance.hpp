#pragma once
// Internal: conservative advancement, the time of impact for gaps that are no polynomial (a
// rotating cluster against a wall or a disk). It steps by the time the gap needs to close at the
// fastest it can, so it never steps past a contact; a pure function of its input, like the
// polynomial roots in toi.hpp, so that predictions replay exactly.
#include <algorithm>
#include <cmath>

#include "physics/toi.hpp"

namespace collide::physics::detail {

// Relative size of a normal speed that is only rounding of the velocities involved.
inline constexpr double kRoundingSpeed = 1e-12;
// Deepest overlap a step forced past a grazing contact may leave, m: a tenth of the overlap the
// property tests accept, far below anything drawn.
inline constexpr double kGrazeDepth_m = 1e-10;
// Steps one prediction may take before it gives up and answers kNever.
inline constexpr int kMaxAdvanceSteps = 20000;

struct GapState {
  double gap_m = 0.0;      // clearance between the surfaces (negative: overlap)
  double rate_mps = 0.0;   // d gap / d tau
  double speed_mps = 0.0;  // bound on the relative speed of the two centres
};

struct AdvanceBounds {
  double start_s = 0.0;           // absolute time of tau = 0 (scales the smallest step)
  double tau_max_s = 0.0;         // look no further, s
  double accel_mps2 = 0.0;        // bound on the relative acceleration of the centres along the gap
  double centripetal_mps2 = 0.0;  // bound on the centripetal acceleration of spinning centres
  double reach_m = 0.0;           // disk-disk: sum of the radii (the distance curves by
                                  // |tangential speed|^2 / distance); disk-wall: 0
  double tolerance_m = 0.0;       // a gap this small counts as touching
};

// First tau in [0, tau_max] at which the gap is touching and closing, or kNever. `at(tau)`
// returns the GapState at tau. `steps`, if given, counts the calls made (for tests).
template <class GapAt>
double conservativeAdvance(const GapAt& at, const AdvanceBounds& bounds, int* steps = nullptr) {
  const bool pair = bounds.reach_m > 0.0;
  double tau = 0.0;
  // Floor on the step, doubled each time it binds: leaving a grazing contact costs a few dozen
  // steps instead of millions (a contact found after such a jump is late by under one step).
  double min_step = 1e-13 * std::max(1.0, bounds.start_s);
  for (int iteration = 0; iteration < kMaxAdvanceSteps && tau <= bounds.tau_max_s; ++iteration) {
    if (steps != nullptr) ++*steps;
    const GapState s = at(tau);
    if (s.gap_m <= bounds.tolerance_m && s.rate_mps < -kRoundingSpeed * s.speed_mps) return tau;
    // Over the next step the speed stays below twice its present bound (the step is capped so
    // that acceleration cannot add more), which bounds the curvature term.
    double curvature = bounds.accel_mps2 + bounds.centripetal_mps2;
    if (pair) curvature += 4.0 * s.speed_mps * s.speed_mps / (0.5 * bounds.reach_m);
    double h;
    if (curvature <= 0.0) {
      h = s.rate_mps < 0.0 ? (s.gap_m - bounds.tolerance_m) / -s.rate_mps : kNever;
    } else {
      // gap(tau + h) >= gap + rate h - curvature h^2 / 2: step to where that bound reaches zero
      // (from an overlap that is opening, to where the bound turns positive and back to zero).
      const double disc =
          s.rate_mps * s.rate_mps + 2.0 * curvature * (s.gap_m - bounds.tolerance_m);
      h = disc > 0.0 ? (s.rate_mps + std::sqrt(disc)) / curvature
                     : std::max(s.rate_mps, 0.0) / curvature;
    }
    if (bounds.accel_mps2 > 0.0) h = std::min(h, std::max(s.speed_mps, 1e-9) / bounds.accel_mps2);
    if (!std::isfinite(h)) return kNever;
    // A forced step may pass a contact, but never by more than kGrazeDepth_m: the gap falls at
    // most curvature h^2 / 2 below its linear bound over a step h.
    const double forced =
        curvature > 0.0 ? std::min(min_step, std::sqrt(2.0 * kGrazeDepth_m / curvature)) : min_step;
    if (h < forced) {
      h = forced;
      min_step *= 2.0;
    } else {
      // The safe step is the longer one. (Forcing the shorter one, once the floor had doubled
      // past the graze bound, crept on in graze-bound steps for good: 20,000 steps of 2.5e-5 s
      // that answered "never" with the gap still open, and missed any contact after them.)
      min_step = 1e-13 * std::max(1.0, bounds.start_s + tau);
    }
    tau += h;
  }
  return kNever;
}

}  // namespace collide::physics::detail
