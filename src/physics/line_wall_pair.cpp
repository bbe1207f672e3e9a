// SPDX-License-Identifier: MIT
// The 1D engine's loop for two elastic bodies and one wall, no gravity (pi-blocks: 314 million
// impacts for 9 digits). Every event of such a run goes through it, recorded or not, so a run,
// its replays from checkpoints and its recorded events all take the same arithmetic.
//
// What makes it faster than the general loop is the order of the work, not shortcuts: each unit's
// position is carried along the axis pointing away from the wall (y = x for a wall on the left,
// y = -x on the right, both exact), and at every event both units move on by the predicted time
// of flight tau itself, not by a difference of absolute times. So the chain from one impact to
// the next is "gap -> tau = gap * (1 / closing) -> positions", and the reciprocal of the closing
// speed depends on the velocities alone (which evolve independently of the positions), so the
// processor computes it ahead. The velocities are updated exactly as the general loop updates
// them (line_engine.cpp: wallImpact, pairImpact), so the sequence of impacts, the counts and the
// velocities are the same bits; times and positions agree with the general loop to round-off
// (tau is a product with a reciprocal, one rounding more than a quotient), and unlike the general
// loop's they keep moving when the impacts come closer together than the rounding of t.
//
// Every prediction is a pure function of the units' states (engine.hpp), so a run entered afresh
// from a checkpoint predicts what the run that passed through it predicted. What this loop does
// not handle (the two slots due in one round) goes to the general loop for that round.
#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/line_engine.hpp"
#include "physics/toi.hpp"

namespace collide::physics::detail {

bool LineEngine::wallPairApplies() const {
  return two_bodies_ && (left_wall_ >= 0) != (right_wall_ >= 0);
}

struct LineEngine::WallPairRun {
  explicit WallPairRun(LineEngine& e)
      : engine(e),
        model(e.model_),
        left(e.left_wall_ >= 0),
        near_id(left ? e.order_[0] : e.order_[1]),
        far_id(left ? e.order_[1] : e.order_[0]),
        body_near(e.first_body_[near_id]),
        body_far(e.first_body_[far_id]),
        wall(left ? e.left_wall_ : e.right_wall_),
        wall_slot(left ? 0 : 2),
        contact_y(flip(left ? e.left_x_ : e.right_x_) -
                  flip(left ? e.left_m_[near_id] : e.right_m_[near_id])),
        span_y(flip(left ? e.right_m_[near_id] : e.left_m_[near_id]) -
               flip(left ? e.left_m_[far_id] : e.right_m_[far_id])),
        inv_near(e.inverse_mass_[near_id]),
        inv_far(e.inverse_mass_[far_id]),
        m_eff(e.slot_mass_[1]),
        burst_window(e.model_.collapse_window_s),
        y_near(flip(e.state_.units[near_id].x_ref_m.x())),
        u_near(flip(e.state_.units[near_id].v_mps.x())),
        t_near(e.state_.units[near_id].t_ref_s),
        y_far(flip(e.state_.units[far_id].x_ref_m.x())),
        u_far(flip(e.state_.units[far_id].v_mps.x())),
        t_far(e.state_.units[far_id].t_ref_s),
        last_near(e.state_.last_impact_s[body_near]),
        last_far(e.state_.last_impact_s[body_far]),
        burst_near(e.state_.burst_impacts[body_near]),
        burst_far(e.state_.burst_impacts[body_far]),
        now(e.state_.time_s),
        count(e.state_.collision_count),
        same_time(e.same_time_events_) {
    predictWall();
    predictPair();
  }

  // Between x and y (exact both ways).
  double flip(double x) const { return left ? x : -x; }

  void store() {
    UnitState& un = engine.state_.units[near_id];
    UnitState& uf = engine.state_.units[far_id];
    un.x_ref_m.x() = flip(y_near), un.v_mps.x() = flip(u_near), un.t_ref_s = t_near;
    uf.x_ref_m.x() = flip(y_far), uf.v_mps.x() = flip(u_far), uf.t_ref_s = t_far;
    EngineState& state = engine.state_;
    state.last_impact_s[body_near] = last_near, state.last_impact_s[body_far] = last_far;
    state.burst_impacts[body_near] = burst_near, state.burst_impacts[body_far] = burst_far;
    state.time_s = now;
    state.collision_count = count;
    engine.same_time_events_ = same_time;
    engine.slot_time_[wall_slot] = s_wall;
    engine.slot_time_[1] = s_pair;
  }

  // EngineState::noteImpact.
  void note(double& last, std::int32_t& burst, double t) const {
    burst = t - last <= burst_window ? burst + 1 : 1;
    last = t;
  }

