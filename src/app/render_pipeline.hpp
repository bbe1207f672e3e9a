#pragma once
// scene -> physics -> frames -> sink, one frame at a time so memory does not grow with length.
#include <string>

#include "app/output_target.hpp"
#include "app/render_settings.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {

struct VideoRequest {
  scene::SceneDesc scene;  // duration already overridden if the user asked
  FrameSize size;
  int fps = 60;
  OutputTarget target;
};

struct StillRequest {
  scene::SceneDesc scene;
  FrameSize size;
  double at_s = 0.0;  // simulated time of the still, within [0, duration]
  OutputTarget target;
};

// What was written, for the one-line report on stdout.
struct RenderSummary {
  int frames = 0;
  FrameSize size;
};

RenderSummary renderVideo(const VideoRequest& request);
RenderSummary renderStill(const StillRequest& request);

// Frames in a video of `duration_s` at `fps`: frame k shows t = k / fps, for k <
// round(fps·duration).
int frameCount(double duration_s, int fps);

}  // namespace collide::app
