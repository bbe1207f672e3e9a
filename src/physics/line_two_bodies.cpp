// The 1D engine's fast path for two bodies between two walls or none, elastic everywhere, no
// gravity, nothing recorded (two bodies and one wall, pi-blocks' case: line_wall_pair.cpp).
// It does the arithmetic of the general loop (line_engine.cpp: run, wallImpact, pairImpact,
// predictWall, predictPair; line_groups.cpp: groupImpact for a block struck by the wall and its
// neighbour in one round) statement for statement, on copies of the two units held in registers
// instead of in the engine's tables. A run therefore gives the same bits whichever path takes an
// event, and checkpoints replay exactly. What it does not handle (three slots due in one round,
// both walls at once, a recorded event) goes back to the general loop for one event.
#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/line_engine.hpp"
#include "physics/toi.hpp"

namespace collide::physics::detail {

bool LineEngine::twoBodyFastPathApplies() const {
  const WorldDef& world = model_.world;
  if (state_.bodies.size() != 2 || order_.size() != 2 || accelerated_ || soft_) return false;
  if (world.restitution_model.law != RestitutionLaw::kConstant) return false;
  if (state_.releases_done < world.releases.size()) return false;
  if (inverse_mass_[order_[0]] == 0.0 || inverse_mass_[order_[1]] == 0.0) return false;
  // e = 1 everywhere: decideRestitution then always answers e = 1 (the collapse guard acts only
  // below 1, the resting rule only under gravity) and every impact books 0 J lost.
  if (model_.pairRestitution(0, 1) != 1.0) return false;
  for (int wall : {left_wall_, right_wall_}) {
    if (wall >= 0 && world.walls[wall].restitution != 1.0) return false;
  }
  return true;
}

// The two units held in locals (registers, once runTwoBodies inlines this) instead of in the
// engine's tables: loaded at the start of a run, stored back at every exit.
struct LineEngine::TwoBodyRun {
  explicit TwoBodyRun(LineEngine& e)
      : engine(e),
        model(e.model_),
        unit_l(e.state_.units[e.order_[0]]),
        unit_r(e.state_.units[e.order_[1]]),
        body_l(e.first_body_[e.order_[0]]),
        body_r(e.first_body_[e.order_[1]]),
        inv_l(e.inverse_mass_[e.order_[0]]),
        inv_r(e.inverse_mass_[e.order_[1]]),
        m_eff(e.slot_mass_[1]),
        face_l(e.left_m_[e.order_[0]]),
        face_lr(e.right_m_[e.order_[0]]),
        face_rl(e.left_m_[e.order_[1]]),
        face_r(e.right_m_[e.order_[1]]),
        wall_left(e.left_wall_ >= 0),
        wall_right(e.right_wall_ >= 0),
        left_x(e.left_x_),
        right_x(e.right_x_),
        burst_window(e.model_.collapse_window_s),
        xl(unit_l.x_ref_m.x()),
        vl(unit_l.v_mps.x()),
        tl(unit_l.t_ref_s),
        xr(unit_r.x_ref_m.x()),
        vr(unit_r.v_mps.x()),
        tr(unit_r.t_ref_s),
        last_l(e.state_.last_impact_s[body_l]),
        last_r(e.state_.last_impact_s[body_r]),
        burst_l(e.state_.burst_impacts[body_l]),
        burst_r(e.state_.burst_impacts[body_r]),
        now(e.state_.time_s),
        count(e.state_.collision_count),
        same_time(e.same_time_events_),
        s0(e.slot_time_[0]),
        s1(e.slot_time_[1]),
        s2(e.slot_time_[2]) {}

