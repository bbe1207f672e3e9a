// The 1D engine's fast path for the commonest long run: two bodies between at most two walls,
// elastic everywhere, no gravity, nothing recorded (pi-blocks: 314 million impacts for 9 digits).
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
  if (inverse_mass_[order_[0]] == 0.0 || inverse_mass_[order_[1]] == 0.0) return false;
  // e = 1 everywhere: decideRestitution then always answers e = 1 (the collapse guard acts only
  // below 1, the resting rule only under gravity) and every impact books 0 J lost.
  if (model_.pairRestitution(0, 1) != 1.0) return false;
  for (int wall : {left_wall_, right_wall_}) {
    if (wall >= 0 && world.walls[wall].restitution != 1.0) return false;
  }
  return true;
}

[[gnu::flatten]] bool LineEngine::runTwoBodies(double t_end_s, std::int64_t count_limit,
                                               RunStop& stop) {
  constexpr double kRounding = kTieUlps * std::numeric_limits<double>::epsilon();
  const int l = order_[0], r = order_[1];
  UnitState &unit_l = state_.units[l], &unit_r = state_.units[r];
  const int body_l = first_body_[l], body_r = first_body_[r];
  const double inv_l = inverse_mass_[l], inv_r = inverse_mass_[r], m_eff = slot_mass_[1];
  const double face_l = left_m_[l], face_lr = right_m_[l];  // the left unit's faces
  const double face_rl = left_m_[r], face_r = right_m_[r];  // the right unit's
  const bool wall_left = left_wall_ >= 0, wall_right = right_wall_ >= 0;
  const double left_x = left_x_, right_x = right_x_;
  const std::int64_t cap = model_.world.max_collisions;
  const double burst_window = model_.collapse_window_s;

  double xl = unit_l.x_ref_m.x(), vl = unit_l.v_mps.x(), tl = unit_l.t_ref_s;
  double xr = unit_r.x_ref_m.x(), vr = unit_r.v_mps.x(), tr = unit_r.t_ref_s;
  double last_l = state_.last_impact_s[body_l], last_r = state_.last_impact_s[body_r];
  std::int32_t burst_l = state_.burst_impacts[body_l], burst_r = state_.burst_impacts[body_r];
  double now = state_.time_s;
  std::int64_t count = state_.collision_count;
  std::int64_t same_time = same_time_events_;
  double s0 = slot_time_[0], s1 = slot_time_[1], s2 = slot_time_[2];

  auto store = [&] {
    unit_l.x_ref_m.x() = xl, unit_l.v_mps.x() = vl, unit_l.t_ref_s = tl;
    unit_r.x_ref_m.x() = xr, unit_r.v_mps.x() = vr, unit_r.t_ref_s = tr;
    state_.last_impact_s[body_l] = last_l, state_.last_impact_s[body_r] = last_r;
    state_.burst_impacts[body_l] = burst_l, state_.burst_impacts[body_r] = burst_r;
    state_.time_s = now;
    state_.collision_count = count;
    same_time_events_ = same_time;
    slot_time_[0] = s0, slot_time_[1] = s1, slot_time_[2] = s2;
  };
  // EngineState::noteImpact.
  auto note = [&](double& last, std::int32_t& burst, double t) {
    burst = t - last <= burst_window ? burst + 1 : 1;
    last = t;
  };
  // advance() without acceleration.
  auto advanceL = [&](double t) {
    if (t != tl) xl = xl + vl * (t - tl);
    tl = t;
  };
  auto advanceR = [&](double t) {
    if (t != tr) xr = xr + vr * (t - tr);
    tr = t;
  };
  // predictWall(true), predictWall(false), predictPair(1) without acceleration.
  auto wallLeft = [&] {
    if (!wall_left) return kNever;
    const double gap = xl + face_l - left_x;
    if (gap <= 0.0 && model_.closingIsRoundOff(vl, vl, 0.0)) return kNever;
    return tl + firstClosingRoot(gap, vl, 0.0);
  };
  auto wallRight = [&] {
    if (!wall_right) return kNever;
    const double gap = right_x - xr - face_r;
    if (gap <= 0.0 && model_.closingIsRoundOff(vr, vr, 0.0)) return kNever;
    return tr + firstClosingRoot(gap, -vr, -0.0);
  };
  auto pair = [&] {
    const double t0 = std::max(tl, tr);
    const double gap = (xr + vr * (t0 - tr) + face_rl) - (xl + vl * (t0 - tl) + face_lr);
    const double closing = vr - vl;
    if (gap <= 0.0 && model_.closingIsRoundOff(closing, vl, vr)) return kNever;
    return t0 + firstClosingRoot(gap, closing, 0.0);
  };

  for (;;) {
    if (count >= count_limit) {
      stop = RunStop::kCountLimit;
      break;
    }
    int slot = s1 < s0 ? 1 : 0;
    if (s2 < (slot == 1 ? s1 : s0)) slot = 2;
    const double t = slot == 0 ? s0 : (slot == 1 ? s1 : s2);
    if (!(t <= t_end_s)) {
      stop = RunStop::kDone;
      break;
    }
    if (count >= cap) {
      stop = RunStop::kCollisionCap;
      break;
    }
    const double window = t + kRounding * std::abs(t);
    const int due = (s0 <= window ? 1 : 0) | (s1 <= window ? 2 : 0) | (s2 <= window ? 4 : 0);
    if (due != 1 && due != 2 && due != 4 && due != 3 && due != 6) {
      store();  // both walls at once, or all three slots: the general loop
      return false;
    }
    if (rate_guard_.exceeded(count, t)) {
      store();
      stopForRate();
      stop = RunStop::kRateCap;
      return true;
    }
    if (t == now) {
      if (++same_time > kLineStallEventCount) {
        stop = RunStop::kStalled;
        break;
      }
    } else {
      same_time = 0;
    }
    now = t;
    if (due == 1) {  // wallImpact(true, t)
      advanceL(t);
      const double v = vl, n = 1.0;
      const double u = std::max(-v * n, 0.0);
      const double v_after = v + (1.0 + 1.0) * u * n;
      vl = v_after;
      note(last_l, burst_l, t);
      ++count;
      s0 = v_after * n > 0.0 ? kNever : wallLeft();
      s1 = pair();
    } else if (due == 4) {  // wallImpact(false, t)
      advanceR(t);
      const double v = vr, n = -1.0;
      const double u = std::max(-v * n, 0.0);
      const double v_after = v + (1.0 + 1.0) * u * n;
      vr = v_after;
      note(last_r, burst_r, t);
      ++count;
      s2 = v_after * n > 0.0 ? kNever : wallRight();
      s1 = pair();
    } else if (due == 2) {  // pairImpact(1, t)
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
    } else {
      // groupImpact over slots 0-1 (the left unit between the left wall and the right unit) or
      // 1-2 (the right unit between the left unit and the right wall): the tridiagonal system of
      // two contacts, eliminated as there.
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
  }
  store();
  return true;
}

}  // namespace collide::physics::detail
