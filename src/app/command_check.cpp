// collide check SCENE...: validates scene files and presets (with any overrides) without
// simulating or rendering, and lists every problem.
#include "app/command.hpp"
#include "app/scene_options.hpp"
#include "core/error.hpp"
#include "text/language.hpp"

namespace collide::app {
namespace {

class CheckCommand : public Command {
 public:
  explicit CheckCommand(CLI::App& root)
      : app_(*root.add_subcommand("check",
                                  "Validate scenes without rendering; list every problem")) {
    app_.add_option("SCENE", scenes_, "Preset names or scene files (.toml)")->required();
    // As the picture commands take them, so their command line checks the same scenes.
    duration_option_ = app_.add_option("--duration", duration_s_,
                                       "Simulated seconds, checked as the picture commands do");
    addLanguageOption(app_, lang_);
    changes_.addTo(app_);
    app_.footer(
        "Prints one line per valid scene on stdout and one line per problem on stderr, as\n"
        "FILE:LINE:COLUMN: KEY: VALUE: what is allowed. Exit 2 when any scene has a problem.\n"
        "Examples:\n  collide check lesson.toml\n  collide check course/*.toml\n"
        "  collide check worked-example --set restitution=1.2");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    if (!lang_.empty()) text::setActiveLanguage(text::findLanguage(lang_, "--lang"));
    if (duration_option_->count() > 0) checkDuration(duration_s_, "--duration");
    const std::vector<scene::Override> overrides = changes_.overrides();
    int bad = 0;
    for (const std::string& name : scenes_) {
      try {
        scene::SceneDesc scene = scene::loadScene(name, overrides);
        if (duration_option_->count() > 0) scene.duration_s = duration_s_;
        streams.out << "ok: " << name << ": '" << scene.title << "', " << scene.dimensions << "D, "
                    << scene.bodies.size() << " bod" << (scene.bodies.size() == 1 ? "y" : "ies")
                    << ", " << scene::allWalls(scene).size() << " wall"
                    << (scene::allWalls(scene).size() == 1 ? "" : "s") << ", " << scene.duration_s
                    << " s\n";
      } catch (const scene::SceneError& e) {
        ++bad;
        for (const std::string& problem : e.problems()) streams.err << problem << "\n";
      }
    }
    if (bad == 0) return 0;
    if (scenes_.size() > 1) {
      streams.err << bad << " of " << scenes_.size() << " scenes have problems\n";
    }
    return static_cast<int>(core::ExitCode::kBadInput);
  }

 private:
  CLI::App& app_;
  std::vector<std::string> scenes_;
  double duration_s_ = 0.0;
  CLI::Option* duration_option_ = nullptr;
  std::string lang_;
  OverrideOptions changes_;
};

}  // namespace

std::unique_ptr<Command> makeCheckCommand(CLI::App& root) {
  return std::make_unique<CheckCommand>(root);
}

}  // namespace collide::app
