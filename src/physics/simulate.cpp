#include "physics/simulate.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "core/error.hpp"

namespace collide::physics {
namespace {

// 1D blocks on a frictionless line. Bodies that merged (e = 0) share a group and one velocity.
struct LineState {
  std::vector<double> x_m, v_mps;
  std::vector<int> group;
};

double halfWidth(const WorldDef& world, int i) { return 0.5 * world.bodies[i].size_m; }

double groupMass(const WorldDef& world, const LineState& s, int group) {
  double mass = 0.0;
  for (std::size_t i = 0; i < s.group.size(); ++i) {
    if (s.group[i] == group) mass += world.bodies[i].mass_kg;
  }
  return mass;
}

}  // namespace

Timeline simulate(const WorldDef& world) {
  COLLIDE_ASSERT(world.dimensions == 1, "only 1D worlds are simulated so far");
  const int n = static_cast<int>(world.bodies.size());
  LineState s;
  for (int i = 0; i < n; ++i) {
    s.x_m.push_back(world.bodies[i].position_m.x());
    s.v_mps.push_back(world.bodies[i].velocity_mps.x());
    s.group.push_back(i);
  }
  auto snapshotOf = [&](double t, double lost, int count) {
    Snapshot snap{t, {}, lost, count};
    for (int i = 0; i < n; ++i) snap.bodies.push_back({{s.x_m[i], 0.0}, {s.v_mps[i], 0.0}});
    return snap;
  };

  std::vector<Snapshot> keyframes{snapshotOf(0.0, 0.0, 0)};
  std::vector<CollisionEvent> collisions;
  double t = 0.0, lost = 0.0;
  std::vector<int> order(n);
  for (;;) {
    // Neighbours along the line are the only pairs that can meet first.
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return s.x_m[a] < s.x_m[b]; });
    double best_dt = std::numeric_limits<double>::infinity();
    int best_left = -1, best_right = -1;
    for (int k = 0; k + 1 < n; ++k) {
      const int a = order[k], b = order[k + 1];
      const double closing = s.v_mps[a] - s.v_mps[b];
      if (s.group[a] == s.group[b] || closing <= 0.0) continue;
      const double gap = s.x_m[b] - s.x_m[a] - halfWidth(world, a) - halfWidth(world, b);
      const double dt = std::max(gap, 0.0) / closing;
      if (dt < best_dt) best_dt = dt, best_left = a, best_right = b;
    }
    if (best_left < 0 || t + best_dt > world.duration_s) break;
    t += best_dt;
    for (int i = 0; i < n; ++i) s.x_m[i] += s.v_mps[i] * best_dt;

    const int ga = s.group[best_left], gb = s.group[best_right];
    const double ma = groupMass(world, s, ga), mb = groupMass(world, s, gb);
    const double ua = s.v_mps[best_left], ub = s.v_mps[best_right];
    const double e = world.restitution;
    // Momentum conservation plus the definition of e: v_b' - v_a' = -e (v_b - v_a).
    const double va = ((ma - e * mb) * ua + (1.0 + e) * mb * ub) / (ma + mb);
    const double vb = ((1.0 + e) * ma * ua + (mb - e * ma) * ub) / (ma + mb);
    const double ke_before = 0.5 * ma * ua * ua + 0.5 * mb * ub * ub;
    const double ke_after = 0.5 * ma * va * va + 0.5 * mb * vb * vb;
    const double mu = ma * mb / (ma + mb);
    const double u = ua - ub;
    for (int i = 0; i < n; ++i) {
      if (s.group[i] == ga) s.v_mps[i] = va;
      if (s.group[i] == gb) s.v_mps[i] = (e == 0.0) ? va : vb;
    }
    if (e == 0.0) {
      for (int& g : s.group) g = (g == gb) ? ga : g;
    }
    lost += ke_before - ke_after;
    CollisionEvent event;
    event.time_s = t;
    event.body_a = best_left;
    event.body_b = best_right;
    event.restitution = e;
    event.normal = {1.0, 0.0};
    event.velocity_a_before_mps = {ua, 0.0};
    event.velocity_a_after_mps = {va, 0.0};
    event.velocity_b_before_mps = {ub, 0.0};
    event.velocity_b_after_mps = {(e == 0.0) ? va : vb, 0.0};
    event.closing_speed_mps = u;
    event.energy_lost_J = ke_before - ke_after;
    event.energy_lost_analytic_J = 0.5 * mu * (1.0 - e * e) * u * u;
    collisions.push_back(event);
    keyframes.push_back(snapshotOf(t, lost, static_cast<int>(collisions.size())));
  }
  return Timeline(world, std::move(keyframes), std::move(collisions));
}

}  // namespace collide::physics
