// collide still SCENE --at T -o OUT.png: one instant as an image.
#include <cmath>
#include <cstdio>
#include <iomanip>

#include "app/command.hpp"
#include "app/output_options.hpp"
#include "app/picture_options.hpp"
#include "app/render_pipeline.hpp"
#include "core/error.hpp"

namespace collide::app {
namespace {

class StillCommand : public Command {
 public:
  explicit StillCommand(CLI::App& root)
      : app_(*root.add_subcommand("still", "Render one instant of a scene to a PNG image")) {
    options_.addTo(app_, "Output path, *.png");
    app_.add_option("--at", at_s_, "Simulated time of the image, in seconds")->required();
    out_.addTo(app_);
    app_.footer("Example:\n  collide still worked-example --at 2.5 -o after.png");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    StillRequest request{
        options_.loadScene(), options_.size.parse(), at_s_, stillTarget(options_.output), {}};
    if (!std::isfinite(at_s_) || at_s_ < 0.0 || at_s_ > request.scene.duration_s) {
      char text[160];
      std::snprintf(text, sizeof text, "--at: %g: allowed: a time from 0 to %g s (the duration)",
                    at_s_, request.scene.duration_s);
      throw core::InputError(text);
    }
    request.options = out_;
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
  StillOutputOptions out_;
};

}  // namespace

std::unique_ptr<Command> makeStillCommand(CLI::App& root) {
  return std::make_unique<StillCommand>(root);
}

}  // namespace collide::app
