#include "report/json_summary.hpp"

#include "core/error.hpp"
#include "core/stop_request.hpp"
#include "report/json_events.hpp"
#include "report/json_writer.hpp"

namespace collide::report {
namespace {

// A collision partner: a body index, or for a wall its name.
void writePartner(JsonWriter& json, const physics::Timeline& timeline, int partner) {
  if (partner >= 0) {
    json.value(partner);
    return;
  }
  const int wall = physics::kWallPartnerBase - partner;
  json.value(timeline.world().walls.at(static_cast<std::size_t>(wall)).name);
}

void writeCollision(JsonWriter& json, const physics::Timeline& timeline,
                    const physics::CollisionEvent& event) {
  json.beginObject();
  json.key("time").value(event.time_s);
  json.key("a").value(event.body_a);
  json.key("b");
  writePartner(json, timeline, event.body_b);
  json.key("restitution").value(event.restitution);
  json.key("normal").value(event.normal);
  json.key("velocities_before").beginArray();
  json.value(event.velocity_a_before_mps).value(event.velocity_b_before_mps).endArray();
  json.key("velocities_after").beginArray();
  json.value(event.velocity_a_after_mps).value(event.velocity_b_after_mps).endArray();
  json.key("energy_lost").value(event.energy_lost_J);
  json.key("energy_lost_analytic").value(event.energy_lost_analytic_J);
  if (physics::canReleaseEnergy(timeline.world())) {
    json.key("energy_released").value(event.energy_released_J);
    json.key("kind").value(event.release ? "release" : "impact");
  }
  json.endObject();
}

}  // namespace

double estimateJsonSummaryBytes(const physics::Timeline& timeline,
                                const JsonSummaryOptions& options) {
  // An event's object as written (eleven keys, seven numbers and four vectors, indented) takes
  // some 370 bytes; a body's entry some 200.
  // Version 2's events carry positions and energy_released: some 560 bytes.
  const double kBytesPerCollision = options.version >= 2 ? 560.0 : 370.0;
  constexpr double kBytesPerBody = 300.0, kBytesAround = 800.0;
  const double collisions =
      options.include_collisions ? static_cast<double>(timeline.collisionCount()) : 0.0;
  return kBytesAround + kBytesPerBody * static_cast<double>(timeline.world().bodies.size()) +
         kBytesPerCollision * collisions;
}

namespace {

void writeVersion1(JsonWriter& json, const physics::Timeline& timeline,
                   const JsonSummaryOptions& options) {
  const physics::WorldDef& world = timeline.world();
  const physics::Snapshot start = timeline.initialState();
  const physics::Snapshot end = timeline.sample(timeline.duration_s());
  json.beginObject();
  json.key("scene").value(options.scene_name);
  json.key("dimensions").value(world.dimensions);
  json.key("duration").value(world.duration_s);
  json.key("bodies").beginArray();
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    json.beginObject();
    json.key("name").value(world.bodies[i].name);
    json.key("mass").value(world.bodies[i].mass_kg);
    json.key("initial_velocity").value(start.bodies[i].velocity_mps);
    json.key("final_velocity").value(end.bodies[i].velocity_mps);
    json.endObject();
  }
  json.endArray();
  json.key("collision_count").value(static_cast<long long>(timeline.collisionCount()));
  json.key("momentum_initial").value(timeline.momentum(start));
  json.key("momentum_final").value(timeline.momentum(end));
  json.key("kinetic_energy_initial").value(timeline.kineticEnergy(start));
  json.key("kinetic_energy_final").value(timeline.kineticEnergy(end));
  json.key("energy_lost").value(end.energy_lost_J);
  // Where energy can come in: the books are kinetic_energy_final + energy_lost =
  // kinetic_energy_initial + energy_released (no gravity).
  if (physics::canReleaseEnergy(world)) json.key("energy_released").value(end.energy_released_J);
  // Where bodies slide with friction: its work (+ energy_to_surface on the left of the books).
  if (physics::hasFriction(world)) json.key("energy_to_surface").value(end.energy_to_surface_J);
  // Where bodies feel air drag: its work, likewise.
  if (physics::hasDrag(world)) json.key("energy_to_air").value(end.energy_to_air_J);
  // Molecules with insides: the disks' internal energy at the end, a part of the books.
  if (world.internal_dof > 0) json.key("internal_energy_final").value(end.internal_energy_J);
  if (options.include_collisions) {
    json.key("collisions").beginArray();
    // Every collision, also past the stored log (replayed): the array always has collision_count
    // entries.
    // A stop request (Ctrl-C) is checked per collision: a long run (pi-blocks with 8 digits,
    // 31 million collisions, gigabytes of JSON) stops within microseconds; one relaxed atomic load
    // is nothing next to formatting an event.
    timeline.replayCollisions([&](const physics::CollisionEvent& event) {
      core::throwIfStopRequested();
      writeCollision(json, timeline, event);
    });
    json.endArray();
  }
  json.endObject();
}

void writeBodies(JsonWriter& json, const physics::Timeline& timeline,
                 const physics::Snapshot& start, const physics::Snapshot& end) {
  const physics::WorldDef& world = timeline.world();
  json.key("bodies").beginArray();
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    json.beginObject();
    json.key("number").value(static_cast<long long>(i + 1));
    json.key("name").value(world.bodies[i].name);
    json.key("mass").value(world.bodies[i].mass_kg);
    json.key("initial_position").value(start.bodies[i].position_m);
    json.key("initial_velocity").value(start.bodies[i].velocity_mps);
    json.key("final_position").value(end.bodies[i].position_m);
    json.key("final_velocity").value(end.bodies[i].velocity_mps);
    if (world.rolling) {
      // A rolling ball's spin about the table's axes: its energy, 1/2 (2/5 m r^2) |spin|^2, is
      // part of the kinetic energy.
      json.key("radius").value(world.bodies[i].size_m);
      json.key("initial_spin").value(start.bodies[i].spin_radps);
    }
    json.endObject();
  }
  json.endArray();
}

