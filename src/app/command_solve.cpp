// SPDX-License-Identifier: MIT
// collide solve SCENE [--impact K] [--format text|latex|markdown|mathml]: the working of one
// impact (or release of stored energy), the laws with the scene's numbers, printed (src/working).
#include <charconv>

#include "app/command.hpp"
#include "app/scene_options.hpp"
#include "app/simulation_progress.hpp"
#include "app/world_from_scene.hpp"
#include "core/error.hpp"
#include "core/typed_text.hpp"
#include "report/physics_warnings.hpp"
#include "working/working.hpp"
#include "working/writers.hpp"

namespace collide::app {
namespace {

working::Format parseFormat(const std::string& typed) {
  if (typed == "text") return working::Format::kText;
  if (typed == "latex") return working::Format::kLatex;
  if (typed == "markdown") return working::Format::kMarkdown;
  if (typed == "mathml") return working::Format::kMathml;
  throw core::InputError("--format: '" + core::echoTyped(typed) +
                         "': unknown format; allowed: text, latex, markdown, mathml");
}

// K of --impact, 1-based, checked against the impacts the run has.
std::size_t parseImpact(const std::string& typed, std::size_t count, const std::string& scene) {
  std::size_t k = 0;
  const char* end = typed.data() + typed.size();
  const auto [rest, error] = std::from_chars(typed.data(), end, k);
  const std::string allowed = count == 1 ? "1" : "1 to " + std::to_string(count);
  if (error != std::errc() || rest != end || k < 1 || k > count) {
    throw core::InputError("--impact: '" + core::echoTyped(typed) + "': no such impact in '" +
                           core::echoTyped(scene) + "'; allowed: " + allowed);
  }
  return k - 1;
}

class SolveCommand : public Command {
 public:
  explicit SolveCommand(CLI::App& root)
      : app_(*root.add_subcommand("solve",
                                  "Print the working of an impact: the laws, the "
                                  "scene's numbers substituted, the result")) {
    scene_.addSceneArgument(app_);
    app_.add_option(
        "--impact", impact_,
        "Which impact (or release of stored energy), 1 for the first event (default 1)");
    app_.add_option("--format", format_,
                    "text (Unicode, the default), latex (amsmath align*), markdown ($…$ math) or "
                    "mathml");
    scene_.addChanges(app_);
    app_.footer(
        "Examples:\n  collide solve worked-example\n"
        "  collide solve billiards-break --impact 2 --format latex > break.tex");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    const working::Format format = parseFormat(format_);
    const scene::SceneDesc scene = scene_.load();
    const physics::Timeline timeline = simulateReporting(worldFromScene(scene));
    report::printWarnings(report::physicsWarnings(timeline), streams.err);
    const std::size_t count = working::impactCount(timeline);
    if (count == 0) {
      throw core::InputError("solve: '" + core::echoTyped(scene_.scene) +
                             "': no impact in its simulated time; allowed: a scene whose bodies "
                             "collide (a longer --duration?)");
    }
    const std::size_t impact = parseImpact(impact_, count, scene_.scene);
    streams.out << working::writeWorking(working::workingFor(timeline, impact), format);
    return 0;
  }

 private:
  CLI::App& app_;
  SceneOptions scene_;
  std::string impact_ = "1";
  std::string format_ = "text";
};

}  // namespace

std::unique_ptr<Command> makeSolveCommand(CLI::App& root) {
  return std::make_unique<SolveCommand>(root);
}

}  // namespace collide::app
