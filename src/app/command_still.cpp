// collide still SCENE --at T -o OUT.png: one instant as an image.
#include <cmath>
#include <cstdio>
#include <iomanip>

#include "app/command.hpp"
#include "app/output_options.hpp"
#include "app/picture_options.hpp"
#include "app/print_options.hpp"
#include "app/render_pipeline.hpp"
#include "core/error.hpp"
#include "core/typed_text.hpp"
#include "output/process_end.hpp"

namespace collide::app {
namespace {

class StillCommand : public Command {
 public:
  explicit StillCommand(CLI::App& root)
      : app_(*root.add_subcommand(
            "still", "Render one instant of a scene to an image: PNG, or SVG/PDF for print")) {
    options_.addTo(app_, kFigureOutputHelp, [this](CLI::App& command) {
      at_option_ = command.add_option(
          "--at", at_s_,
          "Simulated time of the image, in seconds (default: mid-scene, half the "
          "duration)");
    });
    out_.addTo(app_);
    print_.addTo(app_);
    bundle_.addTo(app_);
    app_.footer(
        "Examples:\n  collide still worked-example --at 2.5 -o after.png\n"
        "  collide still worked-example --at 2.5 -o after.pdf --print 8cm --latex");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    StillRequest request{options_.loadScene(),
                         options_.size.parse(),
                         at_s_,
                         output::stillTarget(options_.output),
                         {},
                         {},
                         {}};
    // Without --at, the middle of the scene (as batch's png): after the first impact in most
    // lessons, with motion before and after it.
    if (at_option_->count() == 0) at_s_ = request.at_s = 0.5 * request.scene.duration_s;
    if (!std::isfinite(at_s_) || at_s_ < 0.0 || at_s_ > request.scene.duration_s) {
      // The value as typed: 4.0000001 printed as %g would read 4, inside the range it broke.
      char duration[40];
      std::snprintf(duration, sizeof duration, "%g", request.scene.duration_s);
      throw core::InputError("--at: " + core::echoTyped(at_option_->results().back()) +
                             ": allowed: a time from 0 to " + duration + " s (the duration)");
    }
    request.options = out_;
    request.print = print_.resolve(request.size, app_);
    request.bundle = bundle_;
    output::declareOnePictureProcess();  // no teardown after it (output/process_end.hpp)
    const RenderSummary summary = renderStill(request);
    reportStream(request.target, streams)
        << "wrote " << shownPath(request.target) << " (t = " << std::fixed << std::setprecision(3)
        << at_s_ << " s)\n";
    reportSideFilesAndWarnings(summary.side_files, summary.warnings, streams);
    return 0;
  }

 private:
  CLI::App& app_;
  PictureOptions options_;
  double at_s_ = 0.0;
  CLI::Option* at_option_ = nullptr;
  StillOutputOptions out_;
  PrintOptions print_;
  BundleOptions bundle_;
};

}  // namespace

std::unique_ptr<Command> makeStillCommand(CLI::App& root) {
  return std::make_unique<StillCommand>(root);
}

}  // namespace collide::app
