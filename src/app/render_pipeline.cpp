#include "app/render_pipeline.hpp"

#include <cmath>

#include "app/frame_source.hpp"
#include "render/renderer.hpp"

namespace collide::app {

int frameCount(double duration_s, int fps) {
  return std::max(1, static_cast<int>(std::llround(duration_s * fps)));
}

RenderSummary renderVideo(const VideoRequest& request) {
  const FrameSource source(request.scene);
  const int frames = frameCount(source.duration_s(), request.fps);

  render::Renderer renderer(request.size.width_px, request.size.height_px);
  std::unique_ptr<output::FrameSink> sink = makeSink(request.target);
  sink->begin({request.size.width_px, request.size.height_px, request.fps});
  for (int k = 0; k < frames; ++k) {
    sink->write(renderer.render(source.frameAt(static_cast<double>(k) / request.fps)));
  }
  sink->finish();
  return {frames, request.size};
}

RenderSummary renderStill(const StillRequest& request) {
  const FrameSource source(request.scene);
  render::Renderer renderer(request.size.width_px, request.size.height_px);
  std::unique_ptr<output::FrameSink> sink = makeSink(request.target);
  sink->begin({request.size.width_px, request.size.height_px, 1});
  sink->write(renderer.render(source.frameAt(request.at_s)));
  sink->finish();
  return {1, request.size};
}

}  // namespace collide::app