  // Touching or overlapping by rounding: firstClosingRoot's answer, after the general loop's
  // test for a closing speed below round-off (closing: the rate of change of the gap).
  double touchingTau(double closing, double va, double vb) const {
    if (model.closingIsRoundOff(closing, va, vb)) return kNever;
    return closing < 0.0 ? 0.0 : kNever;
  }
  // When the near unit reaches the wall: tau_wall after t_near.
  void predictWall() {
    const double gap = y_near - contact_y;
    if (gap <= 0.0) {
      tau_wall = touchingTau(u_near, u_near, 0.0);
    } else {
      tau_wall = u_near < 0.0 ? gap * (1.0 / -u_near) : kNever;
    }
    s_wall = t_near + tau_wall;
  }
  // When the two units meet: tau_pair after pair_t0, the later of their reference times (the
  // same time except where the general loop left them otherwise).
  void predictPair() {
    pair_t0 = t_near;
    double yn = y_near, yf = y_far;
    if (t_far != t_near) {
      pair_t0 = std::max(t_near, t_far);
      yn = positionAt(y_near, u_near, t_near, pair_t0);
      yf = positionAt(y_far, u_far, t_far, pair_t0);
    }
    const double gap = (yf - yn) - span_y;
    const double closing = u_far - u_near;
    if (gap <= 0.0) {
      tau_pair = touchingTau(closing, u_near, u_far);
    } else {
      tau_pair = closing < 0.0 ? gap * (1.0 / (u_near - u_far)) : kNever;
    }
    s_pair = pair_t0 + tau_pair;
  }
  static double positionAt(double y, double u, double t_ref, double t) {
    return t != t_ref ? y + u * (t - t_ref) : y;
  }

  // The next event: the wall's slot or the pair's, and whether the other is due within rounding
  // of it too (a round for the general loop).
  bool wallFirst() const { return s_wall < s_pair; }
  bool tie(bool wall_first, double t) const {
    constexpr double kRounding = kTieUlps * std::numeric_limits<double>::epsilon();
    return (wall_first ? s_pair : s_wall) <= t + kRounding * std::abs(t);
  }

  // wallImpact at t = s_wall: both units move on by tau_wall.
  template <bool kRecord>
  void hitWall(double t) {
    const double tau = tau_wall;
    y_far = t_far == t_near ? y_far + u_far * tau : positionAt(y_far, u_far, t_far, t);
    y_near = y_near + u_near * tau;
    t_near = t_far = t;
    const double v = u_near;
    const double u = std::max(-v, 0.0);
    u_near = v + (1.0 + 1.0) * u;
    note(last_near, burst_near, t);
    if (kRecord) recordWall(engine, recordOf(t, v, u_far, u, 0.0));
    ++count;
    if (u_near > 0.0) {  // leaving the wall: it never returns (no acceleration)
      tau_wall = s_wall = kNever;
    } else {
      predictWall();
    }
    predictPair();
  }

  // pairImpact at t = s_pair: both units move to pair_t0, then on by tau_pair.
  template <bool kRecord>
  void hitPair(double t) {
    if (t_near != t_far) {
      y_near = positionAt(y_near, u_near, t_near, pair_t0);
      y_far = positionAt(y_far, u_far, t_far, pair_t0);
    }
    y_near = y_near + u_near * tau_pair;
    y_far = y_far + u_far * tau_pair;
    t_near = t_far = t;
    const double vn = u_near, vf = u_far;
    const double u = std::max(vn - vf, 0.0);
    const double impulse = (1.0 + 1.0) * u * m_eff;
    u_near = vn - impulse * inv_near;
    u_far = vf + impulse * inv_far;
    note(last_near, burst_near, t);
    note(last_far, burst_far, t);
    if (kRecord) recordPair(engine, recordOf(t, vn, vf, u, impulse));
    ++count;
    predictWall();
    if (u_far - u_near > 0.0) {  // separating: they never meet again (no acceleration)
      tau_pair = s_pair = kNever;
    } else {
      predictPair();
    }
  }

  template <bool kRecord>
  void impact(bool wall_first, double t) {
    if (wall_first) {
      hitWall<kRecord>(t);
    } else {
      hitPair<kRecord>(t);
    }
  }

  // Events until the count reaches `limit`, the next one is past t_end_s or is due with the
  // other slot: the caller has made sure that no other check of the loop can stop one before.
  void block(double t_end_s, std::int64_t limit) {
    while (count < limit) {
      const bool wall_first = wallFirst();
      const double t = wall_first ? s_wall : s_pair;
      if (!(t <= t_end_s) || tie(wall_first, t)) return;
      same_time = t == now ? same_time + 1 : 0;
      now = t;
      impact<false>(wall_first, t);
    }
  }

