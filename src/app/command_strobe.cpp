// collide strobe SCENE -o OUT.png [--rate HZ]: a stroboscope photograph of the whole scene.
#include <cmath>
#include <cstdio>

#include "app/command.hpp"
#include "app/picture_options.hpp"
#include "app/picture_pipeline.hpp"
#include "app/print_options.hpp"
#include "core/error.hpp"
#include "core/typed_text.hpp"
#include "output/process_end.hpp"

namespace collide::app {
namespace {

std::string plainValue(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// The scene says its strobe cannot teach it (view.best_still): drawn as asked, with the still
// that shows it instead, as batch and lessons draw it.
std::string cloudOfImages(const scene::SceneDesc& scene) {
  const std::string at = plainValue(*scene.view.best_still_s);
  return scene.name + ": its strobe is a cloud of images that teaches little (view.best_still); " +
         "its still at " + at + " s shows it: collide still " + scene.name + " --at " + at;
}

class StrobeCommand : public Command {
 public:
  explicit StrobeCommand(CLI::App& root)
      : app_(*root.add_subcommand(
            "strobe", "One image with the bodies drawn at regular times, earlier ones fainter")) {
    options_.addTo(app_, kFigureOutputHelp, [this](CLI::App& command) {
      rate_option_ = command.add_option("--rate", rate_hz_,
                                        "Images per second, 0.1 to 1000, every one drawn "
                                        "(default: the scene's, else a round rate at which "
                                        "no image overlaps the next; images of a body that "
                                        "would overlap its others are left out)");
    });
    print_.addTo(app_);
    bundle_.addTo(app_);
    app_.footer(
        "Like a stroboscope photograph: the bouncing ball bounces lower each time.\nExamples:\n"
        "  collide strobe bouncing-ball -o bounce.png\n"
        "  collide strobe worked-example -o strobe.png --rate 5 --size 1920x1080");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    PictureRequest request = pictureRequest(options_, print_, bundle_, app_);
    const double rate = rate_option_->count() > 0 ? rate_hz_ : request.scene.view.strobe_rate_hz;
    const bool chosen = rate_option_->count() == 0 && rate == 0.0;  // by the picture
    if (!chosen && (!std::isfinite(rate) || rate < 0.1 || rate > 1000.0 ||
                    rate * request.scene.duration_s > 2000.0)) {
      // Named as the user gave it: --rate as typed, or the scene's key.
      const std::string given = rate_option_->count() > 0
                                    ? "--rate: " + core::echoTyped(rate_option_->results().back())
                                    : "view.strobe_rate: " + plainValue(rate);
      char text[200];
      std::snprintf(text, sizeof text,
                    ": allowed: 0.1 to 1000 images per second, at most 2000 images over the %g s "
                    "scene",
                    request.scene.duration_s);
      throw core::InputError(given + text);
    }
    output::declareOnePictureProcess();  // no teardown after it (output/process_end.hpp)
    PictureSummary summary = renderStrobe(request, rate);
    reportStream(request.target, streams)
        << "wrote " << shownPath(request.target) << " (" << summary.images
        << (summary.images == 1 ? " image, " : " images, ") << summary.rate_hz << " per second)\n";
    if (request.scene.view.best_still_s) summary.warnings.push_back(cloudOfImages(request.scene));
    reportSideFilesAndWarnings(summary.side_files, summary.warnings, streams);
    return 0;
  }

 private:
  CLI::App& app_;
  PictureOptions options_;
  PrintOptions print_;
  BundleOptions bundle_;
  double rate_hz_ = 25.0;
  CLI::Option* rate_option_ = nullptr;
};

}  // namespace

std::unique_ptr<Command> makeStrobeCommand(CLI::App& root) {
  return std::make_unique<StrobeCommand>(root);
}

}  // namespace collide::app
