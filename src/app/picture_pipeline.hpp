#pragma once
// Single-image products other than a still: the stroboscope photograph and the chart alone.
#include <string>
#include <vector>

#include "app/output_target.hpp"
#include "app/render_settings.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {

struct PictureRequest {
  scene::SceneDesc scene;
  FrameSize size;
  OutputTarget target;  // a PNG still
};

// What was drawn, for the report.
struct PictureSummary {
  int images = 0;                     // strobe: images of each body; chart: 1
  std::vector<std::string> warnings;  // the physics warnings (Animation::warnings)
};

// The bodies at t = k / rate_hz for the whole scene in one PNG (rate_hz > 0, checked by the
// caller).
PictureSummary renderStrobe(const PictureRequest& request, double rate_hz);

// The scene's chart (ViewDesc::chart_quantity) as a PNG.
PictureSummary renderChart(const PictureRequest& request);

}  // namespace collide::app
