// The string engine: state, kinematics and the event loop (see string_engine.hpp).
#include "physics/string_engine.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace collide::physics::detail {
namespace {

// A radial speed this small next to the speed is rounding of a velocity along the string's
// normal, not motion along the string.
constexpr double kRadialRounding = 1e-12;
// Events at one instant beyond this count mean the run cannot progress.
constexpr std::int64_t kStringStallEventCount = 10000;

}  // namespace

SwingKinematics swingAt(const SwingState& swing, double gravity_m_s2, double t_s) {
  const PendulumArc arc(swing.length_m, gravity_m_s2, swing.start);
  const PendulumState s = arc.at(t_s - swing.t_ref_s);
  return {swing.pivot_m + pendulumPosition_m(swing.length_m, s.angle_rad),
          pendulumVelocity_m_s(swing.length_m, s)};
}

std::vector<SwingState> initialSwings(const Model& model) {
  const WorldDef& world = model.world;
  const double g = -world.gravity_mps2.y();
  COLLIDE_ASSERT(world.dimensions == 2 && g > 0.0 && world.gravity_mps2.x() == 0.0,
                 "initialSwings: strings need a 2D world with gravity along -y");
  std::vector<SwingState> swings(world.bodies.size());
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const BodyDef& body = world.bodies[i];
    if (!body.on_string) continue;
    SwingState& swing = swings[i];
    swing.has_string = true;
    swing.pivot_m = body.pivot_m;
    const core::Vec2 offset = body.position_m - body.pivot_m;
    swing.length_m = offset.norm();
    COLLIDE_ASSERT(swing.length_m > 0.0, "initialSwings: a string needs a positive length");
    swing.start = pendulumStateOf(offset, body.velocity_mps);
    // Taut if the string can pull (tension >= 0) and the body does not move along it; a body
    // moving inwards starts slack, one moving outwards starts slack and snaps taut at t = 0.
    const double radial = body.velocity_mps.dot(offset) / swing.length_m;
    const double tension =
        swing.length_m * swing.start.angular_velocity_rad_s * swing.start.angular_velocity_rad_s +
        g * std::cos(swing.start.angle_rad);
    swing.taut = std::abs(radial) <= kRadialRounding * body.velocity_mps.norm() && tension >= 0.0;
  }
  return swings;
}

StringEngine::StringEngine(const Model& model, EngineState start, const Recorder& out)
    : model_(model), state_(std::move(start)), out_(out) {
  gravity_m_s2_ = -model.world.gravity_mps2.y();
  if (state_.swings.empty()) state_.swings = initialSwings(model);
  arcs_.resize(state_.units.size());
  for (int u = 0; u < static_cast<int>(state_.units.size()); ++u) refreshArc(u);
}

void StringEngine::refreshArc(int unit) {
  const SwingState& swing = state_.swings[unit];
  if (swing.taut) {
    arcs_[unit].emplace(swing.length_m, gravity_m_s2_, swing.start);
  } else {
    arcs_[unit].reset();
  }
}

StringEngine::Kin StringEngine::unitAt(int unit, double t) const {
  if (arcs_[unit]) {
    const SwingState& swing = state_.swings[unit];
    const PendulumState s = arcs_[unit]->at(t - swing.t_ref_s);
    return {swing.pivot_m + pendulumPosition_m(swing.length_m, s.angle_rad),
            pendulumVelocity_m_s(swing.length_m, s)};
  }
  const UnitState& u = state_.units[unit];
  const double dt = t - u.t_ref_s;
  return {u.x_ref_m + u.v_mps * dt + 0.5 * u.a_mps2 * dt * dt, u.v_mps + u.a_mps2 * dt};
}

StringEngine::Kin StringEngine::bodyAt(int body, double t) const {
  const BodyLink& link = state_.bodies[body];
  Kin k = unitAt(link.unit, t);
  k.x += link.offset_m;
  return k;
}

double StringEngine::speedBound(int unit, double t0, double t1) const {
  const Kin k = unitAt(unit, t0);
  if (arcs_[unit]) {
    // Energy: v^2 + 2 g y is constant on the string, largest at the bottom of the circle.
    const SwingState& swing = state_.swings[unit];
    const double drop = k.x.y() - (swing.pivot_m.y() - swing.length_m);
    return std::sqrt(k.v.squaredNorm() + 2.0 * gravity_m_s2_ * std::max(drop, 0.0));
  }
  return k.v.norm() + gravity_m_s2_ * (t1 - t0);
}

double StringEngine::accelBound(int unit, double speed_bound) const {
  if (!arcs_[unit]) return gravity_m_s2_;
  // Gravity plus the tension's pull, T / m = v^2 / L + g cos(theta) <= v^2 / L + g.
  return 2.0 * gravity_m_s2_ + speed_bound * speed_bound / state_.swings[unit].length_m;
}

void StringEngine::record(CollisionEvent event) {
  event.index = state_.collision_count;
  if (out_.wants(event.index)) out_.emit(event);
  ++state_.collision_count;
}

RunStop StringEngine::run(double t_end_s, std::int64_t count_limit) {
  const std::int64_t cap = model_.world.max_collisions;
  for (;;) {
    // The count limit stops before the next collision, not before a string event: a string
    // going slack or taut counts no collision, and a replay to time t (Timeline::sample, limited
    // to the run's collision count) must still see the string events after the last collision.
    const std::optional<Event> next = nextEvent(model_.world.duration_s);
    const bool collision = next && (next->kind == Kind::kPair || next->kind == Kind::kWall);
    if ((!next || collision) && state_.collision_count >= count_limit) return RunStop::kCountLimit;
    if (!next || !(next->time_s <= t_end_s)) return RunStop::kDone;
    if (collision && state_.collision_count >= cap) return RunStop::kCollisionCap;
    if (next->time_s == state_.time_s) {
      // Each event here predicts afresh, so the stall limit is lower than the other engines'.
      if (++same_time_events_ > kStringStallEventCount) return RunStop::kStalled;
    } else {
      same_time_events_ = 0;
    }
    state_.time_s = std::max(state_.time_s, next->time_s);
    switch (next->kind) {
      case Kind::kPair:
        pairImpact(next->a, next->b, next->time_s);
        break;
      case Kind::kWall:
        wallImpact(next->a, next->b, next->time_s);
        break;
      case Kind::kSlack:
        goSlack(next->a, next->time_s);
        break;
      case Kind::kTaut:
        snapTaut(next->a, next->time_s);
        break;
    }
    // Impacts piling up without end (a body bouncing to rest on a wall with e < 1): the string
    // engine has no resting contacts, so the run stops there with a warning.
    if (next->kind == Kind::kPair || next->kind == Kind::kWall) {
      const int body = next->a;
      if (model_.collapse_window_s > 0.0 &&
          state_.burstAt(body, next->time_s, model_.collapse_window_s) > 1000) {
        out_.warn({WarningKind::kStalled, state_.collision_count - 1, next->time_s,
                   "stalled: impacts of \"" + model_.world.bodies[body].name +
                       "\" accumulate without end (a body coming to rest against another or a "
                       "wall), which scenes with strings do not resolve; later states are not "
                       "simulated"});
        return RunStop::kStalled;
      }
      state_.noteImpact(body, next->time_s, model_.collapse_window_s);
    }
  }
}

std::unique_ptr<Engine> makeStringEngine(const Model& model, EngineState start,
                                         const Recorder& out) {
  return std::make_unique<StringEngine>(model, std::move(start), out);
}

}  // namespace collide::physics::detail
