// The 1D engine's simultaneous impacts: every contact due at one instant is resolved in one round,
// independent of body numbering and mirror-symmetric. See docs/physics.md.
//
// A round is the set of slots due within rounding of the earliest (kTieUlps). Slots that share no
// unit are independent: each is an ordinary pairwise impact. A run of adjacent due slots (a unit
// struck from both sides at once) is one simultaneous system: impulses J_k >= 0 such that every
// contact of the run separates at e_k times its closing speed c_k (Newton's law at each contact,
// applied to the velocities after the whole round):
//
//   sum_l A_kl J_l = (1 + e_k) c_k,   A = the Delassus matrix (tridiagonal in 1D:
//   A_kk = 1/m_left + 1/m_right, A_k,k+1 = -1/m_shared).
//
// A is a Stieltjes matrix (symmetric positive definite, non-positive off the diagonal), so its
// inverse is non-negative and every J_k >= 0: all contacts of the run stay active, and the energy
// lost is sum_k 1/2 J_k (1 - e_k) c_k >= 0, booked contact by contact. Contacts that come due at
// the same instant because of the round (a touching neighbour now pushed) form the next round:
// the impulse travels along a touching row pair by pair, and two fronts meeting in the middle
// meet in lock-step.
#include <algorithm>
#include <cmath>

#include "physics/line_engine.hpp"

