// The 1D engine's set-up, event loop and hot path. See line_engine.hpp.
#include "physics/line_engine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/error.hpp"
#include "physics/toi.hpp"

namespace collide::physics::detail {
namespace {

// A handful of slots is scanned without unpredictable branches; more go through the tree.
constexpr int kScanSlots = 8;
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

}  // namespace

LineEngine::LineEngine(const Model& model, EngineState start, const Recorder& out)
    : model_(model),
      state_(std::move(start)),
      out_(out),
      rate_guard_(model.world.max_collisions_per_second) {
  const WorldDef& world = model_.world;
  friction_ = model.has_friction;
  drag_ = model.has_drag;
  accelerated_ = world.gravity_mps2.x() != 0.0 || friction_ || drag_;
  soft_ = world.contact_model == ContactModel::kSpringDamper;
  COLLIDE_ASSERT(!(friction_ && soft_), "sliding friction needs impulsive contacts");
  const int n = static_cast<int>(world.bodies.size());
  body_order_.resize(n);
  std::iota(body_order_.begin(), body_order_.end(), 0);
  std::stable_sort(body_order_.begin(), body_order_.end(), [&](int a, int b) {
    return world.bodies[a].position_m.x() < world.bodies[b].position_m.x();
  });
  rank_.resize(n);
  for (int k = 0; k < n; ++k) rank_[body_order_[k]] = k;
  // Only the innermost wall on each side can ever be reached.
  for (int w = 0; w < static_cast<int>(world.walls.size()); ++w) {
    const WallDef& wall = world.walls[w];
    if (wall.normal.x() > 0.0 && (left_wall_ < 0 || wall.point_m.x() > left_x_)) {
      left_wall_ = w, left_x_ = wall.point_m.x();
    } else if (wall.normal.x() < 0.0 && (right_wall_ < 0 || wall.point_m.x() < right_x_)) {
      right_wall_ = w, right_x_ = wall.point_m.x();
    }
  }
  rebuild();
}

void LineEngine::rebuild() {
  const std::size_t units = state_.units.size();
  order_.clear();
  left_m_.assign(units, 0.0);
  right_m_.assign(units, 0.0);
  first_body_.assign(units, -1);
  last_body_.assign(units, -1);
  inverse_mass_.assign(units, 0.0);
  for (int body : body_order_) {
    const BodyLink& link = state_.bodies[body];
    const double half = model_.half_size_m[body];
    const int id = link.unit;
    if (first_body_[id] < 0) {
      order_.push_back(id);
      first_body_[id] = body;
      left_m_[id] = link.offset_m.x() - half;
    }
    last_body_[id] = body;
    right_m_[id] = link.offset_m.x() + half;
  }
  for (std::size_t id = 0; id < units; ++id) {
    const UnitState& u = state_.units[id];
    inverse_mass_[id] = u.attached ? 0.0 : 1.0 / u.mass_kg;
  }
  if (friction_) frictionTables();
  if (drag_) dragTables();
  const int slots = static_cast<int>(order_.size()) + 1;
  slot_mass_.assign(slots, 0.0);
  for (int j = 1; j + 1 < slots; ++j) {
    const double inv = inverse_mass_[order_[j - 1]] + inverse_mass_[order_[j]];
    slot_mass_[j] = inv > 0.0 ? 1.0 / inv : 0.0;
  }
  leaves_ = 1;
  while (leaves_ < slots) leaves_ *= 2;
  slot_time_.assign(slots, kNever);
  tree_.assign(2 * leaves_, -1);
  for (int j = 0; j < slots; ++j) {
    tree_[leaves_ + j] = j;
    slot_time_[j] = predict(j);
  }
  // Ties go to the lower slot: a total order, so equal times replay identically.
  auto winner = [&](int a, int b) {
    if (a < 0) return b;
    if (b < 0) return a;
    return slot_time_[b] < slot_time_[a] ? b : a;
  };
  for (int node = leaves_ - 1; node >= 1; --node) {
    tree_[node] = winner(tree_[2 * node], tree_[2 * node + 1]);
  }
  two_bodies_ = twoBodyFastPathApplies();
  wall_pair_ = wallPairApplies();
}

int LineEngine::earliest() const {
  const int slots = static_cast<int>(slot_time_.size());
  if (slots > kScanSlots) return tree_[1];
  int best = 0;
  for (int j = 1; j < slots; ++j) best = slot_time_[j] < slot_time_[best] ? j : best;
  return best;
}

void LineEngine::refresh(int slot) {
  setSlot(slot, predict(slot));
}

void LineEngine::setSlot(int slot, double time) {
  slot_time_[slot] = time;
  if (static_cast<int>(slot_time_.size()) <= kScanSlots) return;
  for (int node = (leaves_ + slot) / 2; node >= 1; node /= 2) {
    const int a = tree_[2 * node], b = tree_[2 * node + 1];
    tree_[node] = a < 0 ? b : (b < 0 ? a : (slot_time_[b] < slot_time_[a] ? b : a));
  }
}

double LineEngine::predict(int slot) const {
  const int units = static_cast<int>(order_.size());
  if (slot == 0) return predictWall(true);
  if (slot == units) return predictWall(false);
  return predictPair(slot);
}

// Every prediction is a pure function of the current states of the units involved.
double LineEngine::predictWall(bool left) const {
  const int wall = left ? left_wall_ : right_wall_;
  if (wall < 0 || order_.empty()) return kNever;
  const int id = left ? order_.front() : order_.back();
  if (inverse_mass_[id] == 0.0) return kNever;  // attached
  if (drag_ && hasDrag(state_.units[id])) {
    return left ? predictDragged(-1, id) : predictDragged(id, -1);
  }
  const UnitState& u = state_.units[id];
  const double x = u.x_ref_m.x(), v = u.v_mps.x(), a = accelerated_ ? u.a_mps2.x() : 0.0;
  const double gap = left ? x + left_m_[id] - left_x_ : right_x_ - x - right_m_[id];
  // Touching the wall at a round-off speed with nothing pressing it on: at rest there.
  if (gap <= 0.0 && a == 0.0 && model_.closingIsRoundOff(v, v, 0.0)) return kNever;
  const double tau = left ? firstClosingRoot(gap, v, 0.5 * a) : firstClosingRoot(gap, -v, -0.5 * a);
  return beforeStops(u.t_ref_s + tau, id, -1);
}

double LineEngine::predictPair(int slot) const {
  const int l = order_[slot - 1], r = order_[slot];
  if (slot_mass_[slot] == 0.0) return kNever;  // both attached
  if (drag_ && (hasDrag(state_.units[l]) || hasDrag(state_.units[r]))) return predictDragged(l, r);
  const UnitState &ul = state_.units[l], &ur = state_.units[r];
  const double t0 = std::max(ul.t_ref_s, ur.t_ref_s);
  const double gap = (positionAt(ur, t0) + left_m_[r]) - (positionAt(ul, t0) + right_m_[l]);
  const double closing = velocityAt(ur, t0) - velocityAt(ul, t0);
  const double c2 = accelerated_ ? 0.5 * (ur.a_mps2.x() - ul.a_mps2.x()) : 0.0;
  // Touching and closing at a speed their velocities cannot resolve: an impact would change
  // nothing representable and come due again at once (an endless rattle at one instant, the end
  // of every converged inelastic collapse). They move together: the limit of those impacts.
  if (gap <= 0.0 && c2 == 0.0 &&
      model_.closingIsRoundOff(closing, velocityAt(ul, t0), velocityAt(ur, t0))) {
    return kNever;
  }
  return beforeStops(t0 + firstClosingRoot(gap, closing, c2), l, r);
}

// Flattened: the impact handlers inline into the loop, which keeps the hot state in registers.
[[gnu::flatten]] RunStop LineEngine::run(double t_end_s, std::int64_t count_limit) {
  if (friction_) return runWithFriction(t_end_s, count_limit);
  const std::int64_t cap = model_.world.max_collisions;
  for (;;) {
    if (state_.collision_count >= count_limit) return RunStop::kCountLimit;
    if (wall_pair_) {
      RunStop stop;
      if (runWallPair(t_end_s, count_limit, stop)) return stop;
    } else if (two_bodies_ && !out_.wants(state_.collision_count)) {
      RunStop stop;
      if (runTwoBodies(t_end_s, count_limit, stop)) return stop;
    }
    const int slot = earliest();
    const double t = slot_time_[slot];
    if (const double t_release = nextReleaseTime(); t_release <= t) {
      // A release due no later than the next impact acts first (releases are few: one
      // comparison per event costs nothing measurable).
      if (!(t_release <= t_end_s)) return RunStop::kDone;
      if (state_.collision_count >= cap) return RunStop::kCollisionCap;
      state_.time_s = t_release;
      applyRelease(t_release);
      continue;
    }
    if (!(t <= t_end_s)) return RunStop::kDone;
    if (state_.collision_count >= cap) return RunStop::kCollisionCap;
    if (rate_guard_.exceeded(state_.collision_count, t)) {
      stopForRate();
      return RunStop::kRateCap;
    }
    if (t == state_.time_s) {
      if (++same_time_events_ > kLineStallEventCount) return RunStop::kStalled;
    } else {
      same_time_events_ = 0;
    }
    state_.time_s = t;
    // Impacts due within rounding of t form one round (docs/physics.md): with a handful of slots
    // a scan finds them, otherwise the tree's subtrees whose earliest time is within reach.
    const double window = t + kTieUlps * kEpsilon * std::abs(t);
    const int slots = static_cast<int>(slot_time_.size());
    int due = 0;
    if (slots <= kScanSlots) {
      for (int j = 0; j < slots; ++j) due += slot_time_[j] <= window;
    } else {
      due = 2;  // let resolveRound look
    }
    if (due > 1) {
      resolveRound(t);
      continue;
    }
    const int units = static_cast<int>(order_.size());
    if (slot == 0 || slot == units) {
      wallImpact(slot == 0, t);
    } else {
      pairImpact(slot, t);
    }
  }
}

LineEngine::Impact LineEngine::wallImpactRecord(double t, int body, int wall, double n, double v,
                                                double u, double m, const ImpactDecision& d) {
  Impact impact;
  impact.t_s = t;
  impact.body_a = body;
  impact.body_b = kWallPartnerBase - wall;
  impact.normal_x = -n;
  impact.va_before = v;
  impact.closing_mps = u;
  impact.decision = d;
  // Booked analytically: exactly 0 for e = 1; a gain (e > 1) is booked as released.
  impact.lost_analytic_J = 0.5 * m * (1.0 - d.e * d.e) * u * u;
  return impact;
}

void LineEngine::wallImpact(bool left, double t) {
  const int id = left ? order_.front() : order_.back();
  UnitState& unit = state_.units[id];
  advance(unit, t);
  const int body = left ? first_body_[id] : last_body_[id];
  const double n = left ? 1.0 : -1.0;  // wall normal, into free space
  const double v = unit.v_mps.x();
  const double u = std::max(-v * n, 0.0);  // approach speed
  const double a_push = wallPush(id, n);
  const int wall = left ? left_wall_ : right_wall_;
  const double window = model_.collapse_window_s;
  const std::int32_t burst = state_.burstAt(body, t, window);
  const ImpactDecision d = decideRestitution(model_, model_.world.walls[wall].restitution, u, burst,
                                             burst, a_push, body, kWallPartnerBase - wall);
  if (d.e == 0.0 || soft_) {
    specialWallImpact(left, t, u, a_push, d);
    return;
  }
  const double v_after = v + (1.0 + d.e) * u * n;
  unit.v_mps.x() = v_after;
  const double m = unit.mass_kg;
  // Booked analytically: exactly 0 for e = 1; a gain (e > 1) is booked as released.
  const double lost = 0.5 * m * (1.0 - d.e * d.e) * u * u;
  state_.noteImpact(body, t, window);
  if (out_.wants(state_.collision_count)) {
    Impact impact = wallImpactRecord(t, body, wall, n, v, u, m, d);
    impact.va_after = v_after;
    impact.impulse_Ns = m * (1.0 + d.e) * u;
    impact.lost_J = lost;
    record(impact);
  }
  finish(lost, d, t);
  // The wall's own slot, then the neighbouring gap (or the other wall for a lone unit).
  // Without acceleration a unit leaving the wall never returns to it: that is exactly what
  // predictWall would find (c1 > 0, c2 = 0), so skip the computation.
  const int units = static_cast<int>(order_.size());
  const bool leaving = !accelerated_ && v_after * n > 0.0;
  if (left) {
    setSlot(0, leaving ? kNever : predictWall(true));
    setSlot(1, units == 1 ? predictWall(false) : predictPair(1));
  } else {
    setSlot(units, leaving ? kNever : predictWall(false));
    setSlot(units - 1, units == 1 ? predictWall(true) : predictPair(units - 1));
  }
}

void LineEngine::pairImpact(int slot, double t) {
  const int l = order_[slot - 1], r = order_[slot];
  UnitState &ul = state_.units[l], &ur = state_.units[r];
  advance(ul, t);
  advance(ur, t);
  const int a = last_body_[l], b = first_body_[r];
  const double vl = ul.v_mps.x(), vr = ur.v_mps.x();
  const double u = std::max(vl - vr, 0.0);  // closing speed
  const double inv_l = inverse_mass_[l], inv_r = inverse_mass_[r];
  // Acceleration pressing a free unit onto an attached one (gravity towards a wall).
  const double a_push = pairPush(l, r);
  const double window = model_.collapse_window_s;
  const ImpactDecision d =
      decideRestitution(model_, model_.pairRestitution(a, b), u, state_.burstAt(a, t, window),
                        state_.burstAt(b, t, window), a_push, a, b);
  if (d.e == 0.0 || soft_) {
    specialPairImpact(slot, t, u, d);
    return;
  }
  // Impulse along the normal from the velocity difference, never from m1 - e m2 (which loses
  // the small mass entirely when the ratio is 1e14): J = (1 + e) u m_eff.
  const double m_eff = slot_mass_[slot];
  const double impulse = (1.0 + d.e) * u * m_eff;
  const double vl_after = vl - impulse * inv_l, vr_after = vr + impulse * inv_r;
  ul.v_mps.x() = vl_after;
  ur.v_mps.x() = vr_after;
  // Booked analytically (the kinetic energies before and after would cancel catastrophically:
  // 1e-12 kg against 1e12 kg loses every digit of the light block's share).
  const double lost = 0.5 * m_eff * (1.0 - d.e * d.e) * u * u;
  state_.noteImpact(a, t, window);
  state_.noteImpact(b, t, window);
  if (out_.wants(state_.collision_count)) {
    Impact impact;
    impact.t_s = t;
    impact.body_a = a;
    impact.body_b = b;
    impact.va_before = vl;
    impact.va_after = vl_after;
    impact.vb_before = vr;
    impact.vb_after = vr_after;
    impact.closing_mps = u;
    impact.impulse_Ns = impulse;
    impact.lost_J = impact.lost_analytic_J = lost;
    impact.decision = d;
    record(impact);
  }
  finish(lost, d, t);
  const int units = static_cast<int>(order_.size());
  setSlot(slot - 1, slot == 1 ? predictWall(true) : predictPair(slot - 1));
  // Likewise a separating pair without acceleration never meets again (c1 > 0, c2 = 0).
  const bool separating = !accelerated_ && vr_after - vl_after > 0.0;
  setSlot(slot, separating ? kNever : predictPair(slot));
  setSlot(slot + 1, slot + 1 == units ? predictWall(false) : predictPair(slot + 1));
}

std::unique_ptr<Engine> makeLineEngine(const Model& model, EngineState start, const Recorder& out) {
  return std::make_unique<LineEngine>(model, std::move(start), out);
}

}  // namespace collide::physics::detail
