#pragma once
// The restitution actually applied at one impact: the pair's or wall's e0 through the restitution
// law, then the collapse rule (TC model) that keeps every run finite.
#include <cstdio>
#include <string>

#include "physics/engine.hpp"

namespace collide::physics::detail {

inline constexpr double kRestHeight_m = 1e-10;

struct ImpactDecision {
  double e_requested = 1.0;  // from e0 and the law
  double e = 1.0;            // applied
  bool collapse = false;     // the collapse rule set e = 0
};

// u_mps: normal closing speed (>= 0). last_a_s, last_b_s: previous impact times of the two
// bodies (a wall passes t_s: only the body's own history counts). a_push_mps2: acceleration
// pressing a body onto an immovable partner (wall, attached unit), 0 between free bodies.
inline ImpactDecision decideRestitution(const Model& model, double e0, double u_mps, double t_s,
                                        double last_a_s, double last_b_s, double a_push_mps2) {
  ImpactDecision d;
  d.e_requested = model.applyLaw(e0, u_mps);
  d.e = d.e_requested;
  const double tc = model.world.collapse_time_s;
  if (d.e <= 0.0) return d;
  // Collisions in rapid succession (both partners hit something less than t_c ago) are what an
  // inelastic collapse is made of: make them perfectly inelastic so that bodies merge or stop.
  const bool rapid = d.e < 1.0 && tc > 0.0 && t_s - last_a_s < tc && t_s - last_b_s < tc;
  // A rebound under a pushing acceleration would fly 2 e u / a: shorter than t_c, the body rests
  // (this also ends the infinite bounce series of a ball with e < 1 in a finite time).
  // Likewise a rebound lower than kRestHeight_m: below that, positions are rounding noise and the
  // bounces would never die out.
  const double rebound = d.e * u_mps;
  const bool resting =
      a_push_mps2 > 0.0 &&
      (2.0 * rebound <= a_push_mps2 * tc || rebound * rebound <= 2.0 * a_push_mps2 * kRestHeight_m);
  if (rapid || resting) {
    d.e = 0.0;
    d.collapse = true;
  }
  return d;
}

// The warning for the first impact the collapse rule made inelastic.
inline std::string collapseMessage(std::int64_t index) {
  char text[160];
  std::snprintf(text, sizeof text,
                "collision %lld came too soon after the previous ones and was made perfectly "
                "inelastic (collapse guard)",
                static_cast<long long>(index));
  return text;
}

}  // namespace collide::physics::detail