namespace collide::physics::detail {

void LineEngine::collectDue(int node, double window_s) {
  const int winner = tree_[node];
  if (winner < 0 || !(slot_time_[winner] <= window_s)) return;
  if (node >= leaves_) {
    due_.push_back(winner);
    return;
  }
  collectDue(2 * node, window_s);
  collectDue(2 * node + 1, window_s);
}

void LineEngine::resolveRound(double t) {
  const double window = t + kTieUlps * std::numeric_limits<double>::epsilon() * std::abs(t);
  due_.clear();
  const int slots = static_cast<int>(slot_time_.size());
  if (slots <= 8) {
    for (int j = 0; j < slots; ++j) {
      if (slot_time_[j] <= window) due_.push_back(j);
    }
  } else {
    collectDue(1, window);
  }
  // Runs of adjacent slots, handled from the right: a merge renumbers only the slots above it.
  std::vector<int> runs = due_;  // due_ is reused by nothing below, but keep the list stable
  int end = static_cast<int>(runs.size()) - 1;
  while (end >= 0) {
    int begin = end;
    while (begin > 0 && runs[begin - 1] == runs[begin] - 1) --begin;
    const int first = runs[begin], last = runs[end];
    if (first == last) {
      const int units = static_cast<int>(order_.size());
      if (first == 0 || first == units) {
        wallImpact(first == 0, t);
      } else {
        pairImpact(first, t);
      }
    } else {
      groupImpact(first, last, t);
    }
    end = begin - 1;
  }
}

void LineEngine::decideGroupContact(Contact& c, double t) {
  const double window = model_.collapse_window_s;
  c.v_left = c.left >= 0 ? state_.units[c.left].v_mps.x() : 0.0;
  c.v_right = c.right >= 0 ? state_.units[c.right].v_mps.x() : 0.0;
  c.closing = std::max(c.v_left - c.v_right, 0.0);
  if (c.left < 0 || c.right < 0) {
    const bool left_wall = c.left < 0;
    const int id = left_wall ? c.right : c.left;
    const int wall = left_wall ? left_wall_ : right_wall_;
    c.body_a = left_wall ? first_body_[id] : last_body_[id];
    c.body_b = kWallPartnerBase - wall;
    const double n = left_wall ? 1.0 : -1.0;
    const double a_push = wallPush(id, n);
    const std::int32_t burst = state_.burstAt(c.body_a, t, window);
    c.decision = decideRestitution(model_, model_.world.walls[wall].restitution, c.closing, burst,
                                   burst, a_push, c.body_a, c.body_b);
  } else {
    c.body_a = last_body_[c.left];
    c.body_b = first_body_[c.right];
    const double a_push = pairPush(c.left, c.right);
    c.decision = decideRestitution(model_, model_.pairRestitution(c.body_a, c.body_b), c.closing,
                                   state_.burstAt(c.body_a, t, window),
                                   state_.burstAt(c.body_b, t, window), a_push, c.body_a, c.body_b);
  }
}

void LineEngine::solveGroupImpulses() {
  const int count = static_cast<int>(contacts_.size());
  // The tridiagonal system, solved by elimination from the left (Thomas): positive pivots, as A
  // is positive definite.
  diagonal_.assign(count, 0.0);
  upper_.assign(count, 0.0);
  rhs_.assign(count, 0.0);
  auto inverseMass = [&](int unit) { return unit < 0 ? 0.0 : inverse_mass_[unit]; };
  for (int k = 0; k < count; ++k) {
    const Contact& c = contacts_[k];
    diagonal_[k] = inverseMass(c.left) + inverseMass(c.right);
    upper_[k] = k + 1 < count ? -inverseMass(c.right) : 0.0;
    rhs_[k] = (1.0 + c.decision.e) * c.closing;
  }
  for (int k = 1; k < count; ++k) {
    const double factor = upper_[k - 1] / diagonal_[k - 1];
    diagonal_[k] -= factor * upper_[k - 1];
    rhs_[k] -= factor * rhs_[k - 1];
  }
  for (int k = count - 1; k >= 0; --k) {
    const double next = k + 1 < count ? upper_[k] * contacts_[k + 1].impulse : 0.0;
    // Rounding can leave -1e-17 where the exact impulse is 0 (a contact closing at 0).
    contacts_[k].impulse = std::max((rhs_[k] - next) / diagonal_[k], 0.0);
  }
}

void LineEngine::recordGroupContact(const Contact& c, double t, double lost) {
  Impact impact;
  impact.t_s = t;
  impact.body_a = c.body_a;
  impact.body_b = c.body_b;
  const bool wall = c.body_b < 0;
  const bool left_wall = c.left < 0;
  // Walls: the body is a, the normal points from it into the wall.
  impact.normal_x = wall && left_wall ? -1.0 : 1.0;
  impact.va_before = left_wall ? c.v_right : c.v_left;
  impact.va_after = left_wall ? state_.units[c.right].v_mps.x() : state_.units[c.left].v_mps.x();
  if (!wall) {
    impact.vb_before = c.v_right;
    impact.vb_after = state_.units[c.right].v_mps.x();
  }
  impact.closing_mps = c.closing;
  impact.impulse_Ns = c.impulse;
  impact.lost_J = impact.lost_analytic_J = lost;
  impact.merged = c.decision.e == 0.0;
  impact.decision = c.decision;
  record(impact);
}

void LineEngine::mergeGroup(int first, double t) {
  const int count = static_cast<int>(contacts_.size());
  // Perfectly inelastic contacts join their partners (right to left: a merge renumbers only the
  // slots above it); against a wall the unit attaches unless gravity pulls it away.
  bool attach_left = false, attach_right = false;
  for (int k = count - 1; k >= 0; --k) {
    const Contact& c = contacts_[k];
    if (c.decision.e != 0.0) continue;
    if (c.left < 0 || c.right < 0) {
      const bool left_wall = c.left < 0;
      const int id = left_wall ? c.right : c.left;
      const double n = left_wall ? 1.0 : -1.0;
      const double a_push = friction_      ? pushAtRest(id, n)
                            : accelerated_ ? -state_.units[id].a_mps2.x() * n
                                           : 0.0;
      if (a_push >= 0.0) (left_wall ? attach_left : attach_right) = true;
      continue;
    }
    joinUnits(first + k, t);
    rebuild();
  }
  if (attach_right) attachUnit(order_.back(), false);
  if (attach_left) attachUnit(order_.front(), true);
  rebuild();
}

void LineEngine::groupImpact(int first, int last, double t) {
  const int units = static_cast<int>(order_.size());
  const int count = last - first + 1;
  contacts_.assign(count, Contact{});
  const double window = model_.collapse_window_s;
  // The partners of each contact, their velocities at t and the restitution that applies.
  for (int k = 0; k < count; ++k) {
    const int slot = first + k;
    Contact& c = contacts_[k];
    c.left = slot == 0 ? -1 : order_[slot - 1];
    c.right = slot == units ? -1 : order_[slot];
    if (c.left >= 0) advance(state_.units[c.left], t);
    if (c.right >= 0) advance(state_.units[c.right], t);
  }
  for (Contact& c : contacts_) decideGroupContact(c, t);
  solveGroupImpulses();
  // Apply: each unit takes the impulse of the contact on its left (pushing it right) and that of
  // the contact on its right (pushing it left).
  for (int k = 0; k < count; ++k) {
    const Contact& c = contacts_[k];
    if (c.left >= 0) state_.units[c.left].v_mps.x() -= c.impulse * inverse_mass_[c.left];
    if (c.right >= 0) state_.units[c.right].v_mps.x() += c.impulse * inverse_mass_[c.right];
  }
  bool merges = false;
  for (int k = 0; k < count; ++k) {
    const Contact& c = contacts_[k];
    const ImpactDecision& d = c.decision;
    const double lost = 0.5 * c.impulse * (1.0 - d.e) * c.closing;
    state_.noteImpact(c.body_a, t, window);
    if (c.body_b >= 0) state_.noteImpact(c.body_b, t, window);
    merges = merges || d.e == 0.0;
    if (out_.wants(state_.collision_count)) recordGroupContact(c, t, lost);
    finish(lost, d, t);
  }
  if (!merges) {
    for (int slot = std::max(first - 1, 0); slot <= std::min(last + 1, units); ++slot) {
      refresh(slot);
    }
    return;
  }
  mergeGroup(first, t);
}

void LineEngine::attachUnit(int id, bool left) {
  UnitState& unit = state_.units[id];
  unit.v_mps.x() = 0.0;
  unit.attached = true;
  unit.a_mps2.setZero();
  unit.x_ref_m.x() = left ? left_x_ - left_m_[id] : right_x_ - right_m_[id];
}

}  // namespace collide::physics::detail
