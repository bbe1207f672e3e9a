// The 2D engine's simultaneous impacts: every impact due at one instant is resolved in one round,
// independent of body numbering. See docs/physics.md.
//
// The impacts due within rounding of the earliest (kTieUlps) are split into groups that share a
// unit. A group of one is an ordinary impact. A larger group of free, non-spinning disks (and the
// walls they hit) is one simultaneous system: normal impulses J_k >= 0 such that every contact
// that takes an impulse separates at e_k times its closing speed c_k, and every other one
// separates at least that fast (Newton's law with unilateral contacts, a linear complementarity
// problem):
//
//   w = A J - (1 + e) c >= 0,   J >= 0,   J_k w_k = 0,
//
// A the Delassus matrix, A_kl = sum over shared disks of (g_k . g_l) / m, g_k = +n_k on the disk
// the normal points to and -n_k on the other. A is positive definite when the normals of the
// contacts on each disk are independent, and the solution is then unique (Cottle, Pang and Stone,
// The Linear Complementarity Problem, 1992): found by trying active sets, it is the same whatever
// the order of the contacts. Each contact that takes an impulse loses 1/2 J_k (1 - e_k) c_k >= 0.
//
// Groups that hold a stuck cluster, a spinning or resting unit, a perfectly inelastic contact, a
// soft contact, or more than kMaxGroupContacts contacts are resolved pair by pair, in the order
// of their contact points (by x, then y): an order set by where the contacts are, so renumbering
// the bodies changes nothing (a mirror image may still differ: a documented limit). Contacts
// that an earlier one of the group changed are predicted again and come due in the next round.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "physics/plane_engine.hpp"

