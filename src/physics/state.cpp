// Initial engine state and exact evaluation of body states between events.
#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/drag_motion.hpp"
#include "physics/engine.hpp"
#include "physics/rolling_law.hpp"

namespace collide::physics::detail {
namespace {

core::Vec2 rotatedBy(const core::Vec2& v, double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

// Unit centre of mass at t inside a soft-contact track: cubic Hermite between samples.
void trackAt(const Track& track, double t, core::Vec2& x, core::Vec2& v) {
  const auto& ts = track.time_s;
  std::size_t k = std::upper_bound(ts.begin(), ts.end(), t) - ts.begin();
  k = std::clamp<std::size_t>(k, 1, ts.size() - 1);
  const double h = ts[k] - ts[k - 1];
  const double s = h > 0.0 ? std::clamp((t - ts[k - 1]) / h, 0.0, 1.0) : 1.0;
  const core::Vec2 &x0 = track.position_m[k - 1], &x1 = track.position_m[k];
  const core::Vec2 &v0 = track.velocity_mps[k - 1], &v1 = track.velocity_mps[k];
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  x = h00 * x0 + h10 * h * v0 + h01 * x1 + h11 * h * v1;
  v = (1 - s) * v0 + s * v1;
}

// What friction has taken up to t_s: the booked pieces of motion, and of each unit's piece in
// progress (since t_ref_s) its work m |f| |x(t) - x_ref| and impulse m f (t - t_ref).
void addSurfaceShare(const Model& model, const EngineState& state, double t_s, Snapshot& snap) {
  EnergyLedger energy = state.energy_to_surface;
  EnergyLedger impulse_x = state.friction_impulse_x, impulse_y = state.friction_impulse_y;
  for (const UnitState& unit : state.units) {
    if (!unit.alive || !(t_s > unit.t_ref_s)) continue;
    const double dt = t_s - unit.t_ref_s;
    if (model.world.rolling) {
      energy.add(clothWork(unit, dt));
    } else {
      const core::Vec2 step = unit.v_mps * dt + 0.5 * unit.a_mps2 * dt * dt;
      energy.add(-unit.mass_kg * unit.friction_mps2.dot(step));
    }
    impulse_x.add(unit.mass_kg * unit.friction_mps2.x() * dt);
    impulse_y.add(unit.mass_kg * unit.friction_mps2.y() * dt);
  }
  snap.energy_to_surface_J = energy.total_J();
  snap.surface_momentum_kgmps = {-impulse_x.total_J(), -impulse_y.total_J()};
}

// What air drag has taken up to t_s: the booked pieces of motion and each unit's piece in
// progress.
void addAirShare(const EngineState& state, double t_s, Snapshot& snap) {
  EnergyLedger energy = state.energy_to_air;
  for (const UnitState& unit : state.units) {
    if (!unit.alive || !hasDrag(unit) || !(t_s > unit.t_ref_s)) continue;
    energy.add(dragWork(unit, t_s - unit.t_ref_s));
  }
  snap.energy_to_air_J = energy.total_J();
}

}  // namespace

EngineState initialState(const Model& model) {
  EngineState state;
  const WorldDef& world = model.world;
  const int n = static_cast<int>(world.bodies.size());
  for (int i = 0; i < n; ++i) {
    const BodyDef& body = world.bodies[i];
    UnitState unit;
    unit.x_ref_m = body.position_m;
    unit.v_mps = body.velocity_mps;
    unit.a_mps2 = world.gravity_mps2;
    if (world.dimensions == 1) {
      unit.x_ref_m.y() = 0.0;
      unit.v_mps.y() = 0.0;
      unit.a_mps2.y() = 0.0;
    }
    unit.mass_kg = body.mass_kg;
    unit.inertia_kgm2 = model.spin_inertia_kgm2[i];
    if (model.has_friction && world.dimensions == 1) {
      // As the line engine sets it after every event (line_friction.cpp), so that the start's
      // motion holds until the first event.
      const double g_n = world.surface_gravity_mps2;
      unit.friction_mps2.x() =
          frictionAlongLine(unit.v_mps.x(), unit.a_mps2.x(), body.friction * g_n,
                            std::max(body.static_friction, body.friction) * g_n);
      unit.a_mps2.x() += unit.friction_mps2.x();
    }
    if (world.rolling) {
      // As the plane engine sets it after every event (plane_rolling.cpp).
      unit.spin_radps = body.spin_radps;
      setRollingLaw(unit, clothOf(world, i));
    } else if (model.has_friction && world.dimensions == 2) {
      // As the plane engine sets it after every event (plane_friction.cpp).
      unit.friction_mps2 = frictionInPlane(unit.v_mps, body.friction * world.surface_gravity_mps2);
      unit.a_mps2 += unit.friction_mps2;
    }
    if (model.has_drag) {
      unit.drag_rate_per_s = body.drag_linear_kgps / body.mass_kg;
      unit.drag_per_m = body.drag_quadratic_kgpm / body.mass_kg;
    }
    state.units.push_back(unit);
    state.bodies.push_back(BodyLink{i, {0.0, 0.0}, 0.0});
  }
  if (model.has_strings) state.swings = initialSwings(model);
  if (world.internal_dof > 0) {
    state.internal_J.assign(n, 0.0);
    state.internal_rng = world.internal_seed;
  }
  state.last_impact_s.assign(n, -std::numeric_limits<double>::infinity());
  state.burst_impacts.assign(n, 0);
  state.cluster_impacts.assign(n, 0);
  state.cluster_start_s.assign(n, -std::numeric_limits<double>::infinity());
  return state;
}

BodyState evaluateBody(const Model& model, const EngineState& state, int body, double t_s) {
  const BodyLink& link = state.bodies[body];
  const UnitState& unit = state.units[link.unit];
  core::Vec2 x, v;
  double angle;
  if (!state.swings.empty() && state.swings[link.unit].taut) {
    const SwingKinematics swing =
        swingAt(state.swings[link.unit], -model.world.gravity_mps2.y(), t_s);
    return {swing.position_m + link.offset_m, swing.velocity_mps, 0.0, 0.0};
  }
  if (unit.track && t_s < unit.t_ref_s) {
    trackAt(*unit.track, t_s, x, v);
    angle = unit.angle_ref_rad;
  } else if (hasDrag(unit) && !unit.attached) {
    const DragState motion = dragMotion(unit, t_s - unit.t_ref_s);
    x = motion.position_m;
    v = motion.velocity_mps;
    angle = unit.angle_ref_rad + unit.omega_radps * (t_s - unit.t_ref_s);
  } else {
    const double dt = t_s - unit.t_ref_s;
    x = unit.x_ref_m + unit.v_mps * dt + 0.5 * unit.a_mps2 * dt * dt;
    v = unit.v_mps + unit.a_mps2 * dt;
    angle = unit.angle_ref_rad + unit.omega_radps * dt;
  }
  BodyState out;
  if (unit.omega_radps == 0.0 && unit.angle_ref_rad == 0.0) {
    out.position_m = x + link.offset_m;
    out.velocity_mps = v;
  } else {
    const core::Vec2 r = rotatedBy(link.offset_m, angle);
    out.position_m = x + r;
    out.velocity_mps = v + unit.omega_radps * core::Vec2(-r.y(), r.x());
  }
  out.angle_rad = angle + link.angle_offset_rad;
  out.angular_velocity_radps = unit.omega_radps;
  if (model.world.rolling)
    out.spin_radps = unit.spin_radps + unit.spin_rate_radps2 * (t_s - unit.t_ref_s);
  return out;
}

Snapshot evaluate(const Model& model, const EngineState& state, double t_s) {
  Snapshot snap;
  snap.time_s = t_s;
  snap.energy_lost_J = state.energy_lost.total_J();
  snap.energy_released_J = state.energy_released.total_J();
  for (double internal_J : state.internal_J) snap.internal_energy_J += internal_J;
  snap.collision_count = static_cast<int>(state.collision_count);
  snap.release_count = static_cast<int>(state.releases_applied);
  if (model.has_friction) addSurfaceShare(model, state, t_s, snap);
  if (model.has_drag) addAirShare(state, t_s, snap);
  const int n = static_cast<int>(state.bodies.size());
  snap.bodies.reserve(n);
  for (int i = 0; i < n; ++i) snap.bodies.push_back(evaluateBody(model, state, i, t_s));
  return snap;
}

}  // namespace collide::physics::detail
