#include "app/picture_pipeline.hpp"

#include <cmath>

#include "app/frame_source.hpp"
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
  sink->finish();
}

}  // namespace

PictureSummary renderStrobe(const PictureRequest& request, double rate_hz) {
  const FrameSource source(request.scene);
  const render::FrameModel frame = source.strobeFrame(rate_hz);
  const int images =
      static_cast<int>(frame.panels.empty() || request.scene.bodies.empty()
                           ? 0
                           : frame.panels.front().ghosts.size() / request.scene.bodies.size()) +
      1;
  writePng(request, frame,
           "Stroboscopic image of " + request.scene.name + ": " + std::to_string(images) +
               " images at " + std::to_string(rate_hz) + " per second");
  return {images, source.warnings()};
}

PictureSummary renderChart(const PictureRequest& request) {
  const FrameSource source(request.scene);
  writePng(
      request, source.chartFrame(),
      "Chart of " + request.scene.view.chart_quantity + " against time for " + request.scene.name);
  return {1, source.warnings()};
}

}  // namespace collide::app
