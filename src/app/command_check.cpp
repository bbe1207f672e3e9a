// collide check SCENE...: validates scene files and presets (with any overrides) without
// simulating or rendering, and lists their problems (a screenful of each kind, and a count).
#include <algorithm>
#include <map>
#include <ostream>

#include "app/command.hpp"
#include "app/scene_options.hpp"
#include "core/error.hpp"
#include "core/typed_text.hpp"
#include "text/language.hpp"

namespace collide::app {
namespace {

// Characters of a name, a title or a problem shown: a line of a terminal's scrollback at most.
constexpr std::size_t kMaxShown = 1000;

// A file with 200,000 unknown tables has as many problems: a screenful of each kind is listed,
// the rest counted.
constexpr std::size_t kListedOfOneKind = 10;

// The problems of one scene, in their order, at most kListedOfOneKind of each kind, then how
// many more of each kind there are.
void listProblems(const std::string& scene, const scene::SceneError& error, std::ostream& err) {
  const std::vector<std::string> problems = error.problems(), kinds = error.kinds();
  std::map<std::string, std::size_t> seen;
  std::vector<std::string> order;  // the kinds, in the order they first come
  for (std::size_t k = 0; k < problems.size(); ++k) {
    const std::size_t count = ++seen[kinds[k]];
    if (count == 1) order.push_back(kinds[k]);
    if (count <= kListedOfOneKind) err << core::echoTyped(problems[k], kMaxShown) << "\n";
  }
  for (const std::string& kind : order) {
    const std::size_t more = seen[kind] - std::min(seen[kind], kListedOfOneKind);
    if (more == 0) continue;
    err << core::echoTyped(scene, kMaxShown) << ": " << more << " more problem"
        << (more == 1 ? "" : "s")
        << " of this kind, not listed: " << core::echoTyped(kind, kMaxShown) << "\n";
  }
}

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
        "FILE:LINE:COLUMN: KEY: VALUE: what is allowed; ten of each kind, then how many more.\n"
        "Exit 2 when any scene has a problem.\n"
        "Examples:\n  collide check lesson.toml\n  collide check course/*.toml\n"
        "  collide check worked-example --set restitution=1.2");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    if (!lang_.empty()) text::setActiveLanguage(text::findLanguage(lang_, "--lang"));
    if (duration_option_->count() > 0) {
      checkDuration(duration_s_, "--duration", duration_option_->results().back());
    }
    const std::vector<scene::Override> overrides = changes_.overrides();
    int bad = 0;
    for (const std::string& name : scenes_) {
      try {
        std::vector<std::string> notes;
        scene::SceneDesc scene = scene::loadScene(name, overrides, &notes);
        if (duration_option_->count() > 0) scene.duration_s = duration_s_;
        // Escaped: a name or a title must not act on the terminal (ESC, BEL).
        streams.out << "ok: " << core::echoTyped(name, kMaxShown) << ": '"
                    << core::echoTyped(scene.title, kMaxShown) << "', " << scene.dimensions << "D, "
                    << scene.bodies.size() << " bod" << (scene.bodies.size() == 1 ? "y" : "ies")
                    << ", " << scene::allWalls(scene).size() << " wall"
                    << (scene::allWalls(scene).size() == 1 ? "" : "s") << ", " << scene.duration_s
                    << " s\n";
        // How keys other than position and velocity set where and how fast bodies start.
        for (const std::string& note : notes) streams.out << "  " << note << "\n";
      } catch (const scene::SceneError& e) {
        ++bad;
        listProblems(name, e, streams.err);
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
