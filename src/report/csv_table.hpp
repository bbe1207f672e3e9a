#pragma once
// `collide data SCENE --csv`: the state of every body at regular time steps, one row per step, for
// a spreadsheet or a plotting script; docs/data-format.md describes every column. Version 2 (the
// default, see csv_books.cpp):
//   t_s, then per body  <name>_x_m, <name>_v_mps, <name>_p_kgmps, <name>_ke_J, <name>_pe_J  (1D)
//                   or  <name>_x_m, <name>_y_m, <name>_vx_mps, <name>_vy_mps,
//                       <name>_px_kgmps, <name>_py_kgmps, <name>_ke_J, <name>_pe_J          (2D)
//   then p_total_kgmps (1D) or px_total_kgmps, py_total_kgmps (2D), a spring_<a>_<b>_J per soft
//   contact pair, energy_lost_J and energy_released_J: every _J column but energy_released_J adds
//   up, in every row, to the energy at the start plus energy_released_J.
// Version 1 (the older shape):
//   t_s, then per body  <name>_x_m, <name>_v_mps, <name>_ke_J, <name>_p_kgmps          (1D)
//                   or  <name>_x_m, <name>_y_m, <name>_vx_mps, <name>_vy_mps, <name>_ke_J,
//                       <name>_px_kgmps, <name>_py_kgmps                                  (2D)
//   then p_total_kgmps (1D) or px_total_kgmps, py_total_kgmps (2D), ke_total_J, energy_lost_J
//   (and energy_released_J where energy can come in). Per-body KE is translational, 1/2 m v^2;
//   ke_total_J also counts the spin of joined 2D disks; energy_lost_J books a soft contact's
//   whole loss at its start.
// Numbers are written in the shortest form that reads back to the same double.
#include <ostream>

#include "physics/timeline.hpp"
#include "report/data_version.hpp"

namespace collide::report {

// The reference simulator's limits for its time step, s.
inline constexpr double kMinCsvStepS = 0.0005;
inline constexpr double kMaxCsvStepS = 0.05;
inline constexpr double kDefaultCsvStepS = 0.01;

struct TimeStep {
  double step_s = kDefaultCsvStepS;  // the step used, within [kMinCsvStepS, kMaxCsvStepS]
  bool clamped = false;              // the requested step was outside and was moved to a limit
};

// `requested_s` moved into [kMinCsvStepS, kMaxCsvStepS]; NaN gives the default, clamped.
TimeStep clampTimeStep(double requested_s);

// Row times: k * step for k = 0, 1, ... while <= duration, and the duration itself as a last row
// when the steps do not land on it. Times are rounded to the nanosecond so that 3 x 0.1 s reads
// "0.3". `step_s` must be > 0.
std::vector<double> csvRowTimes(double duration_s, double step_s);

// The size of a table, known before anything is simulated (its rows come from the duration and the
// step, its columns from the bodies), so that a request for a terabyte is refused up front.
struct CsvSize {
  long long rows = 0;  // header not counted
  int columns = 0;
  // About, from above: 20 bytes a field, what moving bodies' values in their shortest form take
  // with the comma (bodies at rest write "0"), so a table is seldom larger than said.
  double bytes = 0.0;
};
// `releases`: energy can come in (physics::canReleaseEnergy): version 1 has one more column,
// energy_released_J. Version 2's spring columns (known only once simulated) are not counted.
// Bodies sliding with friction add energy_to_surface_J, bodies under drag energy_to_air_J (not
// counted here).
CsvSize estimateCsvSize(int dimensions, std::size_t bodies, double duration_s, double step_s,
                        bool releases = false, int version = kDataVersion);

// Version 1's header line (without its line end) for `world`.
std::string csvHeader(const physics::WorldDef& world);
// Version 2's header line for `timeline` (its spring columns come from its soft contacts).
std::string csvBooksHeader(const physics::Timeline& timeline);

// Writes the header and one row per time of csvRowTimes(timeline.duration_s(), step_s), sampling
// the timeline exactly at each time (a row at a collision time shows the state just after it).
// Names are quoted as CSV requires when they hold a comma, a quote or a line break.
// `version`: kOldestDataVersion to kDataVersion.
void writeCsv(std::ostream& out, const physics::Timeline& timeline, double step_s,
              int version = kDataVersion);
// Version 2's rows (csv_books.cpp), as writeCsv writes them.
void writeCsvBooks(std::ostream& out, const physics::Timeline& timeline, double step_s);

// A field as RFC 4180 writes it: quoted when it holds a comma, a quote or a line break.
std::string csvField(const std::string& text);

}  // namespace collide::report
