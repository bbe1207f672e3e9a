// collide presets: the built-in scenes, one per line; `collide presets show NAME` prints one as a
// scene file to copy and edit.
#include <algorithm>
#include <iomanip>

#include "app/command.hpp"
#include "app/scene_options.hpp"
#include "scene/scene_desc.hpp"
#include "scene/scene_io.hpp"
#include "text/language.hpp"
#include "text/translate.hpp"

namespace collide::app {
namespace {

class PresetsCommand : public Command {
 public:
  explicit PresetsCommand(CLI::App& root)
      : app_(*root.add_subcommand("presets", "List the built-in scenes, or show one as a file")),
        show_(*app_.add_subcommand("show", "Print a preset as a TOML scene file")) {
    show_.add_option("NAME", show_name_, "Preset name")->required();
    addLanguageOption(app_, lang_);
    addLanguageOption(show_, show_lang_);
    show_.footer(
        "Examples:\n  collide presets show bouncing-ball > ball.toml   # then edit ball.toml\n"
        "  collide render ball.toml -o ball.mp4");
    app_.footer(
        "Examples:\n  collide presets\n  collide presets show pi-blocks\n"
        "  collide render pi-blocks --set digits=5 -o pi.mp4");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    // A preset shown in a language has its title and names in it, and says so (lang = "de").
    const std::string& tag = show_.parsed() && !show_lang_.empty() ? show_lang_ : lang_;
    const text::Language& language =
        tag.empty() ? text::shippedLanguages().front() : text::findLanguage(tag, "--lang");
    text::setActiveLanguage(language);
    if (show_.parsed()) {
      streams.out << scene::presetToml(show_name_, tag.empty() ? "" : language.tag);
      return 0;
    }
    // The summaries in one column, two spaces after the longest name.
    std::size_t column = 0;
    for (const scene::PresetInfo& preset : scene::presetList()) {
      column = std::max(column, preset.name.size() + 2);
    }
    for (const scene::PresetInfo& preset : scene::presetList()) {
      streams.out << std::left << std::setw(static_cast<int>(column)) << preset.name
                  << text::tr(preset.summary);
      for (const scene::PresetParameter& parameter : preset.parameters) {
        streams.out << " [--set " << parameter.name << "=" << parameter.min << ".." << parameter.max
                    << "]";
      }
      streams.out << "\n";
    }
    return 0;
  }

 private:
  CLI::App& app_;
  CLI::App& show_;
  std::string show_name_;
  std::string lang_, show_lang_;
};

}  // namespace

std::unique_ptr<Command> makePresetsCommand(CLI::App& root) {
  return std::make_unique<PresetsCommand>(root);
}

std::vector<std::unique_ptr<Command>> makeCommands(CLI::App& root) {
  std::vector<std::unique_ptr<Command>> commands;
  commands.push_back(makeRenderCommand(root));
  commands.push_back(makeStillCommand(root));
  commands.push_back(makeStrobeCommand(root));
  commands.push_back(makeChartCommand(root));
  commands.push_back(makeLessonCommand(root));
  commands.push_back(makeDataCommand(root));
  commands.push_back(makeLayoutCommand(root));
  commands.push_back(makeSolveCommand(root));
  commands.push_back(makePresetsCommand(root));
  commands.push_back(makeCheckCommand(root));
  commands.push_back(makeBatchCommand(root));
  commands.push_back(makeInfoCommand(root));
  commands.push_back(makeHelpManCommand(root));  // hidden
  return commands;
}

}  // namespace collide::app
