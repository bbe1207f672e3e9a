#include "physics/simulate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>

#include "core/stop_request.hpp"
#include "physics/engine.hpp"
#include "physics/timeline_data.hpp"

namespace collide::physics {
namespace {

std::size_t keyframeBytes(const detail::EngineState& state) {
  return sizeof(detail::EngineState) + state.units.size() * sizeof(detail::UnitState) +
         state.bodies.size() * (sizeof(detail::BodyLink) + sizeof(double));
}

std::string describeStop(const char* what, std::int64_t count, double t_s) {
  char text[200];
  std::snprintf(text, sizeof text,
                "%s after %lld collisions at t = %.9g s; later states are not "
                "simulated",
                what, static_cast<long long>(count), t_s);
  return text;
}

constexpr std::size_t kMaxKeyframes = 8192;
constexpr std::int64_t kBodiesPerStrideCollision = 8;
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// Kinetic (translation and disk spin) and potential energy of a state, with the sum of their
// magnitudes: the scale of the round-off in that state's energy.
struct Energies {
  double mechanical_J = 0.0;
  double magnitude_J = 0.0;
};

Energies energiesOf(const detail::Model& model, const Snapshot& snapshot) {
  Energies out;
  const WorldDef& world = model.world;
  for (std::size_t i = 0; i < snapshot.bodies.size(); ++i) {
    const BodyState& body = snapshot.bodies[i];
    const double m = world.bodies[i].mass_kg;
    const double kinetic = 0.5 * m * body.velocity_mps.squaredNorm() +
                           0.5 * model.spin_inertia_kgm2[i] * body.angular_velocity_radps *
                               body.angular_velocity_radps +
                           0.5 * model.ball_inertia_kgm2[i] * body.spin_radps.squaredNorm();
    const double potential = -m * world.gravity_mps2.dot(body.position_m);
    out.mechanical_J += kinetic + potential;
    out.magnitude_J += kinetic + std::abs(potential);
  }
  return out;
}

// ", friction booked X J to the surface" where there is friction, ", drag Y J to the air" where
// there is drag, for the ledger's warning.
std::string surfaceText(const WorldDef& world, const Snapshot& end) {
  std::string out;
  char text[80];
  if (hasFriction(world)) {
    std::snprintf(text, sizeof text, ", friction %.9g J to the surface", end.energy_to_surface_J);
    out += text;
  }
  if (hasDrag(world)) {
    std::snprintf(text, sizeof text, ", drag %.9g J to the air", end.energy_to_air_J);
    out += text;
  }
  return out;
}

// The check on the energy ledger: what the impacts booked against what the mechanical energy
// at both ends says. Each impact rounds the velocities of its partners, and each partner carries
// at most the scene's energy, so the allowance is a few epsilon of that per impact.
void checkLedger(detail::TimelineData& data, const detail::EngineState& last) {
  const Energies start =
      energiesOf(data.model, detail::evaluate(data.model, data.keyframes[0], 0.0));
  const Snapshot end_state = detail::evaluate(data.model, last, last.time_s);
  const Energies end = energiesOf(data.model, end_state);
  data.energy_lost_measured_J = start.mechanical_J - end.mechanical_J;
  const double scale_J = std::max(start.magnitude_J, end.magnitude_J);
  // With friction every stop is an event that rounds too.
  const std::int64_t events =
      last.collision_count + (hasFriction(data.model.world) ? last.string_events : 0);
  data.energy_tolerance_J = 16.0 * kEpsilon * static_cast<double>(events + 1) * scale_J;
  // A soft contact still in progress holds energy in its spring: no check then.
  for (const detail::UnitState& unit : last.units) {
    if (unit.alive && unit.t_ref_s > last.time_s) return;
  }
  // The books: what the end lacks of the start is what was lost less what was released.
  // Friction's work to the same instant (the run's total goes on to its end); molecules with
  // insides: what the disks hold inside left the motion too.
  const double inside_J = detail::evaluate(data.model, last, last.time_s).internal_energy_J;
  const double booked_J = data.energy_lost_J + end_state.energy_to_surface_J +
                          end_state.energy_to_air_J - data.energy_released_J + inside_J;
  const double gap_J = data.energy_lost_measured_J - booked_J;
  if (!(std::abs(gap_J) > data.energy_tolerance_J)) return;
  char text[600];
  std::snprintf(text, sizeof text,
                "energy ledger: the impacts booked %.9g J lost and %.9g J released%s but the "
                "mechanical energy fell by %.9g J, a difference of %.3g J beyond the round-off "
                "allowance of %.3g J; the reported energy_lost is the booked value",
                data.energy_lost_J, data.energy_released_J,
                surfaceText(data.model.world, end_state).c_str(), data.energy_lost_measured_J,
                gap_J, data.energy_tolerance_J);
  data.warnings.push_back({WarningKind::kEnergyLedger, -1, last.time_s, text});
}

// numerator / denominator (both > 0) as %.3g writes it, also where the quotient is beyond a
// double: 1e-300 kg against 1e18 kg is "1e+318", never "inf".
std::string ratioText(double numerator, double denominator) {
  char text[40];
  const double ratio = numerator / denominator;
  if (std::isfinite(ratio)) {
    std::snprintf(text, sizeof text, "%.3g", ratio);
    return text;
  }
  const double decades = std::log10(numerator) - std::log10(denominator);
  const double exponent = std::floor(decades);
  std::snprintf(text, sizeof text, "%.3ge+%.0f", std::pow(10.0, decades - exponent), exponent);
  return text;
}

// Ratios beyond 1 / epsilon cannot be told apart from infinite: the heavier body's share of an
// impulse, or a body's size next to its distance from the origin, falls below round-off.
void checkPrecision(detail::TimelineData& data) {
  const WorldDef& world = data.model.world;
  if (world.bodies.empty()) return;
  const BodyDef *light = &world.bodies[0], *heavy = light, *small = light;
  double extent_m = 0.0;
  for (const BodyDef& body : world.bodies) {
    if (body.mass_kg < light->mass_kg) light = &body;
    if (body.mass_kg > heavy->mass_kg) heavy = &body;
    if (body.size_m < small->size_m) small = &body;
    extent_m = std::max(extent_m, body.position_m.norm() + body.size_m);
  }
  for (const WallDef& wall : world.walls) extent_m = std::max(extent_m, wall.point_m.norm());
  const double resolved = 1.0 / kEpsilon;  // 4.5e15
  char text[400];
  if (heavy->mass_kg / light->mass_kg > resolved) {
    std::snprintf(text, sizeof text,
                  "masses from %.3g kg (\"%s\") to %.3g kg (\"%s\"): a ratio of %s, beyond the "
                  "%.2g that double precision resolves; the heavier body's velocity changes are "
                  "below round-off",
                  light->mass_kg, light->name.c_str(), heavy->mass_kg, heavy->name.c_str(),
                  ratioText(heavy->mass_kg, light->mass_kg).c_str(), resolved);
    data.warnings.push_back({WarningKind::kPrecision, -1, 0.0, text});
  }
  if (extent_m / small->size_m > resolved) {
    std::snprintf(text, sizeof text,
                  "body \"%s\" is %.3g m across in a scene reaching %.3g m from the origin: a "
                  "ratio of %s, beyond the %.2g that double precision resolves; its position is "
                  "known only to about its own size",
                  small->name.c_str(), small->size_m, extent_m,
                  ratioText(extent_m, small->size_m).c_str(), resolved);
    data.warnings.push_back({WarningKind::kPrecision, -1, 0.0, text});
  }
}

// The checkpoints a run may keep: enough that a sample replays at most (collisions / 4096)
// events, few enough that taking them costs little next to the simulation itself.
std::size_t maxKeyframes(const WorldDef& world, const detail::EngineState& first) {
  const std::size_t budget =
      static_cast<std::size_t>(std::max<std::int64_t>(world.max_keyframe_bytes, 0));
  return std::clamp<std::size_t>(budget / keyframeBytes(first), 64, kMaxKeyframes);
}

// Keeps every other checkpoint: those at multiples of the doubled stride.
void thinKeyframes(std::vector<detail::EngineState>& keyframes, std::int64_t& stride) {
  stride *= 2;
  std::vector<detail::EngineState> kept;
  for (detail::EngineState& k : keyframes) {
    if (k.collision_count % stride == 0) kept.push_back(std::move(k));
  }
  keyframes = std::move(kept);
}

// Runs `engine` to the end of the world's duration (or a stop), taking checkpoints on the way.
detail::RunStop runWithCheckpoints(detail::Engine& engine, detail::TimelineData& data,
                                   const WorldDef& world, const SimulationProgress& progress) {
  const std::size_t max_keyframes = maxKeyframes(world, data.keyframes.front());
  // A checkpoint copies every body's state, and sampling from one rebuilds every body's
  // predictions: both cost O(bodies), so a scene of many bodies starts with a stride of
  // bodies / kBodiesPerStrideCollision collisions, which keeps the copies to a fraction of a body
  // per collision (at stride 1, hundreds of disks spent a measurable share of their run copying
  // checkpoints: bench/results.md) while a sample still replays no more collisions than it
  // rebuilds predictions.
  std::int64_t stride = std::max<std::int64_t>(
      1, static_cast<std::int64_t>(world.bodies.size()) / kBodiesPerStrideCollision);
  for (;;) {
    // The only stop check in physics: a stop request (Ctrl-C, see core/stop_request.hpp) ends a
    // long run (31 million collisions for pi-blocks digits=8) by throwing core::StopRequested.
    // Checked once per checkpoint stride (1 collision at first for a few bodies, later the
    // collisions so far over the 64 to 8192 checkpoints kept: ~4,000 for pi-blocks digits=8), so it
    // costs nothing and answers within milliseconds.
    core::throwIfStopRequested();
    const std::int64_t count = engine.state().collision_count;
    if (progress) progress(engine.state().time_s, count);
    const detail::RunStop stop = engine.run(world.duration_s, (count / stride + 1) * stride);
    if (stop != detail::RunStop::kCountLimit) return stop;
    data.keyframes.push_back(engine.state());
    if (data.keyframes.size() > max_keyframes) thinKeyframes(data.keyframes, stride);
  }
}

// How the run ended, as the timeline reports it: its status, how far it is simulated, and the
// warning that says why it stopped early.
void noteStop(detail::TimelineData& data, const detail::EngineState& last, detail::RunStop stop) {
  if (stop == detail::RunStop::kCollisionCap) {
    data.status = SimulationStatus::kCollisionCapReached;
    data.simulated_until_s = last.time_s;
    data.warnings.push_back({WarningKind::kCollisionCap, last.collision_count - 1, last.time_s,
                             describeStop("stopped at the collision cap (max_collisions)",
                                          last.collision_count, last.time_s)});
  } else if (stop == detail::RunStop::kRateCap) {
    // Like the collision cap: the timeline holds up to the last simulated collision.
    data.status = SimulationStatus::kCollisionRateCapReached;
    data.simulated_until_s = last.time_s;
  } else if (stop == detail::RunStop::kStalled) {
    data.status = SimulationStatus::kStalled;
    data.simulated_until_s = last.time_s;
    // The 2D engine names the resting stack that stopped it; any other stall is events piling up
    // at one instant.
    const bool explained =
        !data.warnings.empty() && data.warnings.back().kind == WarningKind::kStalled;
    if (!explained) {
      data.warnings.push_back({WarningKind::kStalled, last.collision_count - 1, last.time_s,
                               describeStop("stalled: collisions kept happening at one instant",
                                            last.collision_count, last.time_s)});
    }
  }
}

}  // namespace

Timeline simulate(const WorldDef& world, const SimulationProgress& progress) {
  auto data = std::make_shared<detail::TimelineData>(world);
  const detail::Model& model = data->model;
  detail::Recorder recorder;
  recorder.events = &data->events;
  recorder.event_limit = world.max_recorded_collisions;
  recorder.soft_contacts = &data->soft_contacts;
  recorder.warnings = &data->warnings;

  checkPrecision(*data);
  data->keyframes.push_back(detail::initialState(model));
  std::unique_ptr<detail::Engine> engine =
      detail::makeEngine(model, data->keyframes.front(), recorder);
  const detail::RunStop stop = runWithCheckpoints(*engine, *data, world, progress);
  const detail::EngineState& last = engine->state();
  if (last.collision_count != data->keyframes.back().collision_count ||
      last.string_events != data->keyframes.back().string_events) {
    data->keyframes.push_back(last);
  }
  data->collision_count = last.collision_count;
  data->string_event_count = last.string_events;
  data->energy_lost_J = last.energy_lost.total_J();
  data->energy_released_J = last.energy_released.total_J();
  data->simulated_until_s = world.duration_s;
  noteStop(*data, last, stop);
  const Snapshot end = detail::evaluate(model, last, data->simulated_until_s);
  data->energy_to_surface_J = end.energy_to_surface_J;
  data->energy_to_air_J = end.energy_to_air_J;
  checkLedger(*data, last);
  return Timeline(std::move(data));
}

}  // namespace collide::physics
