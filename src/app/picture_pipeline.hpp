#pragma once
// Single-image products other than a still: the stroboscope photograph and the chart alone.
#include <optional>
#include <string>
#include <vector>

#include "app/bundle_options.hpp"
#include "app/print_options.hpp"
#include "app/render_settings.hpp"
#include "output/output_target.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {

struct PictureRequest {
  scene::SceneDesc scene;
  FrameSize size;
  output::OutputTarget target;            // PNG, SVG or PDF
  std::optional<frame::PrintSize> print;  // physical size for print; none: screen size
  BundleOptions bundle;                   // LaTeX / Markdown beside the picture
};

// What was drawn, for the report.
struct PictureSummary {
  int images = 0;                       // strobe: images of each body; chart: 1
  double rate_hz = 0.0;                 // strobe: images per second
  std::vector<std::string> side_files;  // --latex, --markdown
  std::vector<std::string> warnings;    // the physics warnings (Animation::warnings)
  std::string description;              // what the picture shows (its alt text)
};

// The bodies at t = k / rate_hz for the whole scene in one picture (rate_hz checked by the
// caller; 0: chosen so images do not overlap).
PictureSummary renderStrobe(const PictureRequest& request, double rate_hz);

// The scene's chart (ViewDesc::chart_quantity) as a picture.
PictureSummary renderChart(const PictureRequest& request);

}  // namespace collide::app
