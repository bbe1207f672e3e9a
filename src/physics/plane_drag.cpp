// SPDX-License-Identifier: MIT
// Air drag in the plane: the 2D engine's disks under linear drag (the quadratic part is 1D only).
// See plane_engine.hpp and docs/physics.md ("Air drag").
//
// A disk with drag moves by drag's closed forms (drag_motion.hpp), componentwise linear, so one
// sliding along a wall keeps its velocity along it (its gravity there is the wall's tangential
// part). Times of impact with it are the gap's first zero, bracketed and refined to round-off
// (drag_contact.hpp), from bounds that hold until the end of the run: the speed of each partner
// (a dragged one's at most |v_terminal| + |v - v_terminal|, which only decays; one without drag
// gains at most |g| a second) and the size of its acceleration, which never grows. A pair also
// has the hull of its relative motion (drag_sweep.hpp): where it stays clear of contact over the
// rest of the run the pair never meets, and elsewhere it certifies the span the search may skip.
#include <algorithm>
#include <cmath>
#include <limits>

#include "physics/drag_contact.hpp"
#include "physics/drag_motion.hpp"
#include "physics/drag_sweep.hpp"
#include "physics/plane_engine.hpp"

namespace collide::physics::detail {
namespace {

constexpr double kRoundOff = std::numeric_limits<double>::epsilon();

struct DiskMotion {
  core::Vec2 x, v, a;
  double speed_bound_mps = 0.0;  // |v| from now to the end of the run at most
};

DiskMotion diskAt(const UnitState& u, double t, double end_s) {
  const double dt = t - u.t_ref_s;
  DiskMotion m;
  if (hasDrag(u)) {
    const DragState s = dragMotion(u, dt);
    m.x = s.position_m;
    m.v = s.velocity_mps;
    m.a = dragAcceleration(u, m.v);
    const core::Vec2 terminal = terminalVelocity(u);
    m.speed_bound_mps = terminal.norm() + (m.v - terminal).norm();
    return m;
  }
  m.x = u.x_ref_m + u.v_mps * dt + 0.5 * u.a_mps2 * dt * dt;
  m.v = u.v_mps + u.a_mps2 * dt;
  m.a = u.a_mps2;
  m.speed_bound_mps = m.v.norm() + u.a_mps2.norm() * std::max(end_s - t, 0.0);
  return m;
}

core::Vec2 velocityAt(const UnitState& u, double t) {
  const double dt = t - u.t_ref_s;
  return hasDrag(u) ? dragMotion(u, dt).velocity_mps : core::Vec2(u.v_mps + u.a_mps2 * dt);
}

// Two disks from one instant, and the band within which their gap counts as touching.
struct PairAt {
  const UnitState& a;
  const UnitState& b;
  DiskMotion at_a, at_b;
  double t_s = 0.0;
  double reach_m = 0.0, touch_m = 0.0;
};

// Whether the hull of the pair's relative motion over [t, t + span_s] keeps the centres farther
// apart than reach and the touching band, with room for the hull's own rounding.
bool staysApart(const PairAt& p, double span_s) {
  const SweptVelocities v{p.at_a.v, velocityAt(p.a, p.t_s + span_s), p.at_b.v,
                          velocityAt(p.b, p.t_s + span_s)};
  const double extent_m =
      (p.at_b.x - p.at_a.x).norm() +
      span_s * ((v.b_start_mps - v.a_start_mps).norm() + (v.b_end_mps - v.a_end_mps).norm() +
                (v.b_start_mps - v.a_end_mps).norm() + (v.b_end_mps - v.a_start_mps).norm());
  const double floor_m = sweptDistanceFloor_m(p.at_b.x - p.at_a.x, v, span_s);
  return floor_m > p.reach_m + 2.0 * p.touch_m + kTieUlps * kRoundOff * extent_m;
}

// Halvings or doublings one search for a span may take.
constexpr int kSpanSteps = 60;

// How long from p.t_s the pair surely stays apart: the rest of the run (to end_s) where the hull
// says so; else about the longest span the hull clears (within a factor 2), searched from
// `hint_s` (the span cleared at the search's previous step) by doubling or halving, and never
// less than the span the partners' speed bounds give; 0 where the disks are too close for either.
double clearSpan_s(const PairAt& p, double end_s, double hint_s) {
  const double rest_s = end_s - p.t_s;
  const double room_m = (p.at_b.x - p.at_a.x).norm() - p.reach_m - 2.0 * p.touch_m;
  if (!(rest_s > 0.0) || !(room_m > 0.0)) return 0.0;
  if (staysApart(p, rest_s)) return rest_s;
  const double sure_s = 0.5 * room_m / (p.at_a.speed_bound_mps + p.at_b.speed_bound_mps);
  if (!(sure_s < rest_s)) return rest_s;
  double span_s = std::min(std::max(sure_s, hint_s), 0.5 * rest_s);
  if (span_s > sure_s && !staysApart(p, span_s)) {
    for (int k = 0; k < kSpanSteps && span_s > sure_s; ++k) {
      span_s *= 0.5;
      if (staysApart(p, span_s)) return std::max(span_s, sure_s);
    }
    return sure_s;
  }
  for (int k = 0; k < kSpanSteps && 2.0 * span_s < rest_s; ++k) {
    if (!staysApart(p, 2.0 * span_s)) break;
    span_s *= 2.0;
  }
  return span_s;
}

}  // namespace

PlaneEngine::Kin PlaneEngine::draggedKinematics(int body, double t) const {
  const BodyLink& link = state_.bodies[body];
  const UnitState& u = state_.units[link.unit];
  const DragState motion = dragMotion(u, t - u.t_ref_s);
  Kin k;
  const double angle = u.angle_ref_rad + u.omega_radps * (t - u.t_ref_s);
  const double c = std::cos(angle), s = std::sin(angle);
  k.arm = {c * link.offset_m.x() - s * link.offset_m.y(),
           s * link.offset_m.x() + c * link.offset_m.y()};
  k.x = motion.position_m + k.arm;
  k.v = motion.velocity_mps + u.omega_radps * core::Vec2(-k.arm.y(), k.arm.x());
  return k;
}

void PlaneEngine::advanceDragged(UnitState& u, double t) {
  const double dt = t - u.t_ref_s;
  state_.energy_to_air.add(dragWork(u, dt));
  const DragState s = dragMotion(u, dt);
  u.x_ref_m = s.position_m;
  u.v_mps = s.velocity_mps;
  u.angle_ref_rad += u.omega_radps * dt;
}

double PlaneEngine::predictDraggedPair(int a, int b, double t0) const {
  const UnitState& ua = state_.units[state_.bodies[a].unit];
  const UnitState& ub = state_.units[state_.bodies[b].unit];
  const double end = model_.world.duration_s;
  const double reach = model_.half_size_m[a] + model_.half_size_m[b];
  auto gap_at = [&](double t) {
    const DiskMotion ma = diskAt(ua, t, end), mb = diskAt(ub, t, end);
    const core::Vec2 d = mb.x - ma.x, dv = mb.v - ma.v, da = mb.a - ma.a;
    const double distance = d.norm();
    DraggedGap g;
    g.gap_m = distance - reach;
    const core::Vec2 n = distance > 0.0 ? core::Vec2(d / distance) : core::Vec2(1.0, 0.0);
    g.rate_mps = n.dot(dv);
    // gap'' = (|dv|^2 - rate^2) / distance + n.da; bounded while the disks are apart
    // (distance >= reach) by the partners' speed bounds and accelerations.
    g.accel_mps2 =
        (dv.squaredNorm() - g.rate_mps * g.rate_mps) / std::max(distance, reach) + n.dot(da);
    const double speeds = ma.speed_bound_mps + mb.speed_bound_mps;
    g.curvature_mps2 = speeds * speeds / reach + ma.a.norm() + mb.a.norm();
    g.rate_floor_mps = -speeds;
    g.touch_m = kTieUlps * kRoundOff * std::max({ma.x.norm(), mb.x.norm(), reach});
    return g;
  };
  auto clear_for = [&](double t, double hint_s) {
    const DiskMotion ma = diskAt(ua, t, end), mb = diskAt(ub, t, end);
    const double touch_m = kTieUlps * kRoundOff * std::max({ma.x.norm(), mb.x.norm(), reach});
    return clearSpan_s(PairAt{ua, ub, ma, mb, t, reach, touch_m}, end, hint_s);
  };
  return firstDraggedContact_s(gap_at, t0, end, kTieUlps * kRoundOff * model_.speed_scale_mps,
                               clear_for);
}

double PlaneEngine::draggedPairPush(const UnitState& ua, const UnitState& ub, const Kin& ka,
                                    const Kin& kb, const core::Vec2& n) const {
  // Units advanced to the impact: their velocities are now's.
  const core::Vec2 push = dragAcceleration(ua, ua.v_mps) - dragAcceleration(ub, ub.v_mps);
  const core::Vec2 dv = kb.v - ka.v;
  const double sliding = dv.squaredNorm() - dv.dot(n) * dv.dot(n);
  const double distance = std::max((kb.x - ka.x).norm(), 1e-300);
  return std::max(push.dot(n) - sliding / distance, 0.0);
}

double PlaneEngine::predictDraggedWall(int body, int wall, double t0) const {
  const UnitState& u = state_.units[state_.bodies[body].unit];
  const WallDef& w = model_.world.walls[wall];
  const double end = model_.world.duration_s;
  const double radius = model_.half_size_m[body];
  // Along the normal the motion is a 1D one: a velocity running monotonically to the terminal
  // one's component (or, without drag, gaining g.n a second).
  const double terminal = hasDrag(u)                     ? terminalVelocity(u).dot(w.normal)
                          : u.a_mps2.dot(w.normal) < 0.0 ? -std::numeric_limits<double>::infinity()
                                                         : std::numeric_limits<double>::infinity();
  auto gap_at = [&](double t) {
    const DiskMotion m = diskAt(u, t, end);
    DraggedGap g;
    g.gap_m = (m.x - w.point_m).dot(w.normal) - radius;
    g.rate_mps = m.v.dot(w.normal);
    g.accel_mps2 = m.a.dot(w.normal);
    g.curvature_mps2 = std::abs(g.accel_mps2);
    g.rate_floor_mps = std::min(g.rate_mps, terminal);
    g.touch_m = kTieUlps * kRoundOff * std::max(m.x.norm(), radius);
    return g;
  };
  return firstDraggedContact_s(gap_at, t0, end, kTieUlps * kRoundOff * model_.speed_scale_mps);
}

}  // namespace collide::physics::detail
