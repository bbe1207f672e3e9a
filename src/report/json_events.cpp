// SPDX-License-Identifier: MIT
#include "report/json_events.hpp"

#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <vector>

#include "core/stop_request.hpp"

namespace collide::report {
namespace {

// One event as written: a collision record seen at one of its instants, or a string event.
struct EventRecord {
  const char* kind = "impact";
  double time_s = 0.0;
  int body_a = 0;
  int body_b = 0;
  bool has_b = false;  // a partner (a body, or a wall when body_b < 0)
  const physics::CollisionEvent* collision = nullptr;  // impact-like kinds: its e and normal
  core::Vec2 velocity_a_before, velocity_a_after, velocity_b_before, velocity_b_after;
  double energy_lost_J = 0.0, energy_released_J = 0.0;
  double duration_s = -1.0;  // contact_end: how long the contact lasted
};

// The end of a soft contact, written once the events before it have been.
struct PendingEnd {
  physics::CollisionEvent event;
  double time_s = 0.0;
  std::int64_t order = 0;  // contacts ending at one instant: in the order they began
  bool operator>(const PendingEnd& other) const {
    return time_s != other.time_s ? time_s > other.time_s : order > other.order;
  }
};
using PendingEnds = std::priority_queue<PendingEnd, std::vector<PendingEnd>, std::greater<>>;

void writeEventPartner(JsonWriter& json, const physics::Timeline& timeline, int partner) {
  if (partner >= 0) {
    json.value(partner + 1);
    return;
  }
  const auto wall = static_cast<std::size_t>(physics::kWallPartnerBase - partner);
  json.beginObject();
  json.key("wall").value(timeline.world().walls.at(wall).name);
  json.endObject();
}

// One entry per body taking part (a wall has none): positions, velocities.
void writeBodyVectors(JsonWriter& json, const EventRecord& record, const core::Vec2& a,
                      const core::Vec2& b) {
  json.beginArray().value(a);
  if (record.has_b && record.body_b >= 0) json.value(b);
  json.endArray();
}

void writeRecord(JsonWriter& json, const physics::Timeline& timeline, const EventRecord& record) {
  // Positions are the same just before and after the instant: the state the timeline gives.
  const physics::Snapshot at = timeline.sample(record.time_s);
  const auto position = [&](int body) {
    return body >= 0 ? at.bodies[static_cast<std::size_t>(body)].position_m : core::Vec2{0, 0};
  };
  json.beginObject();
  json.key("kind").value(record.kind);
  json.key("time").value(record.time_s);
  json.key("a").value(record.body_a + 1);
  if (record.has_b) {
    json.key("b");
    writeEventPartner(json, timeline, record.body_b);
  }
  json.key("positions");
  writeBodyVectors(json, record, position(record.body_a), position(record.body_b));
  json.key("velocities_before");
  writeBodyVectors(json, record, record.velocity_a_before, record.velocity_b_before);
  json.key("velocities_after");
  writeBodyVectors(json, record, record.velocity_a_after, record.velocity_b_after);
  if (record.collision != nullptr) {
    json.key("restitution").value(record.collision->restitution);
    json.key("normal").value(record.collision->normal);
    if (record.collision->merged && !record.collision->hitsWall()) json.key("joined").boolean(true);
  }
  if (record.duration_s >= 0.0) json.key("duration").value(record.duration_s);
  json.key("energy_lost").value(record.energy_lost_J);
  json.key("energy_released").value(record.energy_released_J);
  json.endObject();
}

// The record of a collision at its instant; soft contacts: at their start (velocities as they
// were) or at their end (velocities after, the loss and any release booked there).
EventRecord collisionRecord(const physics::CollisionEvent& event, const char* kind, double time_s,
                            bool contact_start) {
  EventRecord record;
  record.kind = kind;
  record.time_s = time_s;
  record.body_a = event.body_a;
  record.body_b = event.body_b;
  record.has_b = true;
  record.collision = &event;
  const bool contact_end = event.contact_duration_s > 0.0 && !contact_start;
  record.velocity_a_before = contact_end ? event.velocity_a_after_mps : event.velocity_a_before_mps;
  record.velocity_b_before = contact_end ? event.velocity_b_after_mps : event.velocity_b_before_mps;
  record.velocity_a_after =
      contact_start ? event.velocity_a_before_mps : event.velocity_a_after_mps;
  record.velocity_b_after =
      contact_start ? event.velocity_b_before_mps : event.velocity_b_after_mps;
  if (!contact_start) {
    record.energy_lost_J = event.energy_lost_J;
    record.energy_released_J = event.energy_released_J;
  }
  if (contact_end) record.duration_s = event.contact_duration_s;
  return record;
}

const char* collisionKind(const physics::CollisionEvent& event) {
  if (event.release) return "release";
  if (event.hitsWall()) return event.merged ? "rest" : "wall";
  return "impact";
}

EventRecord stringRecord(const physics::StringEvent& event) {
  EventRecord record;
  record.kind = event.taut ? "string_taut" : "string_slack";
  record.time_s = event.time_s;
  record.body_a = event.body;
  record.velocity_a_before = event.velocity_before_mps;
  record.velocity_a_after = event.velocity_after_mps;
  record.energy_lost_J = event.energy_lost_J;
  return record;
}

// Writes the ends of soft contacts due before `time_s` (all of them for +infinity).
void flushEnds(JsonWriter& json, const physics::Timeline& timeline, PendingEnds& ends,
               double time_s) {
  while (!ends.empty() && ends.top().time_s < time_s) {
    const PendingEnd end = ends.top();
    ends.pop();
    writeRecord(json, timeline, collisionRecord(end.event, "contact_end", end.time_s, false));
  }
}

}  // namespace

void writeJsonEvents(JsonWriter& json, const physics::Timeline& timeline) {
  PendingEnds ends;
  std::int64_t begun = 0;
  json.beginArray();
  // A stop request (Ctrl-C) is checked per event: a long run (pi-blocks with 8 digits, 31
  // million collisions, gigabytes of JSON) stops within microseconds.
  const auto on_collision = [&](const physics::CollisionEvent& event) {
    core::throwIfStopRequested();
    flushEnds(json, timeline, ends, event.time_s);
    if (event.contact_duration_s > 0.0) {
      writeRecord(json, timeline, collisionRecord(event, "contact_start", event.time_s, true));
      ends.push({event, event.time_s + event.contact_duration_s, begun++});
      return;
    }
    writeRecord(json, timeline, collisionRecord(event, collisionKind(event), event.time_s, false));
  };
  const auto on_string = [&](const physics::StringEvent& event) {
    core::throwIfStopRequested();
    flushEnds(json, timeline, ends, event.time_s);
    writeRecord(json, timeline, stringRecord(event));
  };
  timeline.replayEvents(on_collision, on_string);
  flushEnds(json, timeline, ends, std::numeric_limits<double>::infinity());
  json.endArray();
}

}  // namespace collide::report