  void store() {
    unit_l.x_ref_m.x() = xl, unit_l.v_mps.x() = vl, unit_l.t_ref_s = tl;
    unit_r.x_ref_m.x() = xr, unit_r.v_mps.x() = vr, unit_r.t_ref_s = tr;
    EngineState& state = engine.state_;
    state.last_impact_s[body_l] = last_l, state.last_impact_s[body_r] = last_r;
    state.burst_impacts[body_l] = burst_l, state.burst_impacts[body_r] = burst_r;
    state.time_s = now;
    state.collision_count = count;
    engine.same_time_events_ = same_time;
    engine.slot_time_[0] = s0, engine.slot_time_[1] = s1, engine.slot_time_[2] = s2;
  }
  // EngineState::noteImpact.
  void note(double& last, std::int32_t& burst, double t) const {
    burst = t - last <= burst_window ? burst + 1 : 1;
    last = t;
  }
  // advance() without acceleration.
  void advanceL(double t) {
    if (t != tl) xl = xl + vl * (t - tl);
    tl = t;
  }
  void advanceR(double t) {
    if (t != tr) xr = xr + vr * (t - tr);
    tr = t;
  }
  // predictWall(true), predictWall(false), predictPair(1) without acceleration.
  double wallLeft() const {
    if (!wall_left) return kNever;
    const double gap = xl + face_l - left_x;
    if (gap <= 0.0 && model.closingIsRoundOff(vl, vl, 0.0)) return kNever;
    return tl + firstClosingRoot(gap, vl, 0.0);
  }
  double wallRight() const {
    if (!wall_right) return kNever;
    const double gap = right_x - xr - face_r;
    if (gap <= 0.0 && model.closingIsRoundOff(vr, vr, 0.0)) return kNever;
    return tr + firstClosingRoot(gap, -vr, -0.0);
  }
  double pair() const {
    const double t0 = std::max(tl, tr);
    const double gap = (xr + vr * (t0 - tr) + face_rl) - (xl + vl * (t0 - tl) + face_lr);
    const double closing = vr - vl;
    if (gap <= 0.0 && model.closingIsRoundOff(closing, vl, vr)) return kNever;
    return t0 + firstClosingRoot(gap, closing, 0.0);
  }
  // The earliest slot's time, and the slots due within rounding of t (bit k: slot k).
  double earliest() const {
    int slot = s1 < s0 ? 1 : 0;
    if (s2 < (slot == 1 ? s1 : s0)) slot = 2;
    return slot == 0 ? s0 : (slot == 1 ? s1 : s2);
  }
  int dueAt(double t) const {
    constexpr double kRounding = kTieUlps * std::numeric_limits<double>::epsilon();
    const double window = t + kRounding * std::abs(t);
    return (s0 <= window ? 1 : 0) | (s1 <= window ? 2 : 0) | (s2 <= window ? 4 : 0);
  }
  // wallImpact(true, t) and wallImpact(false, t).
  void hitLeftWall(double t) {
    advanceL(t);
    const double v = vl, n = 1.0;
    const double u = std::max(-v * n, 0.0);
    const double v_after = v + (1.0 + 1.0) * u * n;
    vl = v_after;
    note(last_l, burst_l, t);
    ++count;
    s0 = v_after * n > 0.0 ? kNever : wallLeft();
    s1 = pair();
  }
  void hitRightWall(double t) {
    advanceR(t);
    const double v = vr, n = -1.0;
    const double u = std::max(-v * n, 0.0);
    const double v_after = v + (1.0 + 1.0) * u * n;
    vr = v_after;
    note(last_r, burst_r, t);
    ++count;
    s2 = v_after * n > 0.0 ? kNever : wallRight();
    s1 = pair();
  }
  // pairImpact(1, t).
  void hitPair(double t) {
    advanceL(t);
    advanceR(t);
    const double u = std::max(vl - vr, 0.0);
    const double impulse = (1.0 + 1.0) * u * m_eff;
    const double vl_after = vl - impulse * inv_l, vr_after = vr + impulse * inv_r;
    vl = vl_after;
    vr = vr_after;
    note(last_l, burst_l, t);
    note(last_r, burst_r, t);
    ++count;
    s0 = wallLeft();
    s1 = vr_after - vl_after > 0.0 ? kNever : pair();
    s2 = wallRight();
  }
  // groupImpact over slots 0-1 (due == 3: the left unit between the left wall and the right
  // unit) or 1-2 (the right unit between the left unit and the right wall): the tridiagonal
  // system of two contacts, eliminated as there.
  void hitGroup(int due, double t) {
    advanceL(t);
    advanceR(t);
    double diagonal0, upper0, rhs0, diagonal1, rhs1;
    if (due == 3) {
      const double closing0 = std::max(0.0 - vl, 0.0), closing1 = std::max(vl - vr, 0.0);
      diagonal0 = 0.0 + inv_l, upper0 = -inv_l, rhs0 = (1.0 + 1.0) * closing0;
      diagonal1 = inv_l + inv_r, rhs1 = (1.0 + 1.0) * closing1;
    } else {
      const double closing0 = std::max(vl - vr, 0.0), closing1 = std::max(vr - 0.0, 0.0);
      diagonal0 = inv_l + inv_r, upper0 = -inv_r, rhs0 = (1.0 + 1.0) * closing0;
      diagonal1 = inv_r + 0.0, rhs1 = (1.0 + 1.0) * closing1;
    }
    const double factor = upper0 / diagonal0;
    diagonal1 -= factor * upper0;
    rhs1 -= factor * rhs0;
    const double impulse1 = std::max((rhs1 - 0.0) / diagonal1, 0.0);
    const double impulse0 = std::max((rhs0 - upper0 * impulse1) / diagonal0, 0.0);
    if (due == 3) {
      vl += impulse0 * inv_l;
      vl -= impulse1 * inv_l;
      vr += impulse1 * inv_r;
      note(last_l, burst_l, t);
      note(last_l, burst_l, t);
      note(last_r, burst_r, t);
    } else {
      vl -= impulse0 * inv_l;
      vr += impulse0 * inv_r;
      vr -= impulse1 * inv_r;
      note(last_l, burst_l, t);
      note(last_r, burst_r, t);
      note(last_r, burst_r, t);
    }
    count += 2;
    s0 = wallLeft();
    s1 = pair();
    s2 = wallRight();
  }
  // The impact of the slots `due` (one slot, or two adjacent: 3 or 6) at t.
  void impact(int due, double t) {
    if (due == 1) {
      hitLeftWall(t);
    } else if (due == 4) {
      hitRightWall(t);
    } else if (due == 2) {
      hitPair(t);
    } else {
      hitGroup(due, t);
    }
  }

