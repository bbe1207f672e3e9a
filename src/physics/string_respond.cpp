// The string engine's responses: impacts, merges, a string going slack or snapping taut
// (see string_engine.hpp and docs/physics.md, "Bodies on strings").
#include <algorithm>
#include <cmath>

#include "physics/string_engine.hpp"

namespace collide::physics::detail {
namespace {

// Angles within this of each other are one angle (rounding of the pendulum solution).
constexpr double kSameAngle_rad = 1e-9;

// The record of an impact against the string-aware response `impact` (a pair's second body's
// velocities are added by the caller; a wall's stay unset).
CollisionEvent impactEvent(double t, int body_a, int body_b, double e, const core::Vec2& normal,
                           double closing_mps, const core::Vec2& velocity_a_before_mps,
                           const StringImpact& impact) {
  CollisionEvent event;
  event.time_s = t;
  event.body_a = body_a;
  event.body_b = body_b;
  event.restitution = e;
  event.restitution_requested = e;
  event.normal = normal;
  event.velocity_a_before_mps = velocity_a_before_mps;
  event.velocity_a_after_mps = impact.velocity_a_mps;
  event.closing_speed_mps = closing_mps;
  event.impulse_Ns = impact.contact_impulse_Ns;
  event.energy_lost_J = impact.energy_lost_J;
  event.energy_lost_analytic_J = impact.energy_lost_J;
  return event;
}

// The record of two bodies that stuck together: both move on at `velocity_after_mps`.
CollisionEvent mergeEvent(double t, int body_a, int body_b, const core::Vec2& normal,
                          double closing_mps, const core::Vec2& velocity_a_before_mps,
                          const core::Vec2& velocity_b_before_mps,
                          const core::Vec2& velocity_after_mps, double impulse_Ns, double lost_J) {
  CollisionEvent event;
  event.time_s = t;
  event.body_a = body_a;
  event.body_b = body_b;
  event.restitution = 0.0;
  event.restitution_requested = 0.0;
  event.normal = normal;
  event.velocity_a_before_mps = velocity_a_before_mps;
  event.velocity_b_before_mps = velocity_b_before_mps;
  event.velocity_a_after_mps = velocity_after_mps;
  event.velocity_b_after_mps = velocity_after_mps;
  event.closing_speed_mps = closing_mps;
  event.impulse_Ns = impulse_Ns;
  event.energy_lost_J = lost_J;
  event.energy_lost_analytic_J = lost_J;
  event.merged = true;
  return event;
}

}  // namespace

ImpactPartner StringEngine::partner(int unit, double t) const {
  const Kin k = unitAt(unit, t);
  ImpactPartner p;
  p.inverse_mass_per_kg = 1.0 / state_.units[unit].mass_kg;
  p.velocity_mps = k.v;
  p.taut = taut(unit);
  if (p.taut) p.string_out = (k.x - state_.swings[unit].pivot_m).normalized();
  return p;
}

void StringEngine::restart(int unit, double t, const core::Vec2& x, const core::Vec2& v,
                           bool on_string) {
  UnitState& u = state_.units[unit];
  SwingState& swing = state_.swings[unit];
  u.t_ref_s = t;
  u.x_ref_m = x;
  u.v_mps = v;
  u.a_mps2 = model_.world.gravity_mps2;
  swing.taut = false;
  if (on_string && swing.has_string) {
    const PendulumState s = pendulumStateOf(x - swing.pivot_m, v);
    // The string holds only where it can pull: tension / m = L omega^2 + g cos(theta) >= 0.
    const double tension = swing.length_m * s.angular_velocity_rad_s * s.angular_velocity_rad_s +
                           gravity_m_s2_ * std::cos(s.angle_rad);
    if (tension >= 0.0) {
      swing.taut = true;
      swing.t_ref_s = t;
      swing.start = s;
    }
  }
  refreshArc(unit);
}

void StringEngine::pairImpact(int a, int b, double t) {
  const Kin ka = bodyAt(a, t), kb = bodyAt(b, t);
  const core::Vec2 n = (kb.x - ka.x).normalized();
  const double closing = n.dot(ka.v - kb.v);
  if (!(closing > 0.0)) return;  // rounding: nothing to resolve
  const double e0 = model_.pairRestitution(a, b);
  const double e = model_.applyLaw(e0, closing);
  // A contact that persists joins (or grows) a group (string_groups.cpp); any other impact on a
  // group parts it into its bodies, and the impact is theirs.
  if (e > 0.0 && joinsInStep(a, b, t)) {
    joinInStep(a, b, t, closing, n, e);
    return;
  }
  splitGroup(state_.bodies[a].unit, t);
  splitGroup(state_.bodies[b].unit, t);
  const int ua = state_.bodies[a].unit, ub = state_.bodies[b].unit;
  if (e == 0.0 && tryMerge(a, b, t, closing, n)) return;
  const StringImpact impact = resolveStringImpact(partner(ua, t), partner(ub, t), n, e);
  const Kin ca = unitAt(ua, t), cb = unitAt(ub, t);
  restart(ua, t, ca.x, impact.velocity_a_mps, impact.string_a_holds);
  restart(ub, t, cb.x, impact.velocity_b_mps, impact.string_b_holds);
  state_.energy_lost.add(impact.energy_lost_J);
  CollisionEvent event = impactEvent(t, a, b, e, n, closing, ka.v, impact);
  event.velocity_b_before_mps = kb.v;
  event.velocity_b_after_mps = impact.velocity_b_mps;
  record(event);
}

void StringEngine::wallImpact(int body, int wall, double t) {
  const int unit = state_.bodies[body].unit;
  const WallDef& w = model_.world.walls[wall];
  const Kin k = bodyAt(body, t);
  const core::Vec2 n = -w.normal;  // from the body into the wall
  const double closing = n.dot(k.v);
  if (!(closing > 0.0)) return;
  splitGroup(unit, t);
  if (state_.bodies[body].unit != unit) {
    wallImpact(body, wall, t);  // the body's own unit now
    return;
  }
  const double e = model_.applyLaw(w.restitution, closing);
  ImpactPartner wall_partner;  // infinite mass, at rest
  const StringImpact impact = resolveStringImpact(partner(unit, t), wall_partner, n, e);
  const Kin c = unitAt(unit, t);
  restart(unit, t, c.x, impact.velocity_a_mps, impact.string_a_holds);
  state_.energy_lost.add(impact.energy_lost_J);
  record(impactEvent(t, body, kWallPartnerBase - wall, e, n, closing, k.v, impact));
}

std::optional<StringEngine::MergeRoles> StringEngine::mergeRoles(int a, int b, double t) const {
  const int ua = state_.bodies[a].unit, ub = state_.bodies[b].unit;
  const SwingState &sa = state_.swings[ua], &sb = state_.swings[ub];
  MergeRoles roles;
  if (sa.taut != sb.taut && !(sa.taut ? sb : sa).has_string) {
    // A free body into a hanging one: the hanging one's string carries both.
    roles.host = sa.taut ? ua : ub;
    roles.guest = sa.taut ? ub : ua;
    roles.hit = sa.taut ? a : b;
    roles.hitter = sa.taut ? b : a;
    return roles;
  }
  if (sa.taut && sb.taut && std::abs(sa.length_m - sb.length_m) <= 1e-12 * sa.length_m) {
    // Two hanging bodies on strings of one length at one angle: their parallel strings carry
    // them as one.
    const Kin ca = unitAt(ua, t), cb = unitAt(ub, t);
    const double angle_a = std::atan2(ca.x.x() - sa.pivot_m.x(), sa.pivot_m.y() - ca.x.y());
    const double angle_b = std::atan2(cb.x.x() - sb.pivot_m.x(), sb.pivot_m.y() - cb.x.y());
    if (std::abs(angle_a - angle_b) > kSameAngle_rad) return std::nullopt;
    roles.host = ua;
    roles.guest = ub;
    return roles;
  }
  return std::nullopt;
}

core::Vec2 StringEngine::guestShift(const MergeRoles& roles, double t) const {
  // A smaller body hitting a hanging one ends inside it, just behind the face it hit.
  core::Vec2 shift = {0.0, 0.0};
  if (roles.hit >= 0) {
    const double r_hit = model_.half_size_m[roles.hit];
    const double r_hitter = model_.half_size_m[roles.hitter];
    const Kin k_hit = bodyAt(roles.hit, t), k_hitter = bodyAt(roles.hitter, t);
    const core::Vec2 inward = (k_hit.x - k_hitter.x).normalized();
    if (r_hitter < r_hit) shift = (k_hit.x - inward * (r_hit - r_hitter)) - k_hitter.x;
  }
  return shift;
}

void StringEngine::joinGuest(const MergeRoles& roles, const core::Vec2& host_x,
                             const core::Vec2& guest_x, const core::Vec2& shift,
                             const core::Vec2& centre, double mass) {
  const int host = roles.host, guest = roles.guest;
  for (BodyLink& link : state_.bodies) {
    if (link.unit == guest) {
      link.offset_m = guest_x + shift + link.offset_m - centre;
      link.unit = host;
    } else if (link.unit == host) {
      link.offset_m = host_x + link.offset_m - centre;
    }
  }
  state_.units[guest].alive = false;
  state_.units[host].mass_kg = mass;
}

bool StringEngine::tryMerge(int a, int b, double t, double closing, const core::Vec2& n) {
  // Which unit keeps its string (`host`) and which joins it (`guest`).
  const std::optional<MergeRoles> roles = mergeRoles(a, b, t);
  if (!roles) return false;
  record(merge(*roles, a, b, t, closing, n));
  return true;
}

CollisionEvent StringEngine::merge(const MergeRoles& roles, int a, int b, double t, double closing,
                                   const core::Vec2& n) {
  const int ua = state_.bodies[a].unit;
  const int host = roles.host, guest = roles.guest;
  const double m_host = state_.units[host].mass_kg, m_guest = state_.units[guest].mass_kg;
  const Kin c_host = unitAt(host, t), c_guest = unitAt(guest, t);
  const core::Vec2 shift = guestShift(roles, t);
  const double mass = m_host + m_guest;
  const core::Vec2 centre = (m_host * c_host.x + m_guest * (c_guest.x + shift)) / mass;
  // The joined unit translates as the host did, on its string's length: its centre of mass
  // moves on a circle of that length about the host's pivot moved by the step from the host's
  // centre to the joined one (a block on parallel strings carries what it caught that way).
  const SwingState& host_swing = state_.swings[host];
  const core::Vec2 pivot = host_swing.pivot_m + (centre - c_host.x);
  const double length = host_swing.length_m;
  // Momentum is kept but for what the string takes: the outward radial part (string pulling).
  const core::Vec2 momentum = m_host * c_host.v + m_guest * c_guest.v;
  const core::Vec2 out = (centre - pivot) / length;
  const double radial = std::max(momentum.dot(out), 0.0);
  const core::Vec2 velocity = (momentum - radial * out) / mass;
  // Loss: 1/2 mu |dv|^2 (the relative motion stopped) + the radial momentum's energy the string
  // took, less the potential energy of the guest's step into the host; no difference of large
  // kinetic energies.
  const double mu = m_host * m_guest / mass;
  const double lost = 0.5 * mu * (c_host.v - c_guest.v).squaredNorm() +
                      0.5 * radial * radial / mass + m_guest * model_.world.gravity_mps2.dot(shift);
  const core::Vec2 before_a = bodyAt(a, t).v, before_b = bodyAt(b, t).v;
  joinGuest(roles, c_host.x, c_guest.x, shift, centre, mass);
  SwingState& swing = state_.swings[host];
  swing.pivot_m = pivot;
  swing.length_m = length;
  restart(host, t, centre, velocity, true);
  arcs_[guest].reset();
  state_.swings[guest].taut = false;
  state_.swings[guest].has_string = false;
  state_.energy_lost.add(lost);
  // The impulse on a's unit, against the normal.
  const double impulse_Ns =
      (ua == host ? m_host : m_guest) * n.dot((ua == host ? c_host : c_guest).v - velocity);
  return mergeEvent(t, a, b, n, closing, before_a, before_b, velocity, impulse_Ns, lost);
}

void StringEngine::goSlack(int unit, double t) {
  const Kin k = unitAt(unit, t);
  restart(unit, t, k.x, k.v, false);
  ++state_.string_events;
  out_.emitString({t, unit, false, bodyAt(unit, t).x, k.v, k.v, 0.0});
}

void StringEngine::snapTaut(int unit, double t) {
  const Kin k = unitAt(unit, t);
  const SwingState& swing = state_.swings[unit];
  const StringJerk jerk = stringJerk(k.x - swing.pivot_m, k.v, model_.world.string_restitution);
  const double lost_J = state_.units[unit].mass_kg * jerk.energy_lost_per_mass_J_kg;
  state_.energy_lost.add(lost_J);
  // A string that bounces the body back inwards (restitution > 0) leaves it slack; otherwise it
  // holds wherever it can pull (a body barely moving along it included: rounding).
  const bool bounced = model_.world.string_restitution > 0.0 && k.v.dot(k.x - swing.pivot_m) > 0.0;
  restart(unit, t, k.x, jerk.velocity_m_s, !bounced);
  ++state_.string_events;
  out_.emitString({t, unit, true, bodyAt(unit, t).x, k.v, jerk.velocity_m_s, lost_J});
}

}  // namespace collide::physics::detail