namespace collide::physics::detail {
namespace {

// Active sets are enumerated: 2^k solves of k x k systems.
constexpr int kMaxGroupContacts = 10;

// Solves the k x k system M x = r (Gaussian elimination with partial pivoting); false when M is
// singular to rounding.
bool solveDense(std::vector<double> m, std::vector<double> r, int k, std::vector<double>& x) {
  for (int col = 0; col < k; ++col) {
    int pivot = col;
    for (int row = col + 1; row < k; ++row) {
      if (std::abs(m[row * k + col]) > std::abs(m[pivot * k + col])) pivot = row;
    }
    double scale = 0.0;
    for (int j = 0; j < k; ++j) scale = std::max(scale, std::abs(m[col * k + j]));
    if (!(std::abs(m[pivot * k + col]) > 1e-12 * scale)) return false;
    if (pivot != col) {
      for (int j = 0; j < k; ++j) std::swap(m[col * k + j], m[pivot * k + j]);
      std::swap(r[col], r[pivot]);
    }
    for (int row = col + 1; row < k; ++row) {
      const double f = m[row * k + col] / m[col * k + col];
      if (f == 0.0) continue;
      for (int j = col; j < k; ++j) m[row * k + j] -= f * m[col * k + j];
      r[row] -= f * r[col];
    }
  }
  x.assign(k, 0.0);
  for (int row = k - 1; row >= 0; --row) {
    double sum = r[row];
    for (int j = row + 1; j < k; ++j) sum -= m[row * k + j] * x[j];
    x[row] = sum / m[row * k + row];
  }
  return true;
}

// Whether the impulses of active set `mask` (`impulse`, negative ones clipped to 0; `x` as
// solved, over the active contacts `active`) solve the complementarity problem: no active
// impulse below 0 (to rounding) and every inactive contact separating.
bool solvesGroup(const std::vector<double>& delassus, const std::vector<double>& rhs, int k,
                 int mask, const std::vector<int>& active, const std::vector<double>& x,
                 const std::vector<double>& impulse) {
  const int m = static_cast<int>(active.size());
  double scale = 0.0;
  bool holds = true;
  for (int p = 0; p < m; ++p) {
    // Rounding can leave -1e-17 where the exact impulse is 0.
    if (x[p] < -1e-12 * (std::abs(rhs[active[p]]) / delassus[active[p] * (k + 1)])) holds = false;
  }
  for (int i = 0; i < k; ++i) scale = std::max(scale, rhs[i]);
  for (int i = 0; holds && i < k; ++i) {
    if ((mask >> i) & 1) continue;
    double w = -rhs[i];
    for (int j = 0; j < k; ++j) w += delassus[i * k + j] * impulse[j];
    if (w < -1e-12 * scale) holds = false;
  }
  return holds;
}

// The impulses J >= 0 that solve w = A J - rhs >= 0, J_k w_k = 0 for the k x k Delassus matrix A,
// by trying active sets, the full set first (the common case: every contact pushes); empty when
// no set does.
std::vector<double> activeSetImpulses(const std::vector<double>& delassus,
                                      const std::vector<double>& rhs, int k) {
  std::vector<double> x;
  for (int mask = (1 << k) - 1; mask > 0; --mask) {
    std::vector<int> active;
    for (int i = 0; i < k; ++i) {
      if ((mask >> i) & 1) active.push_back(i);
    }
    const int m = static_cast<int>(active.size());
    std::vector<double> sub(m * m), r(m);
    for (int p = 0; p < m; ++p) {
      r[p] = rhs[active[p]];
      for (int q = 0; q < m; ++q) sub[p * m + q] = delassus[active[p] * k + active[q]];
    }
    if (!solveDense(sub, r, m, x)) continue;
    std::vector<double> impulse(k, 0.0);
    for (int p = 0; p < m; ++p) impulse[active[p]] = std::max(x[p], 0.0);
    if (solvesGroup(delassus, rhs, k, mask, active, x, impulse)) return impulse;
  }
  return {};
}

}  // namespace

bool PlaneEngine::collectTies(const Event& first) {
  ties_.assign(1, first);
  const double window =
      first.time_s + kTieUlps * std::numeric_limits<double>::epsilon() * std::abs(first.time_s);
  while (!heap_.empty()) {
    const Event& top = heap_.front();
    if (!(top.time_s <= window)) break;
    const Event next = top;
    std::pop_heap(heap_.begin(), heap_.end(), Later{});
    heap_.pop_back();
    if (!valid(next)) continue;
    if (next.kind == kStop) {  // no impact: back into the queue after (crossings are not here)
      set_aside_.push_back(next);
      continue;
    }
    const bool duplicate = std::any_of(ties_.begin(), ties_.end(), [&](const Event& e) {
      return e.kind == next.kind && e.a == next.a && e.b == next.b;
    });
    if (!duplicate) ties_.push_back(next);
  }
  for (const Event& stop : set_aside_) {
    heap_.push_back(stop);
    std::push_heap(heap_.begin(), heap_.end(), Later{});
  }
  set_aside_.clear();
  return ties_.size() > 1;
}

void PlaneEngine::resolveInstant(double t) {
  // Groups: impacts that share a unit, by union-find over the units involved.
  const int count = static_cast<int>(ties_.size());
  std::vector<int> group(count);
  std::iota(group.begin(), group.end(), 0);
  auto root = [&](int k) {
    while (group[k] != k) k = group[k] = group[group[k]];
    return k;
  };
  auto unitsOf = [&](const Event& e, int& u1, int& u2) {
    u1 = state_.bodies[e.a].unit;
    u2 = e.kind == 0 ? state_.bodies[e.b].unit : -1;
  };
  for (int i = 0; i < count; ++i) {
    int a1, a2;
    unitsOf(ties_[i], a1, a2);
    for (int j = i + 1; j < count; ++j) {
      int b1, b2;
      unitsOf(ties_[j], b1, b2);
      if (a1 == b1 || a1 == b2 || (a2 >= 0 && (a2 == b1 || a2 == b2))) group[root(j)] = root(i);
    }
  }
  // Each group in the order of its first impact; groups share no unit, so the order does not
  // change the outcome.
  std::vector<bool> done(count, false);
  for (int i = 0; i < count; ++i) {
    if (done[i]) continue;
    std::vector<Event> members;
    for (int j = i; j < count; ++j) {
      if (!done[j] && root(j) == root(i)) {
        members.push_back(ties_[j]);
        done[j] = true;
      }
    }
    if (members.size() == 1 || !simultaneousImpact(members, t)) {
      orderByPlace(members, t);
      for (const Event& e : members) {
        if (!valid(e)) continue;  // an earlier impact of the group changed its partners
        if (e.kind == 0) {
          pairImpact(e.a, e.b, t);
        } else {
          wallImpact(e.a, e.b, t);
        }
        if (resting_upper_ >= 0) return;
      }
    }
  }
}

void PlaneEngine::orderByPlace(std::vector<Event>& members, double t) const {
  if (members.size() < 2) return;
  // Where each contact is: between two disks the point dividing their centres in the ratio of
  // the radii (the same bits whichever disk is named first), on a wall the disk's point nearest it.
  struct Placed {
    core::Vec2 point;
    Event event;
  };
  std::vector<Placed> placed;
  for (const Event& e : members) {
    const core::Vec2 xa = kinematics(e.a, t).x;
    const double ra = model_.half_size_m[e.a];
    core::Vec2 point;
    if (e.kind == 0) {
      const core::Vec2 xb = kinematics(e.b, t).x;
      const double rb = model_.half_size_m[e.b];
      point = (xa * rb + xb * ra) / (ra + rb);
    } else {
      point = xa - ra * model_.world.walls[e.b].normal;
    }
    placed.push_back({point, e});
  }
  // Body numbers decide only between contacts at one point, which disks cannot make.
  std::sort(placed.begin(), placed.end(), [](const Placed& p, const Placed& q) {
    if (p.point.x() != q.point.x()) return p.point.x() < q.point.x();
    if (p.point.y() != q.point.y()) return p.point.y() < q.point.y();
    return Later{}(q.event, p.event);
  });
  for (std::size_t k = 0; k < members.size(); ++k) members[k] = placed[k].event;
}

bool PlaneEngine::oneSystemApplies(const std::vector<Event>& members) const {
  // Molecules with insides share energy pair by pair (each pair draws its own shares).
  if (static_cast<int>(members.size()) > kMaxGroupContacts ||
      model_.world.contact_model == ContactModel::kSpringDamper || !state_.internal_J.empty()) {
    return false;
  }
  for (const Event& e : members) {
    for (int body : {e.a, e.kind == 0 ? e.b : -1}) {
      if (body < 0) continue;
      const int id = state_.bodies[body].unit;
      const UnitState& unit = state_.units[id];
      if (members_[id].size() != 1 || unit.omega_radps != 0.0 || unit.resting_walls != 0) {
        return false;
      }
    }
  }
  return true;
}

PlaneEngine::GroupContact PlaneEngine::groupContact(const Event& e, double t) {
  const double window = model_.collapse_window_s;
  GroupContact c;
  c.a = e.a;
  advanceUnit(state_.bodies[e.a].unit, t);
  const Kin ka = kinematics(e.a, t);
  if (e.kind == 0) {
    c.b = e.b;
    advanceUnit(state_.bodies[e.b].unit, t);
    const Kin kb = kinematics(e.b, t);
    const core::Vec2 d = kb.x - ka.x;
    const double distance = d.norm();
    c.n = distance > 0.0 ? core::Vec2(d / distance) : core::Vec2(1.0, 0.0);
    c.closing = std::max((ka.v - kb.v).dot(c.n), 0.0);
    const double a_push = pairPush(state_.units[state_.bodies[e.a].unit],
                                   state_.units[state_.bodies[e.b].unit], ka, kb, c.n);
    c.decision = decideRestitution(model_, model_.pairRestitution(e.a, e.b), c.closing,
                                   state_.burstAt(e.a, t, window), state_.burstAt(e.b, t, window),
                                   a_push, e.a, e.b);
  } else {
    const WallDef& w = model_.world.walls[e.b];
    c.b = kWallPartnerBase - e.b;
    c.n = -w.normal;
    c.closing = std::max(ka.v.dot(c.n), 0.0);
    const double a_push = -state_.units[state_.bodies[e.a].unit].a_mps2.dot(w.normal);
    const std::int32_t burst = state_.burstAt(e.a, t, window);
    c.decision =
        decideRestitution(model_, w.restitution, c.closing, burst, burst, a_push, e.a, c.b);
  }
  c.e = c.decision.e;
  return c;
}

void PlaneEngine::delassusSystem(const std::vector<GroupContact>& contacts,
                                 std::vector<double>& delassus, std::vector<double>& rhs) const {
  const int k = static_cast<int>(contacts.size());
  const auto jacobian = [](const GroupContact& c, int body) -> core::Vec2 {
    if (body == c.b) return c.n;
    if (body == c.a) return -c.n;
    return core::Vec2::Zero();
  };
  delassus.assign(k * k, 0.0);
  rhs.assign(k, 0.0);
  for (int i = 0; i < k; ++i) {
    rhs[i] = (1.0 + contacts[i].e) * contacts[i].closing;
    for (int j = 0; j < k; ++j) {
      double sum = 0.0;
      for (int body : {contacts[i].a, contacts[i].b}) {
        if (body < 0) continue;
        sum += jacobian(contacts[i], body).dot(jacobian(contacts[j], body)) * inverseMassOf(body);
      }
      delassus[i * k + j] = sum;
    }
  }
}

std::vector<CollisionEvent> PlaneEngine::groupRecordsBefore(
    const std::vector<GroupContact>& contacts, double t) const {
  std::vector<CollisionEvent> records;
  for (const GroupContact& c : contacts) {
    CollisionEvent event;
    event.body_a = c.a;
    event.body_b = c.b;
    event.normal = c.n;
    event.velocity_a_before_mps = kinematics(c.a, t).v;
    if (c.b >= 0) event.velocity_b_before_mps = kinematics(c.b, t).v;
    event.closing_speed_mps = c.closing;
    event.restitution = c.e;
    event.time_s = t;
    event.impulse_Ns = c.impulse;
    // 1/2 J (1 - e) c: what this contact's impulse took out of the motion along its normal.
    event.energy_lost_J = event.energy_lost_analytic_J = 0.5 * c.impulse * (1.0 - c.e) * c.closing;
    records.push_back(event);
  }
  return records;
}

void PlaneEngine::applyGroupImpulses(const std::vector<GroupContact>& contacts) {
  for (const GroupContact& c : contacts) {
    UnitState& ua = state_.units[state_.bodies[c.a].unit];
    ua.v_mps -= c.impulse * inverseMassOf(c.a) * c.n;
    if (c.b >= 0) {
      UnitState& ub = state_.units[state_.bodies[c.b].unit];
      ub.v_mps += c.impulse * inverseMassOf(c.b) * c.n;
    }
  }
  std::vector<int> touched;
  for (const GroupContact& c : contacts) {
    for (int body : {c.a, c.b}) {
      if (body < 0) continue;
      const int id = state_.bodies[body].unit;
      if (std::find(touched.begin(), touched.end(), id) == touched.end()) touched.push_back(id);
    }
  }
  for (int id : touched) renew(id);
  for (int id : touched) predictUnit(id, -1);
}

bool PlaneEngine::simultaneousImpact(const std::vector<Event>& members, double t) {
  if (!oneSystemApplies(members)) return false;
  const int k = static_cast<int>(members.size());
  std::vector<GroupContact> contacts;
  for (int i = 0; i < k; ++i) {
    contacts.push_back(groupContact(members[i], t));
    // Perfectly inelastic contacts merge, stick or settle: pair by pair.
    if (contacts.back().e == 0.0) return false;
  }
  // The Delassus matrix and the right-hand side (1 + e) c.
  std::vector<double> delassus, rhs;
  delassusSystem(contacts, delassus, rhs);
  const std::vector<double> best = activeSetImpulses(delassus, rhs, k);
  if (best.empty()) return false;
  // Apply every impulse to velocities taken before any of them.
  for (int i = 0; i < k; ++i) contacts[i].impulse = best[i];
  std::vector<CollisionEvent> records = groupRecordsBefore(contacts, t);
  applyGroupImpulses(contacts);
  const double window = model_.collapse_window_s;
  for (int i = 0; i < k; ++i) {
    const GroupContact& c = contacts[i];
    // A contact that another impulse already separated took none: it was not an impact.
    if (c.impulse <= 0.0) continue;
    state_.noteImpact(c.a, t, window);
    if (c.b >= 0) state_.noteImpact(c.b, t, window);
    noteClustering(c.a, t, c.decision);
    if (c.b >= 0) noteClustering(c.b, t, c.decision);
    CollisionEvent& event = records[i];
    event.velocity_a_after_mps = kinematics(c.a, t).v;
    if (c.b >= 0) event.velocity_b_after_mps = kinematics(c.b, t).v;
    finish(event, c.decision);
  }
  return true;
}

}  // namespace collide::physics::detail
