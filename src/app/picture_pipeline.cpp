#include "app/picture_pipeline.hpp"

#include <cmath>

#include "app/animation.hpp"
#include "app/signals.hpp"
#include "render/renderer.hpp"

namespace collide::app {
namespace {

void writePng(const PictureRequest& request, const render::FrameModel& frame,
              const std::string& description) {
  render::Renderer renderer(request.size.width_px, request.size.height_px);
  SinkSettings settings;
  settings.png_text = {
      {"Title", request.scene.title.empty() ? request.scene.name : request.scene.title},
      {"Software", "collide"},
      {"Description", description}};
  std::unique_ptr<output::FrameSink> sink = makeSink(request.target, std::move(settings));
  sink->begin({request.size.width_px, request.size.height_px, 1});
  sink->write(renderer.render(frame));
  // Drawing and encoding a large picture take a while: a signal meanwhile keeps the earlier file.
  StopSignals::throwIfReceived(kindName(request.target.kind) + " '" + request.target.path + "'");
  sink->finish();
}

// The scene simulated; a stop signal meanwhile ends the run with nothing written.
Animation simulated(const PictureRequest& request) {
  return beforeWriting("'" + request.target.path + "'", [&] {
    return animate(request.scene, {request.size.width_px, request.size.height_px});
  });
}

}  // namespace

// Both hold StopSignals for their whole run: Ctrl-C or SIGTERM stop cleanly in the simulation or
// before the PNG is renamed into place.
PictureSummary renderStrobe(const PictureRequest& request, double rate_hz) {
  const StopSignals signals;
  const Animation animation = simulated(request);
  const render::FrameModel frame = animation.frames.strobeFrame(rate_hz);
  const int images =
      static_cast<int>(frame.panels.empty() || request.scene.bodies.empty()
                           ? 0
                           : frame.panels.front().ghosts.size() / request.scene.bodies.size()) +
      1;
  writePng(request, frame,
           "Stroboscopic image of " + request.scene.name + ": " + std::to_string(images) +
               " images at " + std::to_string(rate_hz) + " per second");
  return {images, animation.warnings};
}

PictureSummary renderChart(const PictureRequest& request) {
  const StopSignals signals;
  const Animation animation = simulated(request);
  writePng(
      request, animation.frames.chartFrame(),
      "Chart of " + request.scene.view.chart_quantity + " against time for " + request.scene.name);
  return {1, animation.warnings};
}

}  // namespace collide::app
