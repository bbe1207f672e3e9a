// SPDX-License-Identifier: MIT
#include "report/lab_tables.hpp"

#include <algorithm>
#include <set>

#include "core/stop_request.hpp"
#include "report/csv_table.hpp"
#include "report/json_writer.hpp"

namespace collide::report {
namespace {

// Characters that would split or end a Tracker entry: whitespace and control characters (Tracker
// tries " ", tab, "," and ";" as delimiters in turn), and "#", which starts a gnuplot comment.
bool splitsTrackerEntry(unsigned char c) {
  return c <= ' ' || c == 0x7f || c == ',' || c == ';' || c == '#';
}

std::string trackerEntry(const std::string& text) {
  std::string entry = text;
  for (char& c : entry) {
    if (splitsTrackerEntry(static_cast<unsigned char>(c))) c = '_';
  }
  return entry;
}

// Whether Java's Double.parseDouble might take `text` for a number (so Tracker would not take it
// for a name): every character is one a Java number can hold (digits, sign, point, exponent,
// hex digits and prefix, the d/f suffix, the letters of "Infinity" and "NaN").
bool javaMightReadAsNumber(const std::string& text) {
  static const std::string kNumberCharacters = "0123456789+-.xXpPabcdefABCDEFInityN";
  return text.find_first_not_of(kNumberCharacters) == std::string::npos;
}

// Tab and the characters Vernier's format forbids in names (the quote and the colon).
std::string vernierName(const std::string& text) {
  std::string name = text;
  for (char& c : name) {
    if (static_cast<unsigned char>(c) < ' ' || c == '"' || c == ':') c = ' ';
  }
  return name;
}

}  // namespace

std::vector<std::string> trackerPointNames(const physics::WorldDef& world) {
  std::vector<std::string> names;
  std::set<std::string> given;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    std::string name = trackerEntry(world.bodies[i].name);
    const bool misread = name.empty() || name.back() == 'x' || name.back() == 'X';
    if (misread || given.count(name) > 0) {
      // Appended in two steps: "_" + std::to_string(...) makes g++ 12 warn (-Wrestrict) about
      // a copy it never makes, and CI builds with -Werror.
      name += '_';
      name += std::to_string(i + 1);
    }
    given.insert(name);
    names.push_back(name);
  }
  return names;
}

std::string trackerModelName(const std::string& scene_name) {
  const std::string name = trackerEntry(scene_name);
  // "//" starts a comment line; a name Java reads as a number would be taken for data.
  if (javaMightReadAsNumber(name) || name.rfind("//", 0) == 0) return "scene_" + name;
  return name;
}

void writeTrackerModel(std::ostream& out, const physics::Timeline& timeline,
                       const std::string& scene_name, const std::vector<TrackerRow>& rows) {
  const physics::WorldDef& world = timeline.world();
  out << trackerModelName(scene_name) << "\n"
      << "t";
  for (const std::string& point : trackerPointNames(world)) {
    out << "\tx" << point << "\ty" << point;
  }
  out << "\n";
  for (const TrackerRow& row : rows) {
    core::throwIfStopRequested();  // a sample may replay thousands of collisions
    const physics::Snapshot snapshot = timeline.sample(row.simulated_s);
    out << shortestDecimal(row.video_s);
    for (const physics::BodyState& body : snapshot.bodies) {
      const double y_m = world.dimensions == 1 ? 0.0 : body.position_m.y();
      out << '\t' << shortestDecimal(body.position_m.x()) << '\t' << shortestDecimal(y_m);
    }
    out << "\n";
  }
}

std::vector<VernierColumn> vernierColumns(const physics::WorldDef& world) {
  std::vector<VernierColumn> columns{{"Time", "t", "s"}};
  const bool one_d = world.dimensions == 1;
  for (std::size_t i = 0; i < world.bodies.size(); ++i) {
    const std::string name = vernierName(world.bodies[i].name), n = std::to_string(i + 1);
    if (one_d) {
      columns.push_back({name + " position", "x" + n, "m"});
      columns.push_back({name + " velocity", "v" + n, "m/s"});
    } else {
      columns.push_back({name + " x position", "x" + n, "m"});
      columns.push_back({name + " y position", "y" + n, "m"});
      columns.push_back({name + " x velocity", "vx" + n, "m/s"});
      columns.push_back({name + " y velocity", "vy" + n, "m/s"});
    }
  }
  if (one_d) {
    columns.push_back({"Total momentum", "p", "kg m/s"});
  } else {
    columns.push_back({"Total x momentum", "px", "kg m/s"});
    columns.push_back({"Total y momentum", "py", "kg m/s"});
  }
  columns.push_back({"Total kinetic energy", "KE", "J"});
  columns.push_back({"Energy lost", "Elost", "J"});
  return columns;
}

void writeVernierTable(std::ostream& out, const physics::Timeline& timeline,
                       const std::string& scene_name, double step_s) {
  const physics::WorldDef& world = timeline.world();
  const std::vector<VernierColumn> columns = vernierColumns(world);
  out << "Vernier Format 3\ncollide\t\t\n" << vernierName(scene_name) << "\n";
  for (auto field :
       {&VernierColumn::long_name, &VernierColumn::short_name, &VernierColumn::units}) {
    for (std::size_t c = 0; c < columns.size(); ++c) out << (c ? "\t" : "") << columns[c].*field;
    out << "\n";
  }
  out << "\n";
  const bool one_d = world.dimensions == 1;
  for (const double t : csvRowTimes(timeline.duration_s(), step_s)) {
    core::throwIfStopRequested();
    const physics::Snapshot snapshot = timeline.sample(t);
    out << shortestDecimal(t);
    for (const physics::BodyState& body : snapshot.bodies) {
      const core::Vec2& x = body.position_m;
      const core::Vec2& v = body.velocity_mps;
      if (one_d) {
        out << '\t' << shortestDecimal(x.x()) << '\t' << shortestDecimal(v.x());
      } else {
        out << '\t' << shortestDecimal(x.x()) << '\t' << shortestDecimal(x.y()) << '\t'
            << shortestDecimal(v.x()) << '\t' << shortestDecimal(v.y());
      }
    }
    const core::Vec2 p = timeline.momentum(snapshot);
    out << '\t' << shortestDecimal(p.x());
    if (!one_d) out << '\t' << shortestDecimal(p.y());
    out << '\t' << shortestDecimal(timeline.kineticEnergy(snapshot)) << '\t'
        << shortestDecimal(snapshot.energy_lost_J) << "\n";
  }
}

}  // namespace collide::report
