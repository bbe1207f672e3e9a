// 2D responses: impulses along the contact normal (smooth bodies: tangential components kept),
// resting on walls, stuck clusters, soft contacts, and the event records. See plane_engine.hpp.
#include <algorithm>
#include <cmath>
#include <string>

#include "physics/plane_engine.hpp"
#include "physics/soft_contact.hpp"

namespace collide::physics::detail {
namespace {

double cross(const core::Vec2& a, const core::Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Kinetic energy lost by one unit whose velocity and spin changed: 1/2 m (v - v').(v + v') plus
// the same for rotation, written as products of differences to avoid cancellation.
double unitLoss(double mass, double inertia, const core::Vec2& v, const core::Vec2& v_after,
                double omega, double omega_after) {
  return 0.5 * mass * (v - v_after).dot(v + v_after) +
         0.5 * inertia * (omega - omega_after) * (omega + omega_after);
}

}  // namespace

void PlaneEngine::updateAcceleration(UnitState& unit) const {
  // The walls a unit slides on can push but not pull: its acceleration is gravity projected onto
  // the cone {a : a.n >= 0 for every such wall n}. In the plane that projection is gravity
  // itself, gravity less its component into one wall, or zero (wedged). Projecting wall after
  // wall instead can leave an acceleration along the second wall that lifts the unit off the
  // first, which gains mechanical energy.
  const core::Vec2& g = model_.world.gravity_mps2;
  auto allowed = [&](const core::Vec2& a) {
    for (int w = 0; w < 32; ++w) {
      // 1e-12 m/s^2: rounding of the projection, far below any gravity a scene sets.
      if (((unit.resting_walls >> w) & 1u) && a.dot(model_.world.walls[w].normal) < -1e-12) {
        return false;
      }
    }
    return true;
  };
  if (allowed(g)) {
    unit.a_mps2 = g;
    return;
  }
  core::Vec2 best = core::Vec2::Zero();
  double best_distance = g.squaredNorm();
  for (int w = 0; w < 32; ++w) {
    if (!((unit.resting_walls >> w) & 1u)) continue;
    const core::Vec2& n = model_.world.walls[w].normal;
    const double into = g.dot(n);
    if (into >= 0.0) continue;
    const core::Vec2 candidate = g - into * n;
    const double distance = (g - candidate).squaredNorm();
    if (distance < best_distance && allowed(candidate)) {
      best = candidate;
      best_distance = distance;
    }
  }
  unit.a_mps2 = best;
}

// After its velocity changed a unit stays resting only on walls it still slides along (to
// rounding, which is then removed); a spinning unit rocks off them.
static void keepRestingWalls(const Model& model, UnitState& unit) {
  if (unit.omega_radps != 0.0) {
    unit.resting_walls = 0;
    return;
  }
  for (int w = 0; w < 32; ++w) {
    if (!((unit.resting_walls >> w) & 1u)) continue;
    const core::Vec2& n = model.world.walls[w].normal;
    const double normal = unit.v_mps.dot(n);
    if (std::abs(normal) <= 1e-12 * unit.v_mps.norm() + 1e-15) {
      unit.v_mps -= normal * n;
    } else {
      unit.resting_walls &= ~(1u << w);
    }
  }
}

core::Vec2 PlaneEngine::responseDirection(const UnitState& unit, double lever,
                                          const core::Vec2& direction,
                                          std::uint32_t& blocked) const {
  blocked = 0;
  if (unit.resting_walls == 0 || lever != 0.0 || unit.omega_radps != 0.0) return direction;
  core::Vec2 p = direction;
  for (int w = 0; w < 32; ++w) {
    if (!((unit.resting_walls >> w) & 1u)) continue;
    const core::Vec2& wn = model_.world.walls[w].normal;
    if (p.dot(wn) < 0.0) {
      p -= p.dot(wn) * wn;
      blocked |= 1u << w;
    }
  }
  for (int w = 0; w < 32; ++w) {
    if (((blocked >> w) & 1u) && p.dot(model_.world.walls[w].normal) < -1e-12) p.setZero();
  }
  return p;
}

PlaneEngine::PairResponse PlaneEngine::pairResponse(const UnitState& ua, const UnitState& ub,
                                                    const Kin& ka, const Kin& kb,
                                                    const core::Vec2& n) const {
  PairResponse r;
  // Lever arms of the normal impulse about each centre of mass: (arm + r n) x n = arm x n.
  r.ca = cross(ka.arm, n), r.cb = cross(kb.arm, n);
  // Velocity change of each side per unit impulse. A unit resting on walls cannot move into
  // them: the walls take the blocked part of the impulse (a unilateral constraint).
  r.pa = responseDirection(ua, r.ca, -n, r.blocked_a);
  r.pb = responseDirection(ub, r.cb, n, r.blocked_b);
  if (r.blocked_a != 0) r.ca = 0.0;
  if (r.blocked_b != 0) r.cb = 0.0;
  const double inv = (r.pb / ub.mass_kg - r.pa / ua.mass_kg).dot(n) +
                     (r.ca != 0.0 ? r.ca * r.ca / ua.inertia_kgm2 : 0.0) +
                     (r.cb != 0.0 ? r.cb * r.cb / ub.inertia_kgm2 : 0.0);
  r.m_eff = inv > 0.0 ? 1.0 / inv : 0.0;
  return r;
}

bool PlaneEngine::softPairImpact(int a, int b, double t, const core::Vec2& n, double e,
                                 CollisionEvent& event) {
  UnitState &ua = state_.units[state_.bodies[a].unit], &ub = state_.units[state_.bodies[b].unit];
  const core::Vec2 va = ua.v_mps, vb = ub.v_mps;
  const SoftSide sa{ua.x_ref_m, va, ua.a_mps2, 1.0 / ua.mass_kg};
  const SoftSide sb{ub.x_ref_m, vb, ub.a_mps2, 1.0 / ub.mass_kg};
  SoftOutcome soft = resolveSoftContact(sa, sb, n, e, model_.world.contact_duration_s, t);
  if (!soft.resolved) return false;
  ua.x_ref_m = soft.x_a_m, ua.v_mps = soft.v_a_mps, ua.track = soft.track_a;
  ub.x_ref_m = soft.x_b_m, ub.v_mps = soft.v_b_mps, ub.track = soft.track_b;
  ua.t_ref_s = ub.t_ref_s = t + soft.duration_s;
  event.contact_duration_s = soft.duration_s;
  event.energy_lost_J = soft.record.energy_lost_measured_J;
  event.impulse_Ns = ua.mass_kg * (va - ua.v_mps).norm();
  fileSoftContact(soft, a, b, t);
  return true;
}

void PlaneEngine::applyPairImpulse(UnitState& ua, UnitState& ub, const PairResponse& r,
                                   double impulse) const {
  ua.v_mps += impulse / ua.mass_kg * r.pa;
  ub.v_mps += impulse / ub.mass_kg * r.pb;
  if (r.ca != 0.0) ua.omega_radps -= impulse * r.ca / ua.inertia_kgm2;
  if (r.cb != 0.0) ub.omega_radps += impulse * r.cb / ub.inertia_kgm2;
  // Blocked walls: the unit keeps sliding exactly along them.
  for (auto [unit, blocked] : {std::pair{&ua, r.blocked_a}, std::pair{&ub, r.blocked_b}}) {
    for (int w = 0; w < 32; ++w) {
      if ((blocked >> w) & 1u) {
        const core::Vec2& wn = model_.world.walls[w].normal;
        unit->v_mps -= unit->v_mps.dot(wn) * wn;
      }
    }
  }
}

void PlaneEngine::noteRestingOnDisk(int a, int b, const Kin& ka, const Kin& kb, const core::Vec2& n,
                                    double e, double a_push) {
  const UnitState &ua = state_.units[state_.bodies[a].unit],
                  &ub = state_.units[state_.bodies[b].unit];
  if (e == 0.0 && a_push > 0.0 &&
      std::abs((ua.v_mps - ub.v_mps).dot(n)) <= a_push * model_.world.collapse_time_s) {
    // Upper: the one further against gravity.
    const bool b_above = (kb.x - ka.x).dot(model_.world.gravity_mps2) < 0.0;
    resting_upper_ = b_above ? b : a;
    resting_lower_ = b_above ? a : b;
  }
}

void PlaneEngine::pairImpact(int a, int b, double t) {
  const int id_a = state_.bodies[a].unit, id_b = state_.bodies[b].unit;
  advanceUnit(id_a, t);
  advanceUnit(id_b, t);
  UnitState &ua = state_.units[id_a], &ub = state_.units[id_b];
  const Kin ka = kinematics(a, t), kb = kinematics(b, t);
  const core::Vec2 d = kb.x - ka.x;
  const double distance = d.norm();
  const core::Vec2 n = distance > 0.0 ? core::Vec2(d / distance) : core::Vec2(1.0, 0.0);
  const double u = std::max((ka.v - kb.v).dot(n), 0.0);
  const double a_push = pairPush(ua, ub, ka, kb, n);
  const double window = model_.collapse_window_s;
  const ImpactDecision decision =
      decideRestitution(model_, model_.pairRestitution(a, b), u, state_.burstAt(a, t, window),
                        state_.burstAt(b, t, window), a_push, a, b);
  const double e = decision.e;
  state_.noteImpact(a, t, window);
  state_.noteImpact(b, t, window);
  noteClustering(a, t, decision);
  noteClustering(b, t, decision);
  if (e == 0.0 && model_.world.inelastic_mode == InelasticMode::kStick) {
    stick(a, b, t, u, decision, n);
    return;
  }
  const PairResponse response = pairResponse(ua, ub, ka, kb, n);
  CollisionEvent event;
  event.body_a = a;
  event.body_b = b;
  event.normal = n;
  event.velocity_a_before_mps = ka.v;
  event.velocity_b_before_mps = kb.v;
  event.closing_speed_mps = u;
  event.energy_lost_analytic_J = 0.5 * response.m_eff * (1.0 - e * e) * u * u;
  const bool inside_done =
      !state_.internal_J.empty() && exchangeWithInsides(a, b, response, n, event);
  const bool soft_done = !inside_done && e > 0.0 &&
                         model_.world.contact_model == ContactModel::kSpringDamper &&
                         response.ca == 0.0 && response.cb == 0.0 && ua.omega_radps == 0.0 &&
                         ub.omega_radps == 0.0 && softPairImpact(a, b, t, n, e, event);
  if (!soft_done && !inside_done) {
    const double impulse = (1.0 + e) * u * response.m_eff;
    applyPairImpulse(ua, ub, response, impulse);
    event.impulse_Ns = impulse;
    event.energy_lost_J = event.energy_lost_analytic_J;
  }
  for (UnitState* unit : {&ua, &ub}) {
    if (unit->resting_walls != 0) {
      keepRestingWalls(model_, *unit);
      updateAcceleration(*unit);
    }
  }
  // A disk pressed onto another by gravity with nothing left of the approach would rest on it:
  // continuous rolling contact, beyond an event-driven model. Stop rather than loop.
  noteRestingOnDisk(a, b, ka, kb, n, e, a_push);
  const double t_after = std::max(ua.t_ref_s, ub.t_ref_s);
  event.velocity_a_after_mps = kinematics(a, t_after).v;
  event.velocity_b_after_mps = kinematics(b, t_after).v;
  event.restitution = e;
  event.time_s = t;
  renew(id_a);
  renew(id_b);
  predictUnit(id_a, -1);
  predictUnit(id_b, id_a);
  finish(event, decision);
}

void PlaneEngine::settleOnWall(UnitState& unit, int wall) const {
  // Nothing left of the rebound and nothing pulling the unit away: it slides along the wall
  // from now on (a cluster caught by the collapse rule also stops spinning, settling on it).
  const core::Vec2& normal = model_.world.walls[wall].normal;
  unit.v_mps -= unit.v_mps.dot(normal) * normal;
  unit.omega_radps = 0.0;
  unit.resting_walls |= 1u << wall;
  keepRestingWalls(model_, unit);
  updateAcceleration(unit);
}

bool PlaneEngine::softWallImpact(int body, int wall, double t, double e, CollisionEvent& event) {
  UnitState& unit = state_.units[state_.bodies[body].unit];
  const core::Vec2& normal = model_.world.walls[wall].normal;
  const SoftSide side{unit.x_ref_m, unit.v_mps, unit.a_mps2, 1.0 / unit.mass_kg};
  const SoftSide wall_side{unit.x_ref_m, {0.0, 0.0}, {0.0, 0.0}, 0.0};
  SoftOutcome soft =
      resolveSoftContact(side, wall_side, -normal, e, model_.world.contact_duration_s, t);
  if (!soft.resolved) return false;
  unit.x_ref_m = soft.x_a_m, unit.v_mps = soft.v_a_mps, unit.track = soft.track_a;
  unit.t_ref_s = t + soft.duration_s;
  event.contact_duration_s = soft.duration_s;
  event.energy_lost_J = soft.record.energy_lost_measured_J;
  fileSoftContact(soft, body, event.body_b, t);
  return true;
}

void PlaneEngine::applyWallImpulse(UnitState& unit, const core::Vec2& normal, double lever,
                                   double e, double u, double m_eff) {
  if (lever == 0.0) {
    // Through the centre the velocity changes by exactly (1 + e) u along the normal. Going through
    // impulse / m with m_eff = 1 / (1 / m) instead leaves rounding of u (e = 0: an approach of
    // 2e-16 u), which replays the impact at the same instant, 1e-16 smaller each time, until the
    // speed underflows.
    unit.v_mps += (1.0 + e) * u * normal;
  } else {
    const double impulse = (1.0 + e) * u * m_eff;
    unit.v_mps += impulse / unit.mass_kg * normal;
    unit.omega_radps += impulse * lever / unit.inertia_kgm2;
  }
}

void PlaneEngine::wallImpact(int body, int wall, double t) {
  const int id = state_.bodies[body].unit;
  advanceUnit(id, t);
  UnitState& unit = state_.units[id];
  const WallDef& w = model_.world.walls[wall];
  const Kin k = kinematics(body, t);
  const double u = std::max(-k.v.dot(w.normal), 0.0);
  const double a_push = -unit.a_mps2.dot(w.normal);
  const std::int32_t burst = state_.burstAt(body, t, model_.collapse_window_s);
  const ImpactDecision decision = decideRestitution(model_, w.restitution, u, burst, burst, a_push,
                                                    body, kWallPartnerBase - wall);
  const double e = decision.e;
  // A second perfectly inelastic wall impact of this disk within t_c: a spinning cluster
  // chattering against the wall (each impulse stops the contact point, the spin brings it back
  // at rounding-level speeds, every 1e-13 s or so). The collapse guard settles it like a cluster
  // the rule made inelastic.
  const bool chattering = t - state_.last_impact_s[body] < model_.world.collapse_time_s;
  state_.noteImpact(body, t, model_.collapse_window_s);
  const double c = cross(k.arm, w.normal);
  const double m_eff = 1.0 / (1.0 / unit.mass_kg + (c != 0.0 ? c * c / unit.inertia_kgm2 : 0.0));
  CollisionEvent event;
  event.body_a = body;
  event.body_b = kWallPartnerBase - wall;
  event.normal = -w.normal;
  event.velocity_a_before_mps = k.v;
  event.closing_speed_mps = u;
  event.energy_lost_analytic_J = 0.5 * m_eff * (1.0 - e * e) * u * u;
  const core::Vec2 v = unit.v_mps;
  const double omega = unit.omega_radps;
  const bool rigid_line = c == 0.0 && omega == 0.0;  // the impulse passes through the centre
  bool done = false;
  if (e == 0.0 && a_push >= 0.0 && (rigid_line || decision.collapse || chattering) && wall < 32) {
    settleOnWall(unit, wall);
    event.merged = true;
    done = true;
  } else if (e > 0.0 && model_.world.contact_model == ContactModel::kSpringDamper && rigid_line) {
    done = softWallImpact(body, wall, t, e, event);
  }
  if (!done) applyWallImpulse(unit, w.normal, c, e, u, m_eff);
  if (event.merged) {
    // Settling on the wall also stops the spin: booked as what the unit lost, a sum of
    // non-negative products of differences.
    event.energy_lost_J =
        unitLoss(unit.mass_kg, unit.inertia_kgm2, v, unit.v_mps, omega, unit.omega_radps);
  } else if (event.contact_duration_s == 0.0) {
    event.energy_lost_J = event.energy_lost_analytic_J;
  }
  event.impulse_Ns = unit.mass_kg * (unit.v_mps - v).norm();
  if (unit.resting_walls != 0 && !event.merged) {
    keepRestingWalls(model_, unit);
    updateAcceleration(unit);
  }
  event.velocity_a_after_mps = kinematics(body, unit.t_ref_s).v;
  event.restitution = e;
  event.time_s = t;
  renew(id);
  predictUnit(id, -1);
  finish(event, decision);
}

// Perfectly inelastic 2D impact in stick mode: the two units become one rigid cluster with the
// same momentum and the same angular momentum about the joint centre of mass.
void PlaneEngine::stick(int a, int b, double t, double u, const ImpactDecision& d,
                        const core::Vec2& n) {
  const int id_a = state_.bodies[a].unit, id_b = state_.bodies[b].unit;
  const int keep = std::min(id_a, id_b), gone = std::max(id_a, id_b);
  drop_grid_ = grid_;  // clusters are not filed in the grid: all pairs from the next event on
  CollisionEvent event;
  event.body_a = a;
  event.body_b = b;
  event.normal = n;
  event.velocity_a_before_mps = kinematics(a, t).v;
  event.velocity_b_before_mps = kinematics(b, t).v;
  event.closing_speed_mps = u;
  const UnitState p = state_.units[id_a], q = state_.units[id_b];
  const double m = p.mass_kg + q.mass_kg;
  const core::Vec2 x = (p.mass_kg * p.x_ref_m + q.mass_kg * q.x_ref_m) / m;
  const core::Vec2 v = (p.mass_kg * p.v_mps + q.mass_kg * q.v_mps) / m;
  const core::Vec2 rp = p.x_ref_m - x, rq = q.x_ref_m - x;
  const double angular = p.inertia_kgm2 * p.omega_radps + p.mass_kg * cross(rp, p.v_mps) +
                         q.inertia_kgm2 * q.omega_radps + q.mass_kg * cross(rq, q.v_mps);
  const double inertia =
      p.inertia_kgm2 + p.mass_kg * rp.squaredNorm() + q.inertia_kgm2 + q.mass_kg * rq.squaredNorm();
  const double omega = angular / inertia;
  // Re-express every member in the new cluster frame (angle 0 now).
  for (int id : {id_a, id_b}) {
    const UnitState& old = state_.units[id];
    for (int body : members_[id]) {
      BodyLink& link = state_.bodies[body];
      const double c = std::cos(old.angle_ref_rad), s = std::sin(old.angle_ref_rad);
      const core::Vec2 arm(c * link.offset_m.x() - s * link.offset_m.y(),
                           s * link.offset_m.x() + c * link.offset_m.y());
      link.offset_m = arm + old.x_ref_m - x;
      link.angle_offset_rad += old.angle_ref_rad;
      link.unit = keep;
    }
  }
  // Energy: 1/2 mu |dv|^2 of the relative translation plus the spins, less the cluster's spin.
  const double mu = p.mass_kg * q.mass_kg / m;
  const double lost = 0.5 * mu * (p.v_mps - q.v_mps).squaredNorm() +
                      0.5 * p.inertia_kgm2 * p.omega_radps * p.omega_radps +
                      0.5 * q.inertia_kgm2 * q.omega_radps * q.omega_radps -
                      0.5 * inertia * omega * omega;
  UnitState& merged = state_.units[keep];
  merged = UnitState{};
  merged.t_ref_s = t;
  merged.x_ref_m = x;
  merged.v_mps = v;
  merged.omega_radps = omega;
  merged.mass_kg = m;
  merged.inertia_kgm2 = inertia;
  updateAcceleration(merged);
  state_.units[gone].alive = false;
  members_[keep].insert(members_[keep].end(), members_[gone].begin(), members_[gone].end());
  std::sort(members_[keep].begin(), members_[keep].end());
  members_[gone].clear();
  renew(keep);
  version_[gone] = ++last_stamp_;
  predictUnit(keep, -1);
  event.velocity_a_after_mps = kinematics(a, t).v;
  event.velocity_b_after_mps = kinematics(b, t).v;
  event.energy_lost_J = lost;
  event.energy_lost_analytic_J = lost;
  event.impulse_Ns = mu * u;
  event.merged = true;
  event.restitution = 0.0;
  event.time_s = t;
  finish(event, d);
}

void PlaneEngine::finish(const CollisionEvent& recorded, const ImpactDecision& d) {
  state_.book(recorded.energy_lost_J);
  if (d.capped && !state_.super_elastic_warned) {
    state_.super_elastic_warned = true;
    out_.warn({WarningKind::kSuperElasticCap, state_.collision_count, recorded.time_s,
               superElasticCapMessage(model_, state_.collision_count, recorded.time_s, d)});
  }
  if (d.collapse && !d.resting && !state_.collapse_warned) {
    state_.collapse_warned = true;
    out_.warn({WarningKind::kCollapseRule, state_.collision_count, recorded.time_s,
               collapseMessage(model_, state_.collision_count, recorded.time_s, d)});
  }
  if (out_.wants(state_.collision_count)) {
    CollisionEvent event = recorded;
    event.index = state_.collision_count;
    event.restitution_requested = d.e_requested;
    event.collapse_rule = d.collapse;
    splitGain(event);
    out_.emit(event);
  }
  ++state_.collision_count;
}

void PlaneEngine::fileSoftContact(SoftOutcome& soft, int body_a, int body_b, double t) {
  detail::fileSoftContact(out_, soft, state_.collision_count, body_a, body_b, t);
}

}  // namespace collide::physics::detail
