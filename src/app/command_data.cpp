// collide data SCENE --json PATH|-: the simulated numbers, for checking from outside.
#include "app/command.hpp"
#include "app/output_target.hpp"
#include "app/scene_options.hpp"
#include "app/text_output.hpp"
#include "app/world_from_scene.hpp"
#include "physics/simulate.hpp"
#include "report/json_summary.hpp"

namespace collide::app {
namespace {

class DataCommand : public Command {
 public:
  explicit DataCommand(CLI::App& root)
      : app_(*root.add_subcommand("data", "Write a scene's simulated numbers as JSON")) {
    scene_.addTo(app_);
    app_.add_option("--json", json_path_, "Output path, or - for stdout")->required();
    app_.add_flag("--events", events_, "Include every collision in a \"collisions\" array");
    app_.footer(
        "Examples:\n  collide data worked-example --json -\n"
        "  collide data worked-example --json summary.json --events");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    const scene::SceneDesc scene = scene_.load();
    if (json_path_ != "-") requireParentDirectory("--json", json_path_);
    const physics::Timeline timeline = physics::simulate(worldFromScene(scene));
    writeTextOutput(json_path_, streams.out, [&](std::ostream& stream) {
      report::writeJsonSummary(stream, timeline, {scene.name, events_});
    });
    return 0;
  }

 private:
  CLI::App& app_;
  SceneOptions scene_;
  std::string json_path_;
  bool events_ = false;
};

}  // namespace

std::unique_ptr<Command> makeDataCommand(CLI::App& root) {
  return std::make_unique<DataCommand>(root);
}

}  // namespace collide::app
