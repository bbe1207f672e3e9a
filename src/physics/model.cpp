// The precomputed model of a world: sizes, inertias and the restitution tables and law.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "physics/engine.hpp"

namespace collide::physics::detail {
namespace {

// The collapse guard's burst window as a fraction of the scene's time scale: impacts this close
// are simultaneous for any picture or table of the scene.
constexpr double kCollapseWindowRelative = 1e-9;

std::uint64_t pairKey(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (std::uint64_t{lo} << 32) | hi;
}

}  // namespace

Model::Model(WorldDef def) : world(std::move(def)) {
  COLLIDE_ASSERT(world.dimensions == 1 || world.dimensions == 2, "dimensions must be 1 or 2");
  const int n = static_cast<int>(world.bodies.size());
  for (const BodyDef& body : world.bodies) {
    COLLIDE_ASSERT(body.mass_kg > 0.0 && body.size_m > 0.0, "bodies need positive mass and size");
    const double half = world.dimensions == 1 ? 0.5 * body.size_m : body.size_m;
    half_size_m.push_back(half);
    // Blocks never rotate; a disk spinning with its cluster carries m r^2 / 2.
    spin_inertia_kgm2.push_back(world.dimensions == 2 ? 0.5 * body.mass_kg * half * half : 0.0);
    ball_inertia_kgm2.push_back(world.rolling ? 0.4 * body.mass_kg * half * half : 0.0);
  }
  double smallest_m = std::numeric_limits<double>::infinity(), speed_mps = 0.0, extent_m = 0.0;
  for (int i = 0; i < n; ++i) {
    const BodyDef& body = world.bodies[i];
    smallest_m = std::min(smallest_m, half_size_m[i]);
    speed_mps = std::max(speed_mps, world.dimensions == 1 ? std::abs(body.velocity_mps.x())
                                                          : body.velocity_mps.norm());
    extent_m = std::max(extent_m, body.position_m.norm() + half_size_m[i]);
  }
  for (const WallDef& wall : world.walls) extent_m = std::max(extent_m, wall.point_m.norm());
  for (const BodyDef& body : world.bodies) has_strings = has_strings || body.on_string;
  has_friction = hasFriction(world);
  has_drag = hasDrag(world);
  // A spinning cluster's drag is not modelled: in 2D drag goes with e = 0 sliding on (slip).
  COLLIDE_ASSERT(
      !has_drag ||
          (!has_friction && !has_strings && world.contact_model == ContactModel::kImpulse &&
           (world.dimensions == 1 || world.inelastic_mode == InelasticMode::kSlip)),
      "air drag goes with impulsive contacts of free bodies without friction (2D: slip)");
  COLLIDE_ASSERT(!has_friction || world.dimensions == 1 ||
                     (world.gravity_mps2.x() == 0.0 && world.gravity_mps2.y() == 0.0 &&
                      world.contact_model == ContactModel::kImpulse && !has_strings),
                 "sliding friction in 2D goes with a level table: no gravity in the plane");
  COLLIDE_ASSERT(
      !world.rolling || (world.dimensions == 2 && world.inelastic_mode == InelasticMode::kSlip &&
                         !has_drag && world.internal_dof == 0),
      "rolling balls go on a level table, with e = 0 sliding on (slip)");
  speed_mps = std::max(speed_mps, std::sqrt(2.0 * world.gravity_mps2.norm() * 2.0 * extent_m));
  COLLIDE_ASSERT(world.releases.empty() || world.dimensions == 1, "releases act in 1D only");
  // A release gives its bodies at most the separation speed it adds (bodies at rest: mu u^2 / 2
  // = Q).
  for (const ReleaseDef& release : world.releases) {
    COLLIDE_ASSERT(release.body_a >= 0 && release.body_a < n && release.body_b >= 0 &&
                       release.body_b < n && release.body_a != release.body_b,
                   "a release names a body that does not exist");
    const double ma = world.bodies[release.body_a].mass_kg,
                 mb = world.bodies[release.body_b].mass_kg;
    const double mu = ma * mb / (ma + mb);
    speed_mps =
        std::max({speed_mps, release.separation_speed_mps, std::sqrt(2.0 * release.energy_J / mu)});
  }
  speed_scale_mps = speed_mps;
  time_scale_s = speed_mps > 0.0 ? smallest_m / speed_mps : std::numeric_limits<double>::infinity();
  collapse_window_s = world.collapse_time_s > 0.0 && std::isfinite(time_scale_s)
                          ? kCollapseWindowRelative * time_scale_s
                          : 0.0;
  for (const PairRestitution& pair : world.pair_restitution) {
    COLLIDE_ASSERT(pair.body_a >= 0 && pair.body_a < n && pair.body_b >= 0 && pair.body_b < n,
                   "pair restitution names a body that does not exist");
    pair_e_[pairKey(pair.body_a, pair.body_b)] = pair.restitution;
  }
  if (world.restitution_model.law == RestitutionLaw::kTable) {
    COLLIDE_ASSERT(!world.restitution_model.table.empty(), "a restitution table needs a point");
  }
}

bool Model::closingIsRoundOff(double closing_mps, double va_mps, double vb_mps) const {
  const double speed = std::max({std::abs(va_mps), std::abs(vb_mps), speed_scale_mps});
  return std::abs(closing_mps) <= kTieUlps * std::numeric_limits<double>::epsilon() * speed;
}

double Model::pairOverride(int a, int b) const {
  const auto found = pair_e_.find(pairKey(a, b));
  return found == pair_e_.end() ? world.restitution : found->second;
}

double Model::lawOf(double e0, double u_mps) const {
  const RestitutionModel& law = world.restitution_model;
  switch (law.law) {
    case RestitutionLaw::kConstant:
      return e0;
    case RestitutionLaw::kSpeedThreshold:
      if (u_mps <= law.threshold_speed_mps) return e0;
      return e0 * std::pow(law.threshold_speed_mps / u_mps, law.exponent);
    case RestitutionLaw::kTable: {
      const std::vector<RestitutionPoint>& table = law.table;
      if (u_mps <= table.front().speed_mps) return table.front().restitution;
      if (u_mps >= table.back().speed_mps) return table.back().restitution;
      const auto upper =
          std::upper_bound(table.begin(), table.end(), u_mps,
                           [](double u, const RestitutionPoint& p) { return u < p.speed_mps; });
      const RestitutionPoint& hi = *upper;
      const RestitutionPoint& lo = *std::prev(upper);
      const double f = (u_mps - lo.speed_mps) / (hi.speed_mps - lo.speed_mps);
      return lo.restitution + f * (hi.restitution - lo.restitution);
    }
  }
  return e0;
}

std::unique_ptr<Engine> makeEngine(const Model& model, EngineState start, const Recorder& out) {
  if (model.has_strings) return makeStringEngine(model, std::move(start), out);
  if (model.world.dimensions == 1) return makeLineEngine(model, std::move(start), out);
  return makePlaneEngine(model, std::move(start), out);
}

}  // namespace collide::physics::detail
