// collide render SCENE -o OUT: a video (MP4) or a directory of PNG frames.
#include <iomanip>

#include "app/command.hpp"
#include "app/output_options.hpp"
#include "app/picture_options.hpp"
#include "app/render_pipeline.hpp"
#include "core/error.hpp"
#include "core/typed_text.hpp"

namespace collide::app {
namespace {

// H.264 needs even dimensions: round an odd width or height down, and say so.
FrameSize evenForVideo(FrameSize size, std::ostream& err) {
  const FrameSize even{size.width_px & ~1, size.height_px & ~1};
  if (even.width_px != size.width_px || even.height_px != size.height_px) {
    err << "note: --size " << size.width_px << "x" << size.height_px << " rounded to "
        << even.width_px << "x" << even.height_px << " (H.264 needs even dimensions)\n";
  }
  return even;
}

class RenderCommand : public Command {
 public:
  explicit RenderCommand(CLI::App& root)
      : app_(*root.add_subcommand("render", "Render a scene to an MP4 video or PNG frames")) {
    options_.addTo(app_,
                   "Output path: *.mp4, *.webm, *.gif, a directory for PNG frames, a device or "
                   "FIFO (MP4), or - for stdout (with --format)",
                   [this](CLI::App& command) {
                     command
                         .add_option("--fps", fps_,
                                     "Frames per second, 1 to 240; for GIF 1 to 50 and by default "
                                     "25 (its delays are whole hundredths of a second, and "
                                     "players slow shorter ones)")
                         ->capture_default_str();
                   });
    out_.addTo(app_);
    app_.footer(
        "OUT ending in .mp4 writes an H.264 video; an existing directory or a path ending in '/' "
        "receives frame_00000.png, ...\nExamples:\n"
        "  collide render worked-example -o lesson.mp4 --size 1920x1080 --fps 30\n"
        "  collide render worked-example -o frames/ --duration 2");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    checkFps(fps_);
    VideoRequest request{options_.loadScene(),
                         options_.size.parse(),
                         fps_,
                         output::videoTarget(options_.output, out_.format),
                         {}};
    applyOutputDefaults(app_, out_, streams.err, request);
    fps_ = request.fps;
    if (request.target.kind == output::OutputKind::kGif && fps_ > kMaxGifFps) {
      throw core::InputError(
          "--fps: " + core::echoTyped(app_.get_option("--fps")->results().back()) +
          ": GIF frame delays are whole hundredths of a second and players "
          "show delays under 2/100 s slower; allowed for GIF: 1 to " +
          std::to_string(kMaxGifFps) + " frames per second");
    }
    if (request.target.kind == output::OutputKind::kMp4 ||
        request.target.kind == output::OutputKind::kWebm) {
      request.size = evenForVideo(request.size, streams.err);
    }
    const RenderSummary summary = renderVideo(request);
    reportStream(request.target, streams)
        << "wrote " << shownPath(request.target) << " (" << summary.frames << " frames, "
        << summary.size.width_px << "x" << summary.size.height_px << ", " << fps_ << " fps, "
        << std::fixed << std::setprecision(3) << static_cast<double>(summary.frames) / fps_
        << " s)\n";
    reportSideFilesAndWarnings(summary.side_files, summary.warnings, streams);
    return 0;
  }

 private:
  CLI::App& app_;
  PictureOptions options_;
  int fps_ = 60;
  VideoOutputOptions out_;
};

}  // namespace

std::unique_ptr<Command> makeRenderCommand(CLI::App& root) {
  return std::make_unique<RenderCommand>(root);
}

}  // namespace collide::app
