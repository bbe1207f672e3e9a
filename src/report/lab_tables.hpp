// SPDX-License-Identifier: MIT
#pragma once
// Tables that lab software opens as they are (docs/data-format.md says how to import them):
//   Tracker (Open Source Physics): an "External Model" data file, delimited text that Tracker's
//     DataTool reads: a name row, a row of column names, then numbers; positions per body in
//     matched pairs "x<name>" "y<name>" and a time column "t", one row per video frame, so the
//     model's time step is the video's frame step and its points land on the video's bodies.
//   Logger Pro and Graphical Analysis (Vernier): "Vernier Format 3", tab-delimited: a data set
//     name, rows of long names, short names and units, a blank line, then the data.
// Numbers in the shortest form that reads back to the same double, as in the CSV; names in
// English and never localised (data files are the same in every language).
#include <ostream>
#include <string>
#include <vector>

#include "physics/timeline.hpp"

namespace collide::report {

// One row of a Tracker model: the time it stands at in the video (frame k at k / fps) and the
// simulated time its positions are sampled at (the same unless the video runs in slow motion).
struct TrackerRow {
  double video_s = 0.0;
  double simulated_s = 0.0;
};

// The point names of the bodies as Tracker reads them from the column names ("cart 1" ->
// "cart_1", Tracker shows underscores as spaces): a name Tracker would misread (empty, ending in
// x or X, which Tracker takes for an x column of another point) or one already given gets "_N"
// (N the body's number from 1). Whitespace, control characters and the delimiters Tracker tries
// (",", ";") become "_".
std::vector<std::string> trackerPointNames(const physics::WorldDef& world);

// The model's name row for `scene_name`: Tracker takes a first row with one entry that is not a
// number for the model's name; spaces and delimiters become "_", and a name Java would read as a
// number (or empty) is prefixed with "scene_".
std::string trackerModelName(const std::string& scene_name);

// Writes the name row, "t" and the pairs "x<point>" "y<point>" per body, then one row per entry
// of `rows` (t the video time, positions in metres at the simulated time, y up; 1D bodies are on
// the track, y = 0). Tab-delimited, "\n" line ends.
void writeTrackerModel(std::ostream& out, const physics::Timeline& timeline,
                       const std::string& scene_name, const std::vector<TrackerRow>& rows);

// The columns of a Vernier table: long name, short name, units.
struct VernierColumn {
  std::string long_name;   // "cart 1 position"
  std::string short_name;  // "x1"
  std::string units;       // "m"
};
std::vector<VernierColumn> vernierColumns(const physics::WorldDef& world);

// Writes "Vernier Format 3", the source row ("collide", no date or time: the file is the same on
// every run), the data set's name, the long names, short names and units, a blank line, then one
// row per time of csvRowTimes(duration, step_s): time (s), per body its position (m) and velocity
// (m/s) (in 2D x, y, vx, vy), then the total momentum (kg m/s; 2D px, py), the total kinetic
// energy (J) and the energy lost so far (J). Tab-delimited, "\n" line ends.
void writeVernierTable(std::ostream& out, const physics::Timeline& timeline,
                       const std::string& scene_name, double step_s);

}  // namespace collide::report
