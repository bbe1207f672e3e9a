// SPDX-License-Identifier: MIT
// Contacts that persist between bodies on strings (docs/physics.md, "Swinging together").
//
// Two bodies on taut strings of one length at one angle follow one pendulum motion each, the same
// one: in step they stay in step, touching with no force between them, for ever. A cradle with
// e < 1 comes into step only in the limit of an endless sequence of ever smaller impacts (each
// rebound parts the two by about e u / omega0 and they meet again half a swing later at about
// the speed they parted). Once the energy of their relative motion, 1/2 mu |v_a - v_b|^2, is
// below kTieUlps units of rounding of the pair's energy at the scene's speed scale, no later
// impact of that sequence could change any energy the run holds or reports: the impact ends the
// sequence at its limit instead. The two go on as one group (momentum kept, that energy booked as
// lost, the impact recorded with e = 0 applied and the collapse flag). A group is no stuck
// body: struck, it parts into its bodies and the impact is theirs, pair by pair as ever.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "physics/string_engine.hpp"

namespace collide::physics::detail {
namespace {

// Strings of one length, to rounding.
constexpr double kSameLength = 1e-12;

}  // namespace

bool StringEngine::joinable(int unit) const {
  if (state_.swings[unit].group) return true;
  int bodies = 0;
  for (const BodyLink& link : state_.bodies) bodies += link.unit == unit ? 1 : 0;
  return bodies == 1;  // a unit stuck together at e = 0 never parts, so joins no group
}

bool StringEngine::onCircleGently(int unit, double t, double floor_J) const {
  const SwingState& swing = state_.swings[unit];
  if (swing.taut) return true;
  // A string that bounces (string_restitution > 0) would throw the body back: no moment's slack.
  if (!swing.has_string || model_.world.string_restitution > 0.0) return false;
  const Kin k = unitAt(unit, t);
  const core::Vec2 r = k.x - swing.pivot_m;
  const double radial_mps = k.v.dot(r) / r.norm();
  return std::abs(r.norm() - swing.length_m) <= kSameLength * swing.length_m &&
         0.5 * state_.units[unit].mass_kg * radial_mps * radial_mps <= floor_J;
}

bool StringEngine::joinsInStep(int a, int b, double t) const {
  const int ua = state_.bodies[a].unit, ub = state_.bodies[b].unit;
  if (ua == ub || !joinable(ua) || !joinable(ub)) return false;
  const SwingState &sa = state_.swings[ua], &sb = state_.swings[ub];
  if (!sa.has_string || !sb.has_string) return false;
  const double length = sa.length_m;
  if (std::abs(length - sb.length_m) > kSameLength * length) return false;
  const Kin ka = unitAt(ua, t), kb = unitAt(ub, t);
  const core::Vec2 ra = ka.x - sa.pivot_m, rb = kb.x - sb.pivot_m;
  // One angle to what the contact search counts as touching (a gap of 1e-12 m, or of 1e-12 of
  // the radii) seen from the length of the strings.
  const double reach = model_.half_size_m[a] + model_.half_size_m[b];
  const double same_angle = 8.0 * 1e-12 * std::max(1.0, reach) / length;
  const double angle = std::atan2(ra.x() * rb.y() - ra.y() * rb.x(), ra.dot(rb));
  if (std::abs(angle) > same_angle) return false;
  const double ma = state_.units[ua].mass_kg, mb = state_.units[ub].mass_kg;
  const double v = model_.speed_scale_mps;
  const double floor_J =
      kTieUlps * std::numeric_limits<double>::epsilon() * 0.5 * (ma + mb) * v * v;
  const double relative_J = 0.5 * (ma * mb / (ma + mb)) * (ka.v - kb.v).squaredNorm();
  // A string slack for a moment (an impact off the bottom pushed its body inwards by a radial
  // speed whose energy is below the floor too) is taken as snapping taut at once.
  return relative_J <= floor_J && onCircleGently(ua, t, floor_J) && onCircleGently(ub, t, floor_J);
}

void StringEngine::joinInStep(int a, int b, double t, double closing, const core::Vec2& n,
                              double e) {
  const int host = state_.bodies[a].unit, guest = state_.bodies[b].unit;
  // The jerks that end the slack moments, booked as every jerk (string_respond.cpp).
  if (!taut(host)) snapTaut(host, t);
  if (!taut(guest)) snapTaut(guest, t);
  MergeRoles roles;
  roles.host = host;
  roles.guest = guest;
  CollisionEvent event = merge(roles, a, b, t, closing, n);
  state_.swings[host].group = true;
  state_.swings[guest].group = false;
  event.merged = false;  // a group parts again; the picture draws no bond
  event.collapse_rule = true;
  event.restitution_requested = e;
  record(event);
}

void StringEngine::splitGroup(int unit, double t) {
  if (!state_.swings[unit].group) return;
  const Kin k = unitAt(unit, t);
  const bool taut_now = taut(unit);
  const std::vector<SwingState> own = initialSwings(model_);
  for (int body = 0; body < static_cast<int>(state_.bodies.size()); ++body) {
    if (state_.bodies[body].unit != unit) continue;
    // Units are numbered as the bodies they started as: a group's body gets its own back.
    const core::Vec2 x = k.x + state_.bodies[body].offset_m;
    state_.bodies[body] = BodyLink{body, {0.0, 0.0}, 0.0};
    UnitState& u = state_.units[body];
    u.alive = true;
    u.mass_kg = model_.world.bodies[body].mass_kg;
    state_.swings[body] = own[body];
    restart(body, t, x, k.v, taut_now);
  }
}

}  // namespace collide::physics::detail
