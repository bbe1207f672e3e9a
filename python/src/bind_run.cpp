// SPDX-License-Identifier: MIT
// A simulation: the program's JSON summary and CSV table (collide data), and the exact state at
// any time.
#include <pybind11/stl.h>

#include <cmath>
#include <cstdio>
#include <mutex>
#include <sstream>

#include "app/simulation_progress.hpp"
#include "app/world_from_scene.hpp"
#include "bindings.hpp"
#include "core/error.hpp"
#include "core/typed_text.hpp"
#include "physics/timeline.hpp"
#include "report/csv_table.hpp"
#include "report/json_summary.hpp"
#include "report/physics_warnings.hpp"

namespace collide::python {
namespace {

class Run {
 public:
  Run(physics::Timeline timeline, std::string scene_name)
      : timeline_(std::move(timeline)), scene_name_(std::move(scene_name)) {}

  // `collide data --json` (with --events: the "events" array too), data version 2.
  std::string summaryJson(bool events) {
    std::ostringstream json;
    runReleased([&] {
      const std::lock_guard<std::mutex> lock(mutex_);
      report::writeJsonSummary(json, timeline_, {scene_name_, events});
    });
    return json.str();
  }

  // `collide data --csv --dt`: `dt_typed` is the step as the caller gave it, for the message.
  std::string csv(double dt_s, const std::string& dt_typed) {
    if (!std::isfinite(dt_s) || dt_s < report::kMinCsvStepS || dt_s > report::kMaxCsvStepS) {
      char allowed[120];
      std::snprintf(allowed, sizeof allowed, ": allowed: %g to %g seconds", report::kMinCsvStepS,
                    report::kMaxCsvStepS);
      throw core::InputError("dt: " + core::echoTyped(dt_typed) + allowed);
    }
    std::ostringstream table;
    runReleased([&] {
      const std::lock_guard<std::mutex> lock(mutex_);
      report::writeCsv(table, timeline_, report::clampTimeStep(dt_s).step_s);
    });
    return table.str();
  }

  // The exact state at t (after a collision at t), with the totals the summary reports.
  py::dict state(double t_s, const std::string& t_typed) {
    const double duration_s = timeline_.duration_s();
    if (!std::isfinite(t_s) || t_s < 0.0 || t_s > duration_s) {
      char allowed[80];
      std::snprintf(allowed, sizeof allowed, ": allowed: a time from 0 to %g s (the duration)",
                    duration_s);
      throw core::InputError("t: " + core::echoTyped(t_typed) + allowed);
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    const physics::Snapshot snapshot = timeline_.sample(t_s);
    py::list bodies;
    for (std::size_t k = 0; k < snapshot.bodies.size(); ++k) {
      const physics::BodyState& body = snapshot.bodies[k];
      py::dict entry;
      entry["name"] = timeline_.world().bodies[k].name;
      entry["position"] = py::make_tuple(body.position_m.x(), body.position_m.y());
      entry["velocity"] = py::make_tuple(body.velocity_mps.x(), body.velocity_mps.y());
      entry["angle"] = body.angle_rad;
      entry["angular_velocity"] = body.angular_velocity_radps;
      bodies.append(entry);
    }
    const core::Vec2 momentum = timeline_.momentum(snapshot);
    py::dict state;
    state["t"] = snapshot.time_s;
    state["bodies"] = bodies;
    state["momentum"] = py::make_tuple(momentum.x(), momentum.y());
    state["kinetic_energy"] = timeline_.kineticEnergy(snapshot);
    state["potential_energy"] = timeline_.potentialEnergy(snapshot);
    state["energy_lost"] = snapshot.energy_lost_J;
    state["collision_count"] = snapshot.collision_count;
    return state;
  }

  double duration() const { return timeline_.duration_s(); }
  std::vector<std::string> warnings() const { return report::physicsWarnings(timeline_); }

 private:
  physics::Timeline timeline_;
  std::string scene_name_;
  std::mutex mutex_;  // a Timeline re-simulates from its checkpoints when sampled
};

// `collide data`'s simulation: the scene read in English, simulated in full.
std::unique_ptr<Run> simulate(const py::tuple& recipe_tuple) {
  const SceneRecipe recipe = recipeFrom(recipe_tuple);
  std::unique_ptr<Run> run;
  runReleased([&] {
    scene::SceneDesc loaded;
    {
      std::unique_ptr<LanguageHold> hold;
      loaded = loadForData(recipe, hold);
    }
    run = std::make_unique<Run>(app::simulateReporting(app::worldFromScene(loaded)), loaded.name);
  });
  return run;
}

}  // namespace

void bindRun(py::module_& module) {
  py::class_<Run>(module, "Run")
      .def("summary_json", &Run::summaryJson, py::arg("events") = false)
      .def("csv", &Run::csv, py::arg("dt"), py::arg("dt_typed"))
      .def("state", &Run::state, py::arg("t"), py::arg("t_typed"))
      .def_property_readonly("duration", &Run::duration)
      .def_property_readonly("warnings", &Run::warnings);
  module.def("simulate", &simulate, py::arg("recipe"),
             "Simulates a scene recipe exactly as `collide data` does");
}

}  // namespace collide::python
