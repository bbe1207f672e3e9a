#include "app/picture_pipeline.hpp"

#include <cmath>
#include <cstdio>

#include "app/animation.hpp"
#include "app/figure_writer.hpp"
#include "app/output_checks.hpp"
#include "app/working_texts.hpp"
#include "output/stop_signals.hpp"
#include "render/renderer.hpp"
#include "text/number_format.hpp"
#include "text/translate.hpp"
#include "text/wording.hpp"

namespace collide::app {
namespace {

// Writes the picture and the bundle asked for, the working with it where the scene shows it (as a
// still's, app/working_texts.hpp); returns the bundle's files.
std::vector<std::string> writePicture(const PictureRequest& request, const frame::FrameModel& frame,
                                      const std::string& description,
                                      const WorkingTexts& working = {}) {
  const std::string alt_text = withSentence(description, working.spoken_steps);
  FigureSettings figure;
  figure.size = request.size;
  figure.print = request.print;
  figure.title = request.scene.title.empty() ? request.scene.name : request.scene.title;
  figure.description = alt_text;
  figure.png_text = {{"Title", figure.title}, {"Software", "collide"}, {"Description", alt_text}};
  writeFigure(request.target, frame, figure);
  if (request.target.streamed) return {};  // nothing to put a bundle beside
  return request.bundle.write(pictureBundle(
      request.target.path, description + ".", alt_text,
      request.print ? std::optional<double>(request.print->width_cm) : std::nullopt, working));
}

// The scene simulated, its labels placed for the picture's size and text (the print size's
// pixels and text floor, else --size); a stop signal meanwhile ends the run with nothing written.
Animation simulated(const PictureRequest& request) {
  FigureSettings figure;
  figure.size = request.size;
  figure.print = request.print;
  return output::beforeWriting("'" + request.target.path + "'", [&] {
    return animate(request.scene, figurePictureSize(figure, request.target.kind));
  });
}

}  // namespace

// Both hold StopSignals for their whole run: Ctrl-C or SIGTERM stop cleanly in the simulation or
// before the PNG is renamed into place.
PictureSummary renderStrobe(const PictureRequest& request, double rate_hz) {
  const output::OutputPlan outputs(pictureOutputs(request));
  const output::StopSignals signals;
  const Animation animation = simulated(request);
  // A rate the user gave draws every flash; the picture's own keeps a body's images apart.
  const bool keep_apart = !(rate_hz > 0.0);
  if (keep_apart) rate_hz = animation.frames.strobeRate_hz();
  const frame::FrameModel frame = animation.frames.strobeFrame(rate_hz, keep_apart);
  const int images = animation.frames.strobeImages(rate_hz, keep_apart);
  const std::string description =
      text::fill(text::trn("Stroboscopic image of {scene}: {count} image at {rate} per second",
                           "Stroboscopic image of {scene}: {count} images at {rate} per second",
                           static_cast<unsigned long>(images)),
                 {{"scene", request.scene.name},
                  {"count", text::formatScaled(images, 0)},
                  {"rate", text::formatPlain(rate_hz, text::defaultStyle(), 6)}});
  const std::vector<std::string> side_files = writePicture(
      request, frame, description, workingTexts(request.scene, animation.frames.timeline()));
  return {images, rate_hz, side_files, animation.warnings, description};
}

// The description of a chart picture of `quantity` (energy, momentum or force).
static std::string chartQuantity(const std::string& quantity) {
  if (quantity == "speed") {
    return text::tr(
        "Histogram of the disks' speeds at the end of {scene}, with the "
        "Maxwell-Boltzmann distribution for the same energy");
  }
  if (quantity == "momentum") return text::tr("Chart of momentum against time for {scene}");
  if (quantity == "force") return text::tr("Chart of contact force against time for {scene}");
  return text::tr("Chart of energy against time for {scene}");
}

PictureSummary renderChart(const PictureRequest& request) {
  const output::OutputPlan outputs(pictureOutputs(request));
  const output::StopSignals signals;
  const Animation animation = simulated(request);
  const std::string description =
      text::fill(chartQuantity(request.scene.view.chart_quantity), {{"scene", request.scene.name}});
  const std::vector<std::string> side_files =
      writePicture(request, animation.frames.chartFrame(), description);
  return {1, 0.0, side_files, animation.warnings, description};
}

}  // namespace collide::app
