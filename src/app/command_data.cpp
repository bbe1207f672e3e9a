// collide data SCENE --json PATH|- [--events] --csv PATH|- [--dt S]: the simulated numbers, for
// checking from outside and for spreadsheets.
#include <cmath>
#include <cstdio>

#include "app/command.hpp"
#include "app/output_checks.hpp"
#include "app/scene_options.hpp"
#include "app/simulation_progress.hpp"
#include "app/world_from_scene.hpp"
#include "core/error.hpp"
#include "core/typed_text.hpp"
#include "output/output_target.hpp"
#include "output/stop_signals.hpp"
#include "output/text_output.hpp"
#include "report/csv_table.hpp"
#include "report/json_summary.hpp"
#include "report/physics_warnings.hpp"

namespace collide::app {
namespace {

class DataCommand : public Command {
 public:
  explicit DataCommand(CLI::App& root)
      : app_(*root.add_subcommand("data", "Write a scene's simulated numbers as JSON or CSV")) {
    scene_.words = false;  // CSV and JSON are the same in every language
    scene_.addSceneArgument(app_);
    app_.add_option("--json", json_path_, "Summary as JSON: output path, or - for stdout");
    app_.add_option("--csv", csv_path_,
                    "Table as CSV, one row per time step: output path, or - for stdout");
    app_.add_flag("--events", events_, "Include every collision in a \"collisions\" array");
    dt_option_ =
        app_.add_option("--dt", dt_s_, "CSV time step in seconds, 0.0005 to 0.05 (default 0.01)");
    app_.add_flag("--force", force_,
                  "Write the table even if it would be larger than 10 GB or than the free space "
                  "left for it");
    scene_.addChanges(app_);
    app_.footer(
        "The CSV has t_s, then per body position, velocity, kinetic energy and momentum, then "
        "the total momentum, the total kinetic energy and the energy lost so far (SI units, named "
        "in the header).\nExamples:\n  collide data worked-example --json -\n"
        "  collide data worked-example --json summary.json --events\n"
        "  collide data worked-example --csv table.csv --dt 0.005");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    if (json_path_.empty() && csv_path_.empty()) {
      throw core::InputError("data: nothing to write; allowed: --json PATH|- and/or --csv PATH|-");
    }
    if (json_path_ == "-" && csv_path_ == "-") {
      throw core::InputError("--csv: '-': stdout already receives --json; allowed: a file path");
    }
    if (events_ && json_path_.empty()) {
      throw core::InputError("--events: only applies to --json; allowed: add --json PATH|-");
    }
    if (dt_option_->count() > 0 && csv_path_.empty()) {
      throw core::InputError("--dt: only applies to --csv; allowed: add --csv PATH|-");
    }
    const scene::SceneDesc scene = scene_.load();
    if (!std::isfinite(dt_s_) || dt_s_ < report::kMinCsvStepS || dt_s_ > report::kMaxCsvStepS) {
      char allowed[120];
      std::snprintf(allowed, sizeof allowed, ": allowed: %g to %g seconds", report::kMinCsvStepS,
                    report::kMaxCsvStepS);
      throw core::InputError("--dt: " + core::echoTyped(dt_option_->results().back()) + allowed);
    }
    const report::TimeStep step = report::clampTimeStep(dt_s_);
    // Both files checked (paths, neither the other nor the scene file, the table's size) before
    // anything is simulated.
    std::vector<output::PlannedOutput> planned;
    if (!json_path_.empty()) planned.push_back({"--json", json_path_});
    if (!csv_path_.empty()) planned.push_back(csvOutput(csv_path_, scene, step.step_s));
    const output::OutputPlan outputs(planned, force_);

    // Ctrl-C or SIGTERM from here on stops cleanly: in the simulation, between collisions of the
    // --events stream, between CSV rows, or before a file is renamed into place.
    const output::StopSignals stop_signals;
    const physics::Timeline timeline = output::beforeWriting(
        targetsText(), [&] { return simulateReporting(worldFromScene(scene)); });
    // A run that stopped early (collision cap, stall, collision-rate cap) says where and why.
    report::printWarnings(report::physicsWarnings(timeline), streams.err);
    if (events_) checkEventsSize(timeline);
    if (!json_path_.empty()) {
      output::writeTextOutput(json_path_, streams.out, [&](std::ostream& stream) {
        report::writeJsonSummary(stream, timeline, {scene.name, events_});
      });
    }
    if (!csv_path_.empty()) {
      output::writeTextOutput(csv_path_, streams.out, [&](std::ostream& stream) {
        report::writeCsv(stream, timeline, step.step_s);
      });
    }
    return 0;
  }

 private:
  // Every collision as JSON: its size is known once the simulation has counted them.
  void checkEventsSize(const physics::Timeline& timeline) const {
    output::PlannedOutput json{"--json", json_path_};
    json.estimated_bytes = report::estimateJsonSummaryBytes(timeline, {"", true});
    json.estimate_basis = std::to_string(timeline.collisionCount()) + " collisions";
    json.smaller_with = "a shorter --duration, or no --events";
    const output::OutputPlan events(std::vector<output::PlannedOutput>{json}, force_);
  }

  // The outputs asked for, for a message: "'a.json' or 'b.csv'", "stdout".
  std::string targetsText() const {
    std::string text;
    for (const std::string* path : {&json_path_, &csv_path_}) {
      if (path->empty()) continue;
      if (!text.empty()) text += " or ";
      text += *path == "-" ? "stdout" : "'" + *path + "'";
    }
    return text;
  }

  CLI::App& app_;
  SceneOptions scene_;
  std::string json_path_;
  bool events_ = false;
  std::string csv_path_;
  double dt_s_ = report::kDefaultCsvStepS;
  CLI::Option* dt_option_ = nullptr;
  bool force_ = false;
};

}  // namespace

std::unique_ptr<Command> makeDataCommand(CLI::App& root) {
  return std::make_unique<DataCommand>(root);
}

}  // namespace collide::app
