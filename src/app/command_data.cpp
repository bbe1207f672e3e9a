// collide data SCENE --json PATH|- [--events] --csv PATH|- [--dt S] [--data-version N]
// --tracker PATH|- [--fps N] --vernier PATH|-: the simulated numbers, for checking from outside,
// for spreadsheets and for the lab's software (Tracker, Logger Pro).
#include <cmath>
#include <cstdio>

#include "app/command.hpp"
#include "app/lab_data.hpp"
#include "app/output_checks.hpp"
#include "app/render_settings.hpp"
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
#include "report/lab_tables.hpp"
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
    app_.add_flag("--events", events_,
                  "Include every event (impacts, walls, strings, contacts) in an \"events\" array");
    version_option_ = app_.add_option(
        "--data-version", data_version_,
        "The shape of --json and --csv: 2 (the default) or 1, the older one (docs/data-format.md)");
    dt_option_ = app_.add_option(
        "--dt", dt_s_, "CSV and Vernier time step in seconds, 0.0005 to 0.05 (default 0.01)");
    app_.add_option("--tracker", tracker_path_,
                    "Positions per video frame for Tracker's External Model: output path, or - "
                    "for stdout");
    fps_option_ = app_.add_option(
        "--fps", fps_, "The video's frames per second for --tracker, 1 to 240 (default 60)");
    app_.add_option("--vernier", vernier_path_,
                    "Table in Vernier Format 3 for Logger Pro: output path, or - for stdout");
    app_.add_flag("--force", force_,
                  "Write the table even if it would be larger than 10 GB or than the free space "
                  "left for it");
    scene_.addChanges(app_);
    app_.footer(
        "The CSV has t_s, then per body position, velocity, momentum, kinetic and potential "
        "energy, then the total momentum, each soft contact's spring energy, the energy lost and "
        "released so far (SI units, named in the header); its energy columns add up to the "
        "energy at the start. docs/data-format.md describes every column and field, and how to "
        "import --tracker and --vernier."
        "\nExamples:\n  collide data worked-example --json -\n"
        "  collide data worked-example --json summary.json --events\n"
        "  collide data worked-example --csv table.csv --dt 0.005\n"
        "  collide data worked-example --tracker model.txt --fps 30 --vernier table.txt");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    checkCombinations();
    const scene::SceneDesc scene = scene_.load();
    const report::TimeStep step = checkedStep();
    // Every file checked (paths, none another or the scene file, the tables' sizes) before
    // anything is simulated.
    std::vector<output::PlannedOutput> planned;
    if (!json_path_.empty()) planned.push_back({"--json", json_path_});
    if (!csv_path_.empty()) planned.push_back(csvOutput(csv_path_, scene, step.step_s));
    if (!tracker_path_.empty()) {
      planned.push_back(trackerOutput("--tracker", tracker_path_, scene, fps_));
    }
    if (!vernier_path_.empty()) {
      planned.push_back(vernierOutput("--vernier", vernier_path_, scene, step.step_s));
    }
    const output::OutputPlan outputs(planned, force_);

    // Ctrl-C or SIGTERM from here on stops cleanly: in the simulation, between collisions of the
    // --events stream, between rows, or before a file is renamed into place.
    const output::StopSignals stop_signals;
    const physics::Timeline timeline = output::beforeWriting(
        targetsText(), [&] { return simulateReporting(worldFromScene(scene)); });
    // A run that stopped early (collision cap, stall, collision-rate cap) says where and why.
    report::printWarnings(report::physicsWarnings(timeline), streams.err);
    if (events_) checkEventsSize(timeline);
    writeTables(scene, timeline, step.step_s, streams.out);
    return 0;
  }

 private:
  std::vector<const std::string*> paths() const {
    return {&json_path_, &csv_path_, &tracker_path_, &vernier_path_};
  }

  void checkCombinations() const {
    int to_stdout = 0, asked = 0;
    for (const std::string* path : paths()) {
      asked += path->empty() ? 0 : 1;
      to_stdout += *path == "-" ? 1 : 0;
    }
    if (asked == 0) {
      throw core::InputError(
          "data: nothing to write; allowed: --json, --csv, --tracker and/or --vernier, each "
          "PATH|-");
    }
    if (to_stdout > 1) {
      throw core::InputError(
          "'-': stdout can receive one of --json, --csv, --tracker, --vernier; allowed: a file "
          "path for the others");
    }
    if (events_ && json_path_.empty()) {
      throw core::InputError("--events: only applies to --json; allowed: add --json PATH|-");
    }
    if (dt_option_->count() > 0 && csv_path_.empty() && vernier_path_.empty()) {
      throw core::InputError(
          "--dt: only applies to --csv and --vernier; allowed: add --csv PATH|- or --vernier "
          "PATH|-");
    }
    if (version_option_->count() > 0 && json_path_.empty() && csv_path_.empty()) {
      throw core::InputError(
          "--data-version: only applies to --json and --csv; allowed: add --json PATH|- or --csv "
          "PATH|-");
    }
    checkDataVersion();
    if (fps_option_->count() > 0 && tracker_path_.empty()) {
      throw core::InputError("--fps: only applies to --tracker; allowed: add --tracker PATH|-");
    }
    checkFps(fps_);
  }

  void checkDataVersion() const {
    if (data_version_ >= report::kOldestDataVersion && data_version_ <= report::kDataVersion) {
      return;
    }
    throw core::InputError("--data-version: " + core::echoTyped(version_option_->results().back()) +
                           ": allowed: 1 or 2 (the default)");
  }

  report::TimeStep checkedStep() const {
    if (!std::isfinite(dt_s_) || dt_s_ < report::kMinCsvStepS || dt_s_ > report::kMaxCsvStepS) {
      char allowed[120];
      std::snprintf(allowed, sizeof allowed, ": allowed: %g to %g seconds", report::kMinCsvStepS,
                    report::kMaxCsvStepS);
      throw core::InputError("--dt: " + core::echoTyped(dt_option_->results().back()) + allowed);
    }
    return report::clampTimeStep(dt_s_);
  }

  void writeTables(const scene::SceneDesc& scene, const physics::Timeline& timeline, double step_s,
                   std::ostream& out) const {
    if (!json_path_.empty()) {
      output::writeTextOutput(json_path_, out, [&](std::ostream& stream) {
        report::writeJsonSummary(stream, timeline, {scene.name, events_, data_version_});
      });
    }
    if (!csv_path_.empty()) {
      output::writeTextOutput(csv_path_, out, [&](std::ostream& stream) {
        report::writeCsv(stream, timeline, step_s, data_version_);
      });
    }
    if (!tracker_path_.empty()) {
      const std::vector<report::TrackerRow> rows = trackerRows(scene, timeline, fps_);
      output::writeTextOutput(tracker_path_, out, [&](std::ostream& stream) {
        report::writeTrackerModel(stream, timeline, scene.name, rows);
      });
    }
    if (!vernier_path_.empty()) {
      output::writeTextOutput(vernier_path_, out, [&](std::ostream& stream) {
        report::writeVernierTable(stream, timeline, scene.name, step_s);
      });
    }
  }

  // Every collision as JSON: its size is known once the simulation has counted them.
  void checkEventsSize(const physics::Timeline& timeline) const {
    output::PlannedOutput json{"--json", json_path_};
    json.estimated_bytes = report::estimateJsonSummaryBytes(timeline, {"", true, data_version_});
    json.estimate_basis = std::to_string(timeline.collisionCount()) + " collisions";
    json.smaller_with = "a shorter --duration, or no --events";
    const output::OutputPlan events(std::vector<output::PlannedOutput>{json}, force_);
  }

  // The outputs asked for, for a message: "'a.json' or 'b.csv'", "stdout".
  std::string targetsText() const {
    std::string text;
    for (const std::string* path : paths()) {
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
  int data_version_ = report::kDataVersion;
  CLI::Option* version_option_ = nullptr;
  std::string csv_path_;
  double dt_s_ = report::kDefaultCsvStepS;
  CLI::Option* dt_option_ = nullptr;
  std::string tracker_path_;
  int fps_ = 60;
  CLI::Option* fps_option_ = nullptr;
  std::string vernier_path_;
  bool force_ = false;
};

}  // namespace

std::unique_ptr<Command> makeDataCommand(CLI::App& root) {
  return std::make_unique<DataCommand>(root);
}

}  // namespace collide::app