  LineEngine& engine;
  const Model& model;
  UnitState &unit_l, &unit_r;
  const int body_l, body_r;
  const double inv_l, inv_r, m_eff;
  const double face_l, face_lr;  // the left unit's faces
  const double face_rl, face_r;  // the right unit's
  const bool wall_left, wall_right;
  const double left_x, right_x;
  const double burst_window;
  double xl, vl, tl;
  double xr, vr, tr;
  double last_l, last_r;
  std::int32_t burst_l, burst_r;
  double now;
  std::int64_t count;
  std::int64_t same_time;
  double s0, s1, s2;
};

[[gnu::flatten]] bool LineEngine::runTwoBodies(double t_end_s, std::int64_t count_limit,
                                               RunStop& stop) {
  const std::int64_t cap = model_.world.max_collisions;
  TwoBodyRun run(*this);
  for (;;) {
    if (run.count >= count_limit) {
      stop = RunStop::kCountLimit;
      break;
    }
    const double t = run.earliest();
    if (!(t <= t_end_s)) {
      stop = RunStop::kDone;
      break;
    }
    if (run.count >= cap) {
      stop = RunStop::kCollisionCap;
      break;
    }
    const int due = run.dueAt(t);
    if (due != 1 && due != 2 && due != 4 && due != 3 && due != 6) {
      run.store();  // both walls at once, or all three slots: the general loop
      return false;
    }
    if (const std::optional<RunStop> halt = fastRunStopsAt(run, t)) {
      stop = *halt;
      if (*halt == RunStop::kRateCap) return true;  // the run is stored
      break;
    }
    run.impact(due, t);
  }
  run.store();
  return true;
}

}  // namespace collide::physics::detail
