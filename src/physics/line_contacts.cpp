// The 1D engine's rarer outcomes: perfectly inelastic impacts (merges, attachment to a wall),
// soft contacts, and the event records. See line_engine.hpp.
#include <string>

#include "physics/line_engine.hpp"
#include "physics/soft_contact.hpp"

namespace collide::physics::detail {

void LineEngine::specialWallImpact(bool left, double t, double u, double a_push,
                                   const ImpactDecision& d) {
  const int position = left ? 0 : static_cast<int>(order_.size()) - 1;
  const int id = order_[position];
  UnitState& unit = state_.units[id];
  const int body = left ? first_body_[id] : last_body_[id];
  const int wall = left ? left_wall_ : right_wall_;
  const double n = left ? 1.0 : -1.0;
  const double v = unit.v_mps.x(), m = unit.mass_kg, e = d.e;
  Impact impact = wallImpactRecord(t, body, wall, n, v, u, m, d);
  double v_after = v + (1.0 + e) * u * n;
  bool soft_done = false, attach = false;
  if (e > 0.0) {
    const SoftSide side{unit.x_ref_m, unit.v_mps, unit.a_mps2, 1.0 / m};
    const SoftSide wall_side{unit.x_ref_m, {0.0, 0.0}, {0.0, 0.0}, 0.0};
    SoftOutcome soft =
        resolveSoftContact(side, wall_side, {-n, 0.0}, e, model_.world.contact_duration_s, t);
    if (soft.resolved) {
      soft_done = true;
      impact.duration_s = soft.duration_s;
      unit.x_ref_m = soft.x_a_m;
      unit.v_mps = soft.v_a_mps;
      unit.t_ref_s = t + soft.duration_s;
      unit.track = soft.track_a;
      v_after = soft.v_a_mps.x();
      impact.lost_J = soft.record.energy_lost_measured_J;
      fileSoftContact(soft, body, impact.body_b, t);
    }
  } else {
    // e = 0: the normal velocity is removed. Unless gravity pulls it away, the unit now stays
    // against the wall for good (in 1D later contacts can only press it on), so it joins it.
    v_after = 0.0;
    attach = (friction_ ? pushAtRest(id, n) : a_push) >= 0.0;
  }
  if (!soft_done) {
    unit.v_mps.x() = v_after;
    impact.lost_J = impact.lost_analytic_J;
  }
  if (attach) {
    unit.attached = true;
    unit.a_mps2.setZero();
    unit.x_ref_m.x() = left ? left_x_ - left_m_[id] : right_x_ - right_m_[id];
  }
  impact.va_after = v_after;
  impact.impulse_Ns = m * std::abs(v_after - v);
  impact.merged = attach;
  state_.noteImpact(body, t, model_.collapse_window_s);
  if (out_.wants(state_.collision_count)) record(impact);
  finish(impact.lost_J, d, t);
  if (attach) {
    rebuild();  // inverse masses changed
  } else {
    refresh(position);
    refresh(position + 1);
  }
}

void LineEngine::specialPairImpact(int slot, double t, double u, const ImpactDecision& d) {
  if (d.e == 0.0) {
    merge(slot, t, u, d);
    return;
  }
  const int l = order_[slot - 1], r = order_[slot];
  UnitState &ul = state_.units[l], &ur = state_.units[r];
  const double inv_l = inverse_mass_[l], inv_r = inverse_mass_[r], m_eff = slot_mass_[slot];
  Impact impact;
  impact.t_s = t;
  impact.body_a = last_body_[l];
  impact.body_b = first_body_[r];
  impact.va_before = ul.v_mps.x();
  impact.vb_before = ur.v_mps.x();
  impact.closing_mps = u;
  impact.impulse_Ns = (1.0 + d.e) * u * m_eff;
  impact.decision = d;
  impact.lost_analytic_J = 0.5 * m_eff * (1.0 - d.e * d.e) * u * u;
  const SoftSide sl{ul.x_ref_m, ul.v_mps, ul.a_mps2, inv_l};
  const SoftSide sr{ur.x_ref_m, ur.v_mps, ur.a_mps2, inv_r};
  SoftOutcome soft =
      resolveSoftContact(sl, sr, {1.0, 0.0}, d.e, model_.world.contact_duration_s, t);
  if (soft.resolved) {
    impact.duration_s = soft.duration_s;
    if (inv_l != 0.0) {
      ul.x_ref_m = soft.x_a_m, ul.v_mps = soft.v_a_mps, ul.track = soft.track_a;
      ul.t_ref_s = t + soft.duration_s;
    }
    if (inv_r != 0.0) {
      ur.x_ref_m = soft.x_b_m, ur.v_mps = soft.v_b_mps, ur.track = soft.track_b;
      ur.t_ref_s = t + soft.duration_s;
    }
    impact.lost_J = soft.record.energy_lost_measured_J;
    fileSoftContact(soft, impact.body_a, impact.body_b, t);
  } else {
    ul.v_mps.x() -= impact.impulse_Ns * inv_l;
    ur.v_mps.x() += impact.impulse_Ns * inv_r;
    impact.lost_J = impact.lost_analytic_J;
  }
  impact.va_after = ul.v_mps.x();
  impact.vb_after = ur.v_mps.x();
  state_.noteImpact(impact.body_a, t, model_.collapse_window_s);
  state_.noteImpact(impact.body_b, t, model_.collapse_window_s);
  if (out_.wants(state_.collision_count)) record(impact);
  finish(impact.lost_J, d, t);
  refresh(slot - 1);
  refresh(slot);
  refresh(slot + 1);
}

// e = 0 between neighbours: they become one composite (attached if either side was).
void LineEngine::merge(int slot, double t, double u, const ImpactDecision& d) {
  const int l = order_[slot - 1], r = order_[slot];
  Impact impact;
  impact.t_s = t;
  impact.body_a = last_body_[l];
  impact.body_b = first_body_[r];
  impact.va_before = state_.units[l].v_mps.x();
  impact.vb_before = state_.units[r].v_mps.x();
  impact.closing_mps = u;
  impact.impulse_Ns = u * slot_mass_[slot];
  // From conservation of momentum: 1/2 mu u^2 (attached side: mu = the free unit's mass).
  impact.lost_J = impact.lost_analytic_J = 0.5 * slot_mass_[slot] * u * u;
  impact.merged = true;
  impact.decision = d;
  joinUnits(slot, t);
  impact.va_after = impact.vb_after = state_.units[l].v_mps.x();
  state_.noteImpact(impact.body_a, t, model_.collapse_window_s);
  state_.noteImpact(impact.body_b, t, model_.collapse_window_s);
  if (out_.wants(state_.collision_count)) record(impact);
  finish(impact.lost_J, d, t);
  rebuild();
}

// The units of a slot become one: the left unit's id survives, the right one dies. The caller
// rebuilds the tables.
void LineEngine::joinUnits(int slot, double t) {
  const int l = order_[slot - 1], r = order_[slot];
  UnitState &ul = state_.units[l], &ur = state_.units[r];
  const double vl = ul.v_mps.x(), vr = ur.v_mps.x();
  const double ml = ul.mass_kg, mr = ur.mass_kg;
  const bool attached = ul.attached || ur.attached;
  // Common velocity: total momentum over total mass. (vl - mr / (ml + mr) (vl - vr) cancels: with
  // 1e-6 kg at 1e4 m/s onto 1e9 kg at 1e-6 m/s its rounding, 1e-12 m/s, is 1e-3 kg m/s.)
  const double v = attached ? 0.0 : (ml * vl + mr * vr) / (ml + mr);
  // Place r exactly against l (removing any rounding gap), then re-centre on the joint centre
  // of mass; an attached side keeps its place.
  double xl = ul.x_ref_m.x(), xr = ur.x_ref_m.x();
  if (ur.attached) {
    xl = xr + left_m_[r] - right_m_[l];
  } else {
    xr = xl + right_m_[l] - left_m_[r];
  }
  const double x = (ml * xl + mr * xr) / (ml + mr);
  for (int k = rank_[first_body_[l]]; k <= rank_[last_body_[r]]; ++k) {
    BodyLink& link = state_.bodies[body_order_[k]];
    link.offset_m.x() += (link.unit == l ? xl : xr) - x;
    link.unit = l;
  }
  ul.mass_kg = ml + mr;
  ul.x_ref_m.x() = x;
  ul.v_mps.x() = v;
  ul.attached = attached;
  if (attached) ul.a_mps2.setZero();
  ul.t_ref_s = t;
  ur.alive = false;
}

void LineEngine::record(const Impact& impact) {
  CollisionEvent event;
  event.index = state_.collision_count;
  event.time_s = impact.t_s;
  event.body_a = impact.body_a;
  event.body_b = impact.body_b;
  event.restitution = impact.decision.e;
  event.restitution_requested = impact.decision.e_requested;
  event.collapse_rule = impact.decision.collapse;
  event.normal = {impact.normal_x, 0.0};
  event.velocity_a_before_mps = {impact.va_before, 0.0};
  event.velocity_a_after_mps = {impact.va_after, 0.0};
  event.velocity_b_before_mps = {impact.vb_before, 0.0};
  event.velocity_b_after_mps = {impact.vb_after, 0.0};
  event.closing_speed_mps = impact.closing_mps;
  event.impulse_Ns = impact.impulse_Ns;
  event.energy_lost_J = impact.lost_J;
  event.energy_lost_analytic_J = impact.lost_analytic_J;
  event.merged = impact.merged;
  event.contact_duration_s = impact.duration_s;
  splitGain(event);
  out_.emit(event);
}

void LineEngine::warnSuperElasticCap(double t, const ImpactDecision& d) {
  state_.super_elastic_warned = true;
  out_.warn({WarningKind::kSuperElasticCap, state_.collision_count, t,
             superElasticCapMessage(model_, state_.collision_count, t, d)});
}

void LineEngine::warnCollapse(double t, const ImpactDecision& d) {
  state_.collapse_warned = true;
  out_.warn({WarningKind::kCollapseRule, state_.collision_count, t,
             collapseMessage(model_, state_.collision_count, t, d)});
}

void LineEngine::fileSoftContact(SoftOutcome& soft, int body_a, int body_b, double t) {
  detail::fileSoftContact(out_, soft, state_.collision_count, body_a, body_b, t);
}

}  // namespace collide::physics::detail
