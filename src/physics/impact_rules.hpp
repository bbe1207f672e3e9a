#pragma once
// The restitution actually applied at one impact: the pair's or wall's e0 through the restitution
// law, then the collapse rule (TC model) that keeps every run finite.
#include <algorithm>
#include <cstdio>
#include <string>

#include "physics/engine.hpp"

namespace collide::physics::detail {

inline constexpr double kRestHeight_m = 1e-10;

// Impacts a body must have had in one burst (each within Model::collapse_window_s of the one
// before) before the collapse guard calls it an inelastic collapse. A row of 8 touching equal
// blocks at e = 0.1 struck at one end settles after about 1,300 impacts in all at one instant,
// under 400 per block; a true collapse (three bodies at small e, or a long row) goes on without
// end, so the count is reached only there.
inline constexpr std::int32_t kCollapseBurstImpacts = 10000;

// Impacts at a restitution below 1 that one disk may have within the scene's own time scale (the
// fastest body crossing the smallest one: a disk of a gas meets a few others in that time)
// before the clustering guard stops the run. Disks that cool at e < 1 gather into clusters
// whose collisions come ever faster at one place while time hardly advances (an inelastic
// collapse spread over many bodies): ideal-gas with 1000 disks at e = 0.5 ran on to the cap of
// max_collisions. Making those impacts perfectly inelastic only starts new ones between the
// cluster's neighbours; the run is stopped instead, and says why.
inline constexpr std::int32_t kClusterImpacts = 20000;

// A super-elastic impact (e > 1) multiplies the closing speed by e: between walls the speeds
// would grow without bound, ever faster, until they overflow. Impacts closing faster than this
// many times the scene's speed scale (its starting speeds, gravity's and its releases') are made
// elastic instead, and a warning says so once.
inline constexpr double kSuperElasticSpeedCap = 1000.0;

struct ImpactDecision {
  double e_requested = 1.0;    // from e0 and the law
  double e = 1.0;              // applied
  bool collapse = false;       // the collapse rule set e = 0
  bool resting = false;        // ... because the rebound was too small to fly (else: a burst)
  bool capped = false;         // a super-elastic impact made elastic by kSuperElasticSpeedCap
  double closing_mps = 0.0;    // u, for the warnings
  int body_a = 0, body_b = 0;  // as in CollisionEvent, for the warning
};

// u_mps: normal closing speed (>= 0). burst_a, burst_b: the partners' burst counts including this
// impact (EngineState::burstAt; a wall passes the body's own twice). a_push_mps2: acceleration
// pressing a body onto an immovable partner (wall, attached unit), 0 between free bodies.
inline ImpactDecision decideRestitution(const Model& model, double e0, double u_mps,
                                        std::int32_t burst_a, std::int32_t burst_b,
                                        double a_push_mps2, int body_a, int body_b) {
  ImpactDecision d;
  d.body_a = body_a;
  d.body_b = body_b;
  d.closing_mps = u_mps;
  d.e_requested = model.applyLaw(e0, u_mps);
  d.e = d.e_requested;
  if (d.e > 1.0 && u_mps > kSuperElasticSpeedCap * model.speed_scale_mps) {
    d.e = 1.0;
    d.capped = true;
  }
  const double tc = model.world.collapse_time_s;
  if (d.e <= 0.0 || tc <= 0.0) return d;
  // An inelastic collapse: impacts of the same bodies without end, ever closer together. Only
  // when both partners are deep in such a burst is the impact made perfectly inelastic, so that
  // they merge (1D) or stop approaching (2D) and the burst ends.
  const bool collapsing = d.e < 1.0 && std::min(burst_a, burst_b) >= kCollapseBurstImpacts;
  // A rebound under a pushing acceleration would fly 2 e u / a: shorter than t_c, the body rests
  // (this also ends the infinite bounce series of a ball with e < 1 in a finite time).
  // Likewise a rebound lower than kRestHeight_m: below that, positions are rounding noise and the
  // bounces would never die out.
  const double rebound = d.e * u_mps;
  const bool resting =
      a_push_mps2 > 0.0 &&
      (2.0 * rebound <= a_push_mps2 * tc || rebound * rebound <= 2.0 * a_push_mps2 * kRestHeight_m);
  if (collapsing || resting) {
    d.e = 0.0;
    d.collapse = true;
    d.resting = !collapsing;
  }
  return d;
}

// The warning for the first impact the collapse rule made inelastic, naming the partners.
inline std::string collapseMessage(const Model& model, std::int64_t index, double t_s,
                                   const ImpactDecision& d) {
  const WorldDef& world = model.world;
  const std::string a = "\"" + world.bodies[d.body_a].name + "\"";
  const std::string b = d.body_b >= 0
                            ? "\"" + world.bodies[d.body_b].name + "\""
                            : "wall \"" + world.walls[kWallPartnerBase - d.body_b].name + "\"";
  char text[700];
  if (d.resting) {
    std::snprintf(text, sizeof text,
                  "collision %lld at t = %.9g s between %s and %s was made perfectly inelastic by "
                  "the collapse guard: the rebound would have flown for less than the collapse "
                  "time (%.3g s), so the body rests",
                  static_cast<long long>(index), t_s, a.c_str(), b.c_str(), world.collapse_time_s);
  } else {
    std::snprintf(text, sizeof text,
                  "collision %lld at t = %.9g s between %s and %s was made perfectly inelastic by "
                  "the collapse guard: both had %d or more impacts each within %.3g s of the last "
                  "(an inelastic collapse, impacts without end)",
                  static_cast<long long>(index), t_s, a.c_str(), b.c_str(),
                  static_cast<int>(kCollapseBurstImpacts), model.collapse_window_s);
  }
  return text;
}

// The warning for the first super-elastic impact the speed cap made elastic.
inline std::string superElasticCapMessage(const Model& model, std::int64_t index, double t_s,
                                          const ImpactDecision& d) {
  const WorldDef& world = model.world;
  const std::string b = d.body_b >= 0
                            ? "\"" + world.bodies[d.body_b].name + "\""
                            : "wall \"" + world.walls[kWallPartnerBase - d.body_b].name + "\"";
  char text[600];
  std::snprintf(
      text, sizeof text,
      "collision %lld at t = %.9g s between \"%s\" and %s closed at %.3g m/s, more than "
      "%.0f times the scene's speed scale (%.3g m/s): it and later such impacts were made "
      "elastic instead of e = %.3g, so that the speeds stay finite",
      static_cast<long long>(index), t_s, world.bodies[d.body_a].name.c_str(), b.c_str(),
      d.closing_mps, kSuperElasticSpeedCap, model.speed_scale_mps, d.e_requested);
  return text;
}

}  // namespace collide::physics::detail
