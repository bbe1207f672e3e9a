// SPDX-License-Identifier: MIT
// Version 2 of `collide data --csv`: the state of every body and the energy books at each row, so
// that every row's energy columns add up to the energy at the start (see csv_table.hpp).
#include <sstream>
#include <string>
#include <vector>

#include "core/stop_request.hpp"
#include "physics/energy_books.hpp"
#include "report/csv_table.hpp"
#include "report/json_writer.hpp"

namespace collide::report {
namespace {

// One soft contact pair's spring: a column of its own, whatever number of contacts it has.
struct SpringColumn {
  int body_a = 0, body_b = 0;  // as in physics::CollisionEvent (b < 0: a wall)
};

// The pairs that were in soft contact during the run, in the order they first touched.
std::vector<SpringColumn> springColumns(const physics::Timeline& timeline) {
  std::vector<SpringColumn> columns;
  for (const physics::SoftContact& contact : timeline.softContacts()) {
    bool known = false;
    for (const SpringColumn& column : columns) {
      known = known || (column.body_a == contact.body_a && column.body_b == contact.body_b);
    }
    if (!known) columns.push_back({contact.body_a, contact.body_b});
  }
  return columns;
}

// "spring_1_2_J" for bodies 1 and 2 (numbered from 1), "spring_1_floor_J" for body 1 on the wall
// named floor.
std::string springName(const physics::WorldDef& world, const SpringColumn& column) {
  std::string name = "spring_" + std::to_string(column.body_a + 1) + "_";
  if (column.body_b >= 0) {
    name += std::to_string(column.body_b + 1);
  } else {
    name +=
        world.walls.at(static_cast<std::size_t>(physics::kWallPartnerBase - column.body_b)).name;
  }
  return name + "_J";
}

void writeBodyHeader(std::ostream& out, const physics::WorldDef& world) {
  static const char* const kColumns1d[] = {"_x_m", "_v_mps", "_p_kgmps", "_ke_J", "_pe_J"};
  static const char* const kColumns2d[] = {"_x_m",      "_y_m",      "_vx_mps", "_vy_mps",
                                           "_px_kgmps", "_py_kgmps", "_ke_J",   "_pe_J"};
  for (const physics::BodyDef& body : world.bodies) {
    if (world.dimensions == 1) {
      for (const char* column : kColumns1d) out << ',' << csvField(body.name + column);
    } else {
      for (const char* column : kColumns2d) out << ',' << csvField(body.name + column);
    }
  }
}

// A body's fields: position, velocity, momentum, kinetic energy (from the books: spin included)
// and the potential energy of gravity, -m g.x (zero at the scene's origin).
void writeBodyFields(std::ostream& out, const physics::WorldDef& world, std::size_t i,
                     const physics::BodyState& state, double kinetic_J) {
  const physics::BodyDef& body = world.bodies[i];
  const core::Vec2& x = state.position_m;
  const core::Vec2& v = state.velocity_mps;
  const double m = body.mass_kg;
  // 0 - (...), not -(...): without gravity that is 0, never "-0".
  const double potential_J = 0.0 - m * world.gravity_mps2.dot(x);
  if (world.dimensions == 1) {
    out << ',' << shortestDecimal(x.x()) << ',' << shortestDecimal(v.x()) << ','
        << shortestDecimal(m * v.x());
  } else {
    out << ',' << shortestDecimal(x.x()) << ',' << shortestDecimal(x.y()) << ','
        << shortestDecimal(v.x()) << ',' << shortestDecimal(v.y()) << ','
        << shortestDecimal(m * v.x()) << ',' << shortestDecimal(m * v.y());
  }
  out << ',' << shortestDecimal(kinetic_J) << ',' << shortestDecimal(potential_J);
}

// The energy stored in the pair's spring at this instant (0 while the pair is apart).
double springEnergy(const physics::EnergyBooks& books, const SpringColumn& column) {
  double energy_J = 0.0;
  for (const physics::SpringEnergy& spring : books.springs) {
    if (spring.body_a == column.body_a && spring.body_b == column.body_b) {
      energy_J += spring.energy_J;
    }
  }
  return energy_J;
}

void writeBooksRow(std::ostream& out, const physics::Timeline& timeline,
                   const std::vector<SpringColumn>& springs, double t_s) {
  const physics::WorldDef& world = timeline.world();
  // The books as the picture's energy bar keeps them (lab frame, gravity from the origin): a soft
  // contact's loss accrues while it lasts.
  const physics::EnergyBooks books = physics::energyBooks(timeline, t_s);
  const physics::Snapshot snapshot = timeline.sample(t_s);
  out << shortestDecimal(t_s);
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    writeBodyFields(out, world, i, snapshot.bodies[i], books.kinetic_J[i]);
  }
  const core::Vec2 p = timeline.momentum(snapshot);
  out << ',' << shortestDecimal(p.x());
  if (world.dimensions != 1) out << ',' << shortestDecimal(p.y());
  for (const SpringColumn& column : springs) {
    out << ',' << shortestDecimal(springEnergy(books, column));
  }
  if (world.internal_dof > 0) out << ',' << shortestDecimal(books.internal_J);
  out << ',' << shortestDecimal(books.lost_J);
  if (physics::hasFriction(world)) out << ',' << shortestDecimal(books.surface_J);
  if (physics::hasDrag(world)) out << ',' << shortestDecimal(books.air_J);
  out << ',' << shortestDecimal(books.released_J) << "\n";
}

}  // namespace

std::string csvBooksHeader(const physics::Timeline& timeline) {
  const physics::WorldDef& world = timeline.world();
  std::ostringstream out;
  out << "t_s";
  writeBodyHeader(out, world);
  out << (world.dimensions == 1 ? ",p_total_kgmps" : ",px_total_kgmps,py_total_kgmps");
  for (const SpringColumn& column : springColumns(timeline)) {
    out << ',' << csvField(springName(world, column));
  }
  // Each share of the loss is a column of its own ending in _J, so that the rule "every _J column
  // but energy_released_J adds up to the start plus energy_released_J" holds for new ones too.
  // Molecules with insides: the disks' internal energy, a part of the books like a spring's.
  if (world.internal_dof > 0) out << ",internal_energy_J";
  out << ",energy_lost_J";
  // Sliding friction's work (heat in the surface), only where bodies slide with friction.
  if (physics::hasFriction(world)) out << ",energy_to_surface_J";
  // Air drag's work, only where bodies feel drag.
  if (physics::hasDrag(world)) out << ",energy_to_air_J";
  out << ",energy_released_J";
  return out.str();
}

void writeCsvBooks(std::ostream& out, const physics::Timeline& timeline, double step_s) {
  out << csvBooksHeader(timeline) << "\n";
  const std::vector<SpringColumn> springs = springColumns(timeline);
  for (const double t : csvRowTimes(timeline.duration_s(), step_s)) {
    // A stop request (Ctrl-C) is checked per row: a sample may replay thousands of collisions.
    core::throwIfStopRequested();
    writeBooksRow(out, timeline, springs, t);
  }
}

}  // namespace collide::report