// Version 2: mechanical energy at both ends (kinetic plus gravity's, zero at the origin); the
// books are energy_final + energy_lost (+ energy_to_surface, with friction; + energy_to_air, with
// drag) = energy_initial + energy_released.
void writeVersion2(JsonWriter& json, const physics::Timeline& timeline,
                   const JsonSummaryOptions& options) {
  const physics::WorldDef& world = timeline.world();
  const physics::Snapshot start = timeline.initialState();
  const physics::Snapshot end = timeline.sample(timeline.duration_s());
  json.beginObject();
  json.key("data_version").value(2);
  json.key("scene").value(options.scene_name);
  json.key("dimensions").value(world.dimensions);
  json.key("duration").value(world.duration_s);
  json.key("gravity").value(world.gravity_mps2);
  writeBodies(json, timeline, start, end);
  json.key("collision_count").value(static_cast<long long>(timeline.collisionCount()));
  json.key("momentum_initial").value(timeline.momentum(start));
  json.key("momentum_final").value(timeline.momentum(end));
  json.key("kinetic_energy_initial").value(timeline.kineticEnergy(start));
  json.key("kinetic_energy_final").value(timeline.kineticEnergy(end));
  json.key("potential_energy_initial").value(timeline.potentialEnergy(start));
  json.key("potential_energy_final").value(timeline.potentialEnergy(end));
  json.key("energy_initial").value(timeline.mechanicalEnergy(start));
  json.key("energy_final").value(timeline.mechanicalEnergy(end));
  json.key("energy_lost").value(end.energy_lost_J);
  // Where bodies slide with friction: its work, on the left of the books with energy_lost.
  if (physics::hasFriction(world)) json.key("energy_to_surface").value(end.energy_to_surface_J);
  // Where bodies feel air drag: its work, likewise.
  if (physics::hasDrag(world)) json.key("energy_to_air").value(end.energy_to_air_J);
  json.key("energy_released").value(end.energy_released_J);
  if (world.internal_dof > 0) json.key("internal_energy_final").value(end.internal_energy_J);
  if (options.include_collisions) {
    json.key("events");
    writeJsonEvents(json, timeline);
  }
  json.endObject();
}

}  // namespace

void writeJsonSummary(std::ostream& out, const physics::Timeline& timeline,
                      const JsonSummaryOptions& options) {
  COLLIDE_ASSERT(options.version >= kOldestDataVersion && options.version <= kDataVersion,
                 "writeJsonSummary: no such data version");
  JsonWriter json(out);
  if (options.version >= 2) {
    writeVersion2(json, timeline, options);
  } else {
    writeVersion1(json, timeline, options);
  }
}

}  // namespace collide::report
