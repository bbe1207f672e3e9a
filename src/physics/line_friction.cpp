// SPDX-License-Identifier: MIT
// Sliding friction on a line: the 1D engine's laws of motion with friction, its stops and its
// event loop. See line_engine.hpp and docs/physics.md ("Sliding friction").
//
// A unit slides with kinetic friction against its velocity, f = -sign(v) k (k = mu_k g_n, mass-
// weighted over its bodies), plus gravity along the line: between events its motion is exactly
// quadratic. When v reaches 0 (a stop, t = t_ref - v/a) static friction holds it while gravity
// along the line is within mu_s g_n; otherwise it slides off the other way. Friction's work
// m |f| |dx| and impulse m f dt are booked per piece of motion, never as a difference of kinetic
// energies.
#include <cmath>
#include <limits>

#include "physics/line_engine.hpp"
#include "physics/toi.hpp"

namespace collide::physics::detail {
namespace {

constexpr double kRoundOff = std::numeric_limits<double>::epsilon();

}  // namespace

void LineEngine::frictionTables() {
  const std::size_t units = state_.units.size();
  kinetic_decel_.assign(units, 0.0);
  static_decel_.assign(units, 0.0);
  const WorldDef& world = model_.world;
  const double g_n = world.surface_gravity_mps2;
  for (std::size_t body = 0; body < state_.bodies.size(); ++body) {
    const BodyDef& def = world.bodies[body];
    const int id = state_.bodies[body].unit;
    kinetic_decel_[id] += def.friction * def.mass_kg * g_n;
    static_decel_[id] += std::max(def.static_friction, def.friction) * def.mass_kg * g_n;
  }
  for (std::size_t id = 0; id < units; ++id) {
    kinetic_decel_[id] /= state_.units[id].mass_kg;
    static_decel_[id] /= state_.units[id].mass_kg;
  }
}

void LineEngine::setFrictionLaw(int id) {
  UnitState& u = state_.units[id];
  if (u.attached) {
    u.friction_mps2.setZero();
    u.a_mps2.setZero();
    return;
  }
  const double g = model_.world.gravity_mps2.x();
  const double f = frictionAlongLine(u.v_mps.x(), g, kinetic_decel_[id], static_decel_[id]);
  u.friction_mps2.x() = f;
  u.a_mps2.x() = g + f;
}

double LineEngine::pushAtRest(int id, double n) const {
  const double g = model_.world.gravity_mps2.x();
  if (std::abs(g) <= static_decel_[id]) return 0.0;
  const double a = g > 0.0 ? g - kinetic_decel_[id] : g + kinetic_decel_[id];
  return -a * n;
}

double LineEngine::stopTime(int id) const {
  const UnitState& u = state_.units[id];
  const double v = u.v_mps.x(), a = u.a_mps2.x();
  // Only kinetic friction stops a unit; gravity alone turns it round without an event.
  if (u.friction_mps2.x() == 0.0 || v == 0.0 || !(v * a < 0.0)) return kNever;
  return u.t_ref_s + (-v / a);
}

void LineEngine::bookFriction(const UnitState& u, double t) {
  const double f = u.friction_mps2.x();
  if (f == 0.0) return;
  const double dt = t - u.t_ref_s;
  const double dx = u.v_mps.x() * dt + 0.5 * u.a_mps2.x() * dt * dt;
  state_.energy_to_surface.add(-u.mass_kg * f * dx);
  state_.friction_impulse_x.add(u.mass_kg * f * dt);
}

void LineEngine::stopUnit(int id, double t) {
  UnitState& u = state_.units[id];
  const double v = u.v_mps.x(), a = u.a_mps2.x(), f = u.friction_mps2.x();
  // The distance to rest in closed form, v^2 / (2|a|): the same to rounding as the position
  // at t, without the difference of two nearly equal terms.
  const double dx = -0.5 * v * v / a;
  state_.energy_to_surface.add(-u.mass_kg * f * dx);
  state_.friction_impulse_x.add(u.mass_kg * f * (t - u.t_ref_s));
  u.x_ref_m.x() += dx;
  u.v_mps.x() = 0.0;
  u.t_ref_s = t;
  ++state_.string_events;  // an event, no collision: sampling replays across it
  setFrictionLaw(id);
}

// Two touching units, the one behind pushed onto the one ahead (less friction behind), that
// would bounce apart by less than the rounding of their positions (or close at a speed their
// velocities cannot resolve):
// they slide on as one, the limit of their ever shorter bounces (like a ball settling on a
// floor, docs/physics.md). Without this an elastic pair would bounce for ever, ever faster, and
// an impact at a round-off speed would come due again at once. The kinetic energy of their
// relative motion, 1/2 mu u^2, is booked as lost.
bool LineEngine::joinPressingPair() {
  const double t = state_.time_s;
  const int units = static_cast<int>(order_.size());
  for (int slot = 1; slot < units; ++slot) {
    if (slot_mass_[slot] == 0.0) continue;
    const int l = order_[slot - 1], r = order_[slot];
    UnitState &ul = state_.units[l], &ur = state_.units[r];
    const double xl = positionAt(ul, t) + right_m_[l], xr = positionAt(ur, t) + left_m_[r];
    // Touching: apart by no more than the rounding of their positions.
    const double touching = kTieUlps * kRoundOff * std::max(std::abs(xl), std::abs(xr));
    const double vl = velocityAt(ul, t), vr = velocityAt(ur, t);
    const double pressing = ul.a_mps2.x() - ur.a_mps2.x();
    if (!(xr - xl <= touching) || !(pressing > 0.0)) continue;
    const double u = vl - vr;
    if (!(u * u <= 2.0 * pressing * touching) && !model_.closingIsRoundOff(u, vl, vr)) {
      continue;
    }
    advance(ul, t);
    advance(ur, t);
    state_.book(0.5 * slot_mass_[slot] * (vl - vr) * (vl - vr));
    joinUnits(slot, t);
    rebuild();
    return true;
  }
  return false;
}

void LineEngine::settleFriction() {
  for (int id : order_) setFrictionLaw(id);
  while (joinPressingPair()) {
    for (int id : order_) setFrictionLaw(id);
  }
  const int slots = static_cast<int>(slot_time_.size());
  for (int j = 0; j < slots; ++j) refresh(j);
}

void LineEngine::impactAt(int slot, double t) {
  // Impacts due within rounding of t form one round (docs/physics.md).
  const double window = t + kTieUlps * kRoundOff * std::abs(t);
  int due = 0;
  for (double time : slot_time_) due += time <= window;
  if (due > 1) {
    resolveRound(t);
    return;
  }
  const int units = static_cast<int>(order_.size());
  if (slot == 0 || slot == units) {
    wallImpact(slot == 0, t);
  } else {
    pairImpact(slot, t);
  }
}

// run() for scenes with friction: the next event is the earliest of the units' stops, the
// releases and the impacts. Stops count no collision, so the count limit waits for the next
// impact (a replay to time t must still see the stops after the last collision).
RunStop LineEngine::runWithFriction(double t_end_s, std::int64_t count_limit) {
  const std::int64_t cap = model_.world.max_collisions;
  for (;;) {
    settleFriction();
    int stopping = -1;
    double t_stop = kNever;
    for (int id : order_) {
      const double time = stopTime(id);
      if (time < t_stop) stopping = id, t_stop = time;
    }
    const int slot = earliest();
    const double t = slot_time_[slot];
    const double t_release = nextReleaseTime();
    const double t_next = std::min({t_stop, t, t_release});
    if (!(t_next <= t_end_s)) return RunStop::kDone;
    if (t_stop != t_next) {
      if (state_.collision_count >= count_limit) return RunStop::kCountLimit;
      if (state_.collision_count >= cap) return RunStop::kCollisionCap;
    }
    if (t_next == state_.time_s) {
      if (++same_time_events_ > kLineStallEventCount) return RunStop::kStalled;
    } else {
      same_time_events_ = 0;
    }
    if (t_stop == t_next) {
      state_.time_s = std::max(state_.time_s, t_stop);
      stopUnit(stopping, t_stop);
      continue;
    }
    state_.time_s = t_next;
    if (t_release == t_next) {
      applyRelease(t_release);
      continue;
    }
    if (rate_guard_.exceeded(state_.collision_count, t)) {
      stopForRate();
      return RunStop::kRateCap;
    }
    impactAt(slot, t);
  }
}

}  // namespace collide::physics::detail
