// SPDX-License-Identifier: MIT
#pragma once
// The tables for lab software (report/lab_tables.hpp) as `collide data --tracker/--vernier` and
// `collide lesson` write them: a Tracker model's rows follow the video's frames, and each file's
// size is known before anything is simulated.
#include <string>
#include <vector>

#include "output/output_plan.hpp"
#include "physics/timeline.hpp"
#include "report/lab_tables.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {

// One row per frame of `collide render` at `fps`: frame k at video time k / fps, showing the
// simulated time the video shows then (slow motion around collisions, ViewDesc::
// slow_motion_factor, makes the two differ). Both rounded to the nanosecond, as the CSV's times,
// so a row at a time the CSV also has holds the same positions.
std::vector<report::TrackerRow> trackerRows(const scene::SceneDesc& scene,
                                            const physics::Timeline& timeline, int fps);

// The --tracker and --vernier files of `scene`, their sizes from their rows and columns: a
// Tracker model has at most fps x duration x the slow-motion factor rows.
output::PlannedOutput trackerOutput(const std::string& option, const std::string& path,
                                    const scene::SceneDesc& scene, int fps);
output::PlannedOutput vernierOutput(const std::string& option, const std::string& path,
                                    const scene::SceneDesc& scene, double step_s);

}  // namespace collide::app
