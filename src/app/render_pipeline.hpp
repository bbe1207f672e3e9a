#pragma once
// scene -> physics -> frames -> sink. A video's frames are composed on one worker thread
// (app/frames_ahead.hpp), drawn on the calling (GL) thread and encoded on another worker thread,
// so the three overlap; memory does not grow with the video's length. SIGINT and
// SIGTERM stop the run between frames and leave nothing at the target.
#include <atomic>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "app/bundle_options.hpp"
#include "app/output_options.hpp"
#include "app/print_options.hpp"
#include "app/render_settings.hpp"
#include "core/progress.hpp"
#include "output/output_target.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {

// The frames of a video drawn so far, of the frames in all (0 until the first is drawn).
struct FrameCount {
  std::atomic<int> drawn{0};
  std::atomic<int> total{0};
};

struct VideoRequest {
  scene::SceneDesc scene;  // duration already overridden if the user asked
  FrameSize size;
  int fps = 60;
  output::OutputTarget target;
  VideoOutputOptions options;  // checked against target.kind
  core::ProgressStyle progress = core::ProgressStyle::kSilent;
  std::ostream* progress_stream = nullptr;  // needed unless kSilent
  int encoder_threads = 0;  // MP4: x264 threads; 0: 1.5 per core (batch_threads.hpp)
  // Compose, draw, convert and encode every frame in turn on the calling thread, with no thread of
  // its own (a batch worker whose share is one core); otherwise they overlap on three threads.
  bool one_thread = false;
  // For a host that shows progress itself (the Python module's notebook bar). Not owned; may be
  // null.
  FrameCount* frame_count = nullptr;
};

struct StillRequest {
  scene::SceneDesc scene;
  FrameSize size;
  double at_s = 0.0;            // simulated time of the still, within [0, duration]
  output::OutputTarget target;  // PNG, SVG or PDF
  StillOutputOptions options;
  std::optional<frame::PrintSize> print;  // physical size for print; none: screen size
  BundleOptions bundle;                   // LaTeX / Markdown beside the picture
};

// What was written, for the report on stdout.
struct RenderSummary {
  int frames = 0;
  FrameSize size;
  std::vector<std::string> side_files;  // captions, alt text: written beside the main output
  std::vector<std::string> warnings;    // the physics warnings (Animation::warnings)
};

// Throws core::Error subclasses: InputError for option combinations, OutputError and RenderError
// for failures, InterruptedError (exit 128 + signal) when SIGINT or SIGTERM stopped the run.
RenderSummary renderVideo(const VideoRequest& request);
RenderSummary renderStill(const StillRequest& request);

// Frames in a video of `duration_s` at `fps`: frame k shows t = k / fps, for k <
// round(fps·duration).
int frameCount(double duration_s, int fps);

}  // namespace collide::app