  // What the records need of an impact, passed by value so that the run's own state never
  // escapes to a call (it stays in registers).
  struct Record {
    std::int64_t index;
    double t, x_sign;
    int wall, body_near, body_far;
    std::int32_t burst_near, burst_far;
    double near_before, far_before, near_after, far_after;  // along y
    double closing, impulse, m_eff;
  };
  Record recordOf(double t, double near_before, double far_before, double closing,
                  double impulse) const {
    return {count,       t,          flip(1.0), wall,  body_near, body_far, burst_near, burst_far,
            near_before, far_before, u_near,    u_far, closing,   impulse,  m_eff};
  }
  // The general loop's records of the two impacts (x = x_sign * y), with its decisions.
  [[gnu::noinline]] static void recordWall(LineEngine& engine, const Record r) {
    const Model& model = engine.model_;
    engine.state_.collision_count = r.index;
    const int near_id = r.x_sign > 0.0 ? engine.order_[0] : engine.order_[1];
    const double m = engine.state_.units[near_id].mass_kg;
    const double u = r.closing;
    const ImpactDecision d =
        decideRestitution(model, model.world.walls[r.wall].restitution, u, r.burst_near,
                          r.burst_near, 0.0, r.body_near, kWallPartnerBase - r.wall);
    Impact impact =
        wallImpactRecord(r.t, r.body_near, r.wall, r.x_sign, r.x_sign * r.near_before, u, m, d);
    impact.va_after = r.x_sign * r.near_after;
    impact.impulse_Ns = m * (1.0 + d.e) * u;
    impact.lost_J = 0.5 * m * (1.0 - d.e * d.e) * u * u;
    engine.record(impact);
  }
  [[gnu::noinline]] static void recordPair(LineEngine& engine, const Record r) {
    const Model& model = engine.model_;
    engine.state_.collision_count = r.index;
    const bool left = r.x_sign > 0.0;  // the near body is body_a, on the left
    const int a = left ? r.body_near : r.body_far, b = left ? r.body_far : r.body_near;
    const std::int32_t burst_a = left ? r.burst_near : r.burst_far;
    const std::int32_t burst_b = left ? r.burst_far : r.burst_near;
    const double u = r.closing;
    const ImpactDecision d =
        decideRestitution(model, model.pairRestitution(a, b), u, burst_a, burst_b, 0.0, a, b);
    Impact impact;
    impact.t_s = r.t;
    impact.body_a = a;
    impact.body_b = b;
    impact.va_before = r.x_sign * (left ? r.near_before : r.far_before);
    impact.va_after = r.x_sign * (left ? r.near_after : r.far_after);
    impact.vb_before = r.x_sign * (left ? r.far_before : r.near_before);
    impact.vb_after = r.x_sign * (left ? r.far_after : r.near_after);
    impact.closing_mps = u;
    impact.impulse_Ns = r.impulse;
    impact.lost_J = impact.lost_analytic_J = 0.5 * r.m_eff * (1.0 - d.e * d.e) * u * u;
    impact.decision = d;
    engine.record(impact);
  }

  LineEngine& engine;
  const Model& model;
  const bool left;            // the wall is on the left: y = x; on the right: y = -x
  const int near_id, far_id;  // the unit next to the wall and the other
  const int body_near, body_far;
  const int wall, wall_slot;
  const double contact_y;  // the near unit's y when it touches the wall
  const double span_y;     // y_far - y_near when the two touch
  const double inv_near, inv_far, m_eff;
  const double burst_window;
  double y_near, u_near, t_near;  // position, velocity (along y) and reference time
  double y_far, u_far, t_far;
  double last_near, last_far;
  std::int32_t burst_near, burst_far;
  double now;
  std::int64_t count;
  std::int64_t same_time;
  double s_wall = kNever, tau_wall = kNever;  // the slots: time, and flight time before it
  double s_pair = kNever, tau_pair = kNever, pair_t0 = 0.0;
};

// The general loop's checks, in its order, for each event; between them, blocks of events that
// none of those checks but the end of the run and a round could stop (collision cap, count
// limit, the rate guard's next check and the stall count are all further off).
[[gnu::flatten]] bool LineEngine::runWallPair(double t_end_s, std::int64_t count_limit,
                                              RunStop& stop) {
  const std::int64_t cap = model_.world.max_collisions;
  constexpr std::int64_t kAll = std::numeric_limits<std::int64_t>::max();
  const std::int64_t record_until =
      out_.stream != nullptr ? kAll : (out_.events != nullptr ? out_.event_limit : 0);
  WallPairRun run(*this);
  for (;;) {
    if (run.count >= count_limit) {
      stop = RunStop::kCountLimit;
      break;
    }
    const bool wall_first = run.wallFirst();
    const double t = wall_first ? run.s_wall : run.s_pair;
    if (!(t <= t_end_s)) {
      stop = RunStop::kDone;
      break;
    }
    if (run.count >= cap) {
      stop = RunStop::kCollisionCap;
      break;
    }
    if (run.tie(wall_first, t)) {
      run.store();  // a round: the general loop
      return false;
    }
    if (const std::optional<RunStop> halt = fastRunStopsAt(run, t)) {
      stop = *halt;
      if (*halt == RunStop::kRateCap) return true;  // the run is stored
      break;
    }
    if (run.count < record_until) {
      run.impact<true>(wall_first, t);
      continue;
    }
    run.impact<false>(wall_first, t);
    run.block(t_end_s, std::min({count_limit, cap, rate_guard_.nextCheck(),
                                 run.count + (kLineStallEventCount - run.same_time)}));
  }
  run.store();
  return true;
}

}  // namespace collide::physics::detail
