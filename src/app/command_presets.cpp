// collide presets: the built-in scenes, one per line.
#include <iomanip>

#include "app/command.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {
namespace {

class PresetsCommand : public Command {
 public:
  explicit PresetsCommand(CLI::App& root)
      : app_(*root.add_subcommand("presets", "List the built-in scenes")) {
    app_.footer("Example:\n  collide presets");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    for (const scene::PresetInfo& preset : scene::presetList()) {
      streams.out << std::left << std::setw(22) << preset.name << preset.summary << "\n";
    }
    return 0;
  }

 private:
  CLI::App& app_;
};

}  // namespace

std::unique_ptr<Command> makePresetsCommand(CLI::App& root) {
  return std::make_unique<PresetsCommand>(root);
}

std::vector<std::unique_ptr<Command>> makeCommands(CLI::App& root) {
  std::vector<std::unique_ptr<Command>> commands;
  commands.push_back(makeRenderCommand(root));
  commands.push_back(makeStillCommand(root));
  commands.push_back(makeDataCommand(root));
  commands.push_back(makePresetsCommand(root));
  commands.push_back(makeInfoCommand(root));
  return commands;
}

}  // namespace collide::app
