#include "report/csv_table.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "core/stop_request.hpp"
#include "report/json_writer.hpp"

namespace collide::report {

// RFC 4180: a field holding a comma, a quote or a line break is quoted, quotes doubled.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

std::string csvHeader(const physics::WorldDef& world) {
  std::ostringstream out;
  out << "t_s";
  for (const physics::BodyDef& body : world.bodies) {
    const std::string& n = body.name;
    if (world.dimensions == 1) {
      for (const char* column : {"_x_m", "_v_mps", "_ke_J", "_p_kgmps"}) {
        out << ',' << csvField(n + column);
      }
    } else {
      for (const char* column :
           {"_x_m", "_y_m", "_vx_mps", "_vy_mps", "_ke_J", "_px_kgmps", "_py_kgmps"}) {
        out << ',' << csvField(n + column);
      }
    }
  }
  out << (world.dimensions == 1 ? ",p_total_kgmps" : ",px_total_kgmps,py_total_kgmps")
      << ",ke_total_J,energy_lost_J";
  // Only where energy can come in, so that other scenes' tables keep their columns.
  if (physics::canReleaseEnergy(world)) out << ",energy_released_J";
  // Likewise only where bodies slide with friction: its work, turned into heat.
  if (physics::hasFriction(world)) out << ",energy_to_surface_J";
  if (physics::hasDrag(world)) out << ",energy_to_air_J";
  return out.str();
}

CsvSize estimateCsvSize(int dimensions, std::size_t bodies, double duration_s, double step_s,
                        bool releases, int version) {
  // A double in its shortest form has up to 17 digits, a sign, a point and an exponent: moving
  // bodies' fields average about 20 bytes with the comma.
  constexpr double kBytesPerField = 20.0;
  CsvSize size;
  size.rows = static_cast<long long>(std::floor(duration_s / step_s + 1e-9)) + 1;
  const int momentum_columns = dimensions == 1 ? 1 : 2;
  if (version >= 2) {
    // Position, velocity, momentum, kinetic and potential energy per body; energy_lost_J and
    // energy_released_J always.
    const int per_body = dimensions == 1 ? 5 : 8;
    size.columns = 1 + per_body * static_cast<int>(bodies) + momentum_columns + 2;
  } else {
    const int per_body = dimensions == 1 ? 4 : 7;
    size.columns =
        1 + per_body * static_cast<int>(bodies) + momentum_columns + 2 + (releases ? 1 : 0);
  }
  size.bytes = static_cast<double>(size.rows) * size.columns * kBytesPerField;
  return size;
}

TimeStep clampTimeStep(double requested_s) {
  if (std::isnan(requested_s)) return {kDefaultCsvStepS, true};
  if (requested_s < kMinCsvStepS) return {kMinCsvStepS, true};
  if (requested_s > kMaxCsvStepS) return {kMaxCsvStepS, true};
  return {requested_s, false};
}

std::vector<double> csvRowTimes(double duration_s, double step_s) {
  COLLIDE_ASSERT(step_s > 0.0 && duration_s >= 0.0, "need a positive step and a duration");
  const auto toNanosecond = [](double t) { return std::round(t * 1e9) / 1e9; };
  std::vector<double> times;
  // The small allowance keeps a last step that lands on the duration up to rounding.
  const auto steps = static_cast<long long>(std::floor(duration_s / step_s + 1e-9));
  times.reserve(static_cast<std::size_t>(steps) + 2);
  for (long long k = 0; k <= steps; ++k) {
    times.push_back(std::min(toNanosecond(static_cast<double>(k) * step_s), duration_s));
  }
  if (duration_s - times.back() > 1e-9) times.push_back(duration_s);
  return times;
}

void writeCsv(std::ostream& out, const physics::Timeline& timeline, double step_s, int version) {
  COLLIDE_ASSERT(version >= kOldestDataVersion && version <= kDataVersion,
                 "writeCsv: no such data version");
  if (version >= 2) {
    writeCsvBooks(out, timeline, step_s);
    return;
  }
  const physics::WorldDef& world = timeline.world();
  // Plain \n line ends: what scripts on every system and every spreadsheet read.
  out << csvHeader(world) << "\n";
  const bool releases = physics::canReleaseEnergy(world);
  const bool friction = physics::hasFriction(world);
  const bool drag = physics::hasDrag(world);
  for (const double t : csvRowTimes(timeline.duration_s(), step_s)) {
    // A stop request (Ctrl-C) is checked per row: a sample may replay thousands of collisions.
    core::throwIfStopRequested();
    const physics::Snapshot snapshot = timeline.sample(t);
    out << shortestDecimal(t);
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
      const double m = world.bodies[i].mass_kg;
      const physics::BodyState& state = snapshot.bodies[i];
      const core::Vec2& x = state.position_m;
      const core::Vec2& v = state.velocity_mps;
      const double ke = 0.5 * m * (world.dimensions == 1 ? v.x() * v.x() : v.squaredNorm());
      if (world.dimensions == 1) {
        out << ',' << shortestDecimal(x.x()) << ',' << shortestDecimal(v.x()) << ','
            << shortestDecimal(ke) << ',' << shortestDecimal(m * v.x());
      } else {
        out << ',' << shortestDecimal(x.x()) << ',' << shortestDecimal(x.y()) << ','
            << shortestDecimal(v.x()) << ',' << shortestDecimal(v.y()) << ',' << shortestDecimal(ke)
            << ',' << shortestDecimal(m * v.x()) << ',' << shortestDecimal(m * v.y());
      }
    }
    const core::Vec2 p = timeline.momentum(snapshot);
    out << ',' << shortestDecimal(p.x());
    if (world.dimensions != 1) out << ',' << shortestDecimal(p.y());
    out << ',' << shortestDecimal(timeline.kineticEnergy(snapshot)) << ','
        << shortestDecimal(snapshot.energy_lost_J);
    if (releases) out << ',' << shortestDecimal(snapshot.energy_released_J);
    if (friction) out << ',' << shortestDecimal(snapshot.energy_to_surface_J);
    if (drag) out << ',' << shortestDecimal(snapshot.energy_to_air_J);
    out << "\n";
  }
}

}  // namespace collide::report
