// SPDX-License-Identifier: MIT
// Air drag on a line: the 1D engine's units under drag. See line_engine.hpp and docs/physics.md
// ("Air drag").
//
// A unit's drag is the sum of its bodies' (forces add: k = sum k_i, c = sum c_i), over its mass.
// Between events it moves by drag's closed forms (drag_motion.hpp); the drag's work is booked per
// piece of motion; a time of impact with a dragged unit is the first zero of the gap, bracketed
// and refined to round-off (drag_contact.hpp).
#include <cmath>
#include <limits>

#include "physics/drag_contact.hpp"
#include "physics/line_engine.hpp"

namespace collide::physics::detail {
namespace {

constexpr double kRoundOff = std::numeric_limits<double>::epsilon();

// One side of a gap: a unit's face (its centre plus face_m), or a wall (unit null) at face_m.
struct GapSide {
  const UnitState* unit = nullptr;
  double face_m = 0.0;
};

struct SideMotion {
  double x_m = 0.0, v_mps = 0.0, a_mps2 = 0.0, terminal_mps = 0.0;
};

SideMotion sideAt(const GapSide& side, double t) {
  if (side.unit == nullptr) return {side.face_m, 0.0, 0.0, 0.0};
  const UnitState& u = *side.unit;
  const double dt = t - u.t_ref_s;
  if (u.attached) return {u.x_ref_m.x() + side.face_m, 0.0, 0.0, 0.0};
  if (hasDrag(u)) {
    const DragState m = dragMotion(u, dt);
    return {m.position_m.x() + side.face_m, m.velocity_mps.x(),
            dragAcceleration(u, m.velocity_mps).x(), terminalVelocity(u).x()};
  }
  const double g = u.a_mps2.x();
  return {u.x_ref_m.x() + u.v_mps.x() * dt + 0.5 * g * dt * dt + side.face_m, u.v_mps.x() + g * dt,
          g, terminalVelocity(u).x()};
}

}  // namespace

void LineEngine::dragTables() {
  const WorldDef& world = model_.world;
  for (UnitState& unit : state_.units) unit.drag_rate_per_s = unit.drag_per_m = 0.0;
  for (std::size_t body = 0; body < state_.bodies.size(); ++body) {
    UnitState& unit = state_.units[state_.bodies[body].unit];
    unit.drag_rate_per_s += world.bodies[body].drag_linear_kgps;
    unit.drag_per_m += world.bodies[body].drag_quadratic_kgpm;
  }
  for (UnitState& unit : state_.units) {
    if (unit.attached) {
      unit.drag_rate_per_s = unit.drag_per_m = 0.0;
    } else {
      unit.drag_rate_per_s /= unit.mass_kg;
      unit.drag_per_m /= unit.mass_kg;
    }
  }
}

void LineEngine::advanceDragged(UnitState& u, double t) {
  const double dt = t - u.t_ref_s;
  state_.energy_to_air.add(dragWork(u, dt));
  const DragState m = dragMotion(u, dt);
  u.x_ref_m.x() = m.position_m.x();
  u.v_mps.x() = m.velocity_mps.x();
  u.t_ref_s = t;
}

double LineEngine::accelerationNow(int id) const {
  const UnitState& u = state_.units[id];
  if (u.attached) return 0.0;
  return hasDrag(u) ? dragAcceleration(u, u.v_mps).x() : u.a_mps2.x();
}

double LineEngine::predictDragged(int l, int r) const {
  const GapSide left = l < 0 ? GapSide{nullptr, left_x_} : GapSide{&state_.units[l], right_m_[l]};
  const GapSide right = r < 0 ? GapSide{nullptr, right_x_} : GapSide{&state_.units[r], left_m_[r]};
  const double t0 =
      std::max(left.unit ? left.unit->t_ref_s : 0.0, right.unit ? right.unit->t_ref_s : 0.0);
  const double end = model_.world.duration_s;
  if (!(t0 <= end)) return kNever;
  auto gap_at = [&](double t) {
    const SideMotion a = sideAt(left, t), b = sideAt(right, t);
    DraggedGap g;
    g.gap_m = b.x_m - a.x_m;
    g.rate_mps = b.v_mps - a.v_mps;
    g.accel_mps2 = b.a_mps2 - a.a_mps2;
    g.touch_m = kTieUlps * kRoundOff * std::max(std::abs(a.x_m), std::abs(b.x_m));
    g.curvature_mps2 = std::abs(a.a_mps2) + std::abs(b.a_mps2);
    g.rate_floor_mps = std::min(b.v_mps, b.terminal_mps) - std::max(a.v_mps, a.terminal_mps);
    return g;
  };
  // Closing speeds a few units of rounding of the scene's speeds are none (as closingIsRoundOff).
  const double floor = kTieUlps * kRoundOff * model_.speed_scale_mps;
  return firstDraggedContact_s(gap_at, t0, end, floor);
}

}  // namespace collide::physics::detail
