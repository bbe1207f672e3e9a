#include "app/render_pipeline.hpp"

#include <cmath>

#include "app/frame_builder.hpp"
#include "app/world_from_scene.hpp"
#include "physics/simulate.hpp"
#include "render/renderer.hpp"

namespace collide::app {

int frameCount(double duration_s, int fps) {
  return std::max(1, static_cast<int>(std::llround(duration_s * fps)));
}

RenderSummary renderVideo(const VideoRequest& request) {
  const physics::Timeline timeline = physics::simulate(worldFromScene(request.scene));
  const FramePlan plan = planFrames(request.scene, timeline);
  const int frames = frameCount(request.scene.duration_s, request.fps);

  render::Renderer renderer(request.size.width_px, request.size.height_px);
  std::unique_ptr<output::FrameSink> sink = makeSink(request.target);
  sink->begin({request.size.width_px, request.size.height_px, request.fps});
  for (int k = 0; k < frames; ++k) {
    const physics::Snapshot snapshot = timeline.sample(static_cast<double>(k) / request.fps);
    sink->write(renderer.render(buildFrame(request.scene, timeline, plan, snapshot)));
  }
  sink->finish();
  return {frames, request.size};
}

RenderSummary renderStill(const StillRequest& request) {
  const physics::Timeline timeline = physics::simulate(worldFromScene(request.scene));
  const FramePlan plan = planFrames(request.scene, timeline);
  render::Renderer renderer(request.size.width_px, request.size.height_px);
  std::unique_ptr<output::FrameSink> sink = makeSink(request.target);
  sink->begin({request.size.width_px, request.size.height_px, 1});
  sink->write(
      renderer.render(buildFrame(request.scene, timeline, plan, timeline.sample(request.at_s))));
  sink->finish();
  return {1, request.size};
}

}  // namespace collide::app
