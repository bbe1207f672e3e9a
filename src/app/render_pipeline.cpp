#include "app/render_pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <optional>

#include "app/animation.hpp"
#include "app/figure_writer.hpp"
#include "app/frames_ahead.hpp"
#include "app/output_checks.hpp"
#include "app/version.hpp"
#include "app/working_texts.hpp"
#include "output/encode_thread.hpp"
#include "output/stop_signals.hpp"
#include "output/text_output.hpp"
#include "render/renderer.hpp"
#include "report/alt_text.hpp"
#include "report/captions.hpp"
#include "report/click_track.hpp"
#include "report/narration.hpp"
#include "text/language.hpp"
#include "text/number_format.hpp"
#include "text/translate.hpp"
#include "text/wording.hpp"

namespace collide::app {
namespace {

// Frames that may wait between the renderer and the encoder. For a sink that takes RGBA, one is
// enough to overlap them: the renderer draws frame k + 1 into its own readback buffer while frame
// k is written, and copies it in when the writer is done; each further one costs a frame of memory
// (8 MiB at 1080p). The MP4 and WebM sinks stage frames as Y'CbCr 4:2:0 instead (3 MiB at 1080p),
// converted on a thread of their own while the next frame is drawn: two of them let drawing run
// ahead while x264 is slow on a frame. A third ran no faster once x264 had 1.5 frame threads per
// core (mp4_sink.cpp), whose frames its memory now pays for (bench/results.md).
constexpr int kEncodeBuffers = 1;
constexpr int kStagedEncodeBuffers = 2;

std::string titleOf(const scene::SceneDesc& scene) {
  return scene.title.empty() ? scene.name : scene.title;
}

std::string madeWith(const scene::SceneDesc& scene) {
  return std::string("Made with collide ") + kVersion + " from scene '" + scene.name + "'";
}

// The playback time at which a video shows simulated time t (simulatedAt increases).
double playbackAt(const compose::FrameSource& source, double t_s) {
  double low = 0.0, high = source.duration_s();
  for (int k = 0; k < 64; ++k) {
    const double mid = 0.5 * (low + high);
    (source.simulatedAt(mid) < t_s ? low : high) = mid;
  }
  return high;
}

// Tags for MP4/WebM: what the video shows and how it was made.
output::MediaExtras videoExtras(const VideoRequest& request, const compose::FrameSource& source,
                                int frames, const std::vector<report::Cue>& cues) {
  const physics::Timeline& timeline = source.timeline();
  output::MediaExtras extras;
  const double length_s = static_cast<double>(frames) / request.fps;
  extras.metadata["title"] = titleOf(request.scene);
  extras.metadata["comment"] = madeWith(request.scene);
  extras.metadata["description"] =
      report::describeParameters(timeline) + "; " + std::to_string(request.size.width_px) + "x" +
      std::to_string(request.size.height_px) + " at " + std::to_string(request.fps) + " fps";
  if (request.options.sound) {
    // Each knock where the video shows its collision (later, with slow motion).
    const bool slowed = source.duration_s() != source.simulatedDuration_s();
    report::ClickTrack clicks =
        report::synthesizeClicks(timeline, length_s, 48000,
                                 slowed ? [&](double t_s) { return playbackAt(source, t_s); }
                                        : std::function<double(double)>{});
    extras.audio = output::AudioTrack{clicks.sample_rate_hz, std::move(clicks.samples)};
  }
  const text::Iso639 language = text::iso639(text::activeLanguage().tag);
  extras.language_terminology = language.terminology;
  extras.language_bibliographic = language.bibliographic;
  // TRANSLATORS: the name of the subtitle track that narrates the video (players list it).
  extras.subtitle_title = text::tr("Narration");
  if (request.options.embed_captions) {
    for (const report::Cue& cue : cues)
      extras.subtitles.push_back({cue.start_s, cue.end_s, cue.text});
  }
  return extras;
}

// A frame is drawn: the progress line and the host's count (VideoRequest::frame_count).
void countFrame(core::Progress& progress, const VideoRequest& request, int drawn, int total) {
  progress.update(drawn);
  if (request.frame_count == nullptr) return;
  request.frame_count->total.store(total);
  request.frame_count->drawn.store(drawn);
}

}  // namespace

int frameCount(double duration_s, int fps) {
  return std::max(1, static_cast<int>(std::llround(duration_s * fps)));
}

constexpr double kShortestSlowCue_s = 1.0;  // a caption shown for less cannot be read

// The narration is told in simulated time (a caption says "t = 0.250 s" and ends at the scene's
// end); with slow motion around the collisions a video shows each instant later, where its cue
// then belongs.
std::vector<report::Cue> narrationCues(const compose::FrameSource& source, const std::string& title,
                                       double length_s, int fps) {
  if (source.duration_s() == source.simulatedDuration_s()) {
    return report::narrate(source.timeline(), {title, length_s});
  }
  // The last frame ends the scene (length_s is the playback duration rounded to frames).
  const double end_s = std::abs(length_s - source.duration_s()) <= 0.5 / fps
                           ? source.simulatedDuration_s()
                           : source.simulatedAt(length_s);
  std::vector<report::Cue> cues;
  for (report::Cue cue : report::narrate(source.timeline(), {title, end_s})) {
    cue.start_s = playbackAt(source, cue.start_s);
    cue.end_s = playbackAt(source, cue.end_s);
    // Events a few milliseconds apart (a shot and the bullet's impact, the start and a bullet's
    // hit) stay too briefly to read even slowed: such a cue and the next are shown as one.
    if (!cues.empty() && cues.back().end_s - cues.back().start_s < kShortestSlowCue_s) {
      cues.back().text += "\n" + cue.text;
      cues.back().end_s = cue.end_s;
    } else {
      cues.push_back(std::move(cue));
    }
  }
  if (!cues.empty()) cues.back().end_s = length_s;
  return cues;
}

RenderSummary renderVideo(const VideoRequest& request) {
  request.options.check(request.target);
  // Every file it writes, checked before any work (and its folder watched for a signal).
  const output::OutputPlan outputs(videoOutputs(request), request.options.force);
  // Ctrl-C or SIGTERM stop cleanly: in the simulation, or between frames (the sink then removes
  // what it wrote).
  const output::StopSignals signals;
  const Animation animation = output::beforeWriting("'" + request.target.path + "'", [&] {
    return animate(request.scene, {request.size.width_px, request.size.height_px});
  });
  const compose::FrameSource& source = animation.frames;
  const int frames = frameCount(source.duration_s(), request.fps);
  const double length_s = static_cast<double>(frames) / request.fps;
  std::vector<report::Cue> cues;
  if (request.options.wantsNarration()) {
    cues = narrationCues(source, titleOf(request.scene), length_s, request.fps);
  }

  output::SinkSettings settings;
  if (request.options.quality >= 0) settings.quality = request.options.quality;
  settings.preset = request.options.preset;
  settings.encoder_threads = request.encoder_threads;
  settings.transparent = request.options.transparent;
  settings.extras = videoExtras(request, source, frames, cues);
  settings.png_text = {{"Title", titleOf(request.scene)},
                       {"Software", std::string("collide ") + kVersion},
                       {"Description", settings.extras.metadata["description"]},
                       {"Comment", madeWith(request.scene)}};
  const std::string what = output::kindName(request.target.kind) + " '" + request.target.path + "'";

  render::Renderer renderer(request.size.width_px, request.size.height_px);
  std::unique_ptr<output::FrameSink> sink = output::makeSink(request.target, std::move(settings));
  sink->begin({request.size.width_px, request.size.height_px, request.fps});
  core::Progress progress(
      request.progress_stream != nullptr ? *request.progress_stream : std::cerr,
      request.progress_stream != nullptr ? request.progress : core::ProgressStyle::kSilent, frames,
      "rendering");
  {
    // A rendered frame stays whole until the second render() after it (render/renderer.hpp),
    // so a staging sink's conversion runs on its own thread while the next frame is drawn.
    output::EncodeThread encoder(
        *sink, request.size.width_px, request.size.height_px, kEncodeBuffers, kStagedEncodeBuffers,
        output::FrameLifetime::kUntilNextSubmit,
        request.one_thread ? output::EncodeOn::kCallingThread : output::EncodeOn::kOwnThreads);
    const auto compose = [&](int k) {
      frame::FrameModel model = source.frameAt(static_cast<double>(k) / request.fps);
      if (request.options.transparent) model.style.background.a = 0.0f;
      return model;
    };
    std::optional<FramesAhead> ahead;
    if (!request.one_thread) ahead.emplace(frames, compose);
    for (int k = 0; k < frames; ++k) {
      output::StopSignals::throwIfReceived(what);
      const core::ImageView frame = renderer.render(ahead ? ahead->next() : compose(k));
      encoder.submit(frame, renderer.changedRects());
      countFrame(progress, request, k + 1, frames);
    }
    output::StopSignals::throwIfReceived(what);
    encoder.finish();
  }
  progress.finish();

  RenderSummary summary{frames, request.size, {}, animation.warnings};
  const std::string& path = request.target.path;
  if (request.options.captions) {
    const std::string vtt = output::besidePath(path, ".vtt");
    output::writeTextOutput(vtt, std::cout, [&](std::ostream& out) {
      report::writeWebVtt(out, cues, titleOf(request.scene), text::activeLanguage().tag);
    });
    summary.side_files.push_back(vtt);
  }
  if (request.options.srt) {
    const std::string srt = output::besidePath(path, ".srt");
    output::writeTextOutput(srt, std::cout,
                            [&](std::ostream& out) { report::writeSrt(out, cues); });
    summary.side_files.push_back(srt);
  }
  return summary;
}

RenderSummary renderStill(const StillRequest& request) {
  const output::OutputPlan outputs(stillOutputs(request));
  // Ctrl-C or SIGTERM stop cleanly: in the simulation, or before the picture is renamed into place.
  const output::StopSignals signals;
  FigureSettings figure;
  figure.size = request.size;
  figure.print = request.print;
  const Animation animation = output::beforeWriting("'" + request.target.path + "'", [&] {
    return animate(request.scene, figurePictureSize(figure, request.target.kind));
  });
  const compose::FrameSource& source = animation.frames;
  const physics::Timeline& timeline = source.timeline();
  // Gliders on an air track are described as such, not as blocks.
  const std::vector<scene::BodyDesc>& bodies = request.scene.bodies;
  const bool gliders = !bodies.empty() && std::all_of(bodies.begin(), bodies.end(),
                                                      [](auto& b) { return b.shape == "glider"; });
  std::vector<report::PanelDescription> panels;
  for (std::size_t p = 0; p < source.panelCount(); ++p) {
    panels.push_back({source.panelHeading(p), &source.panelTimeline(p), gliders});
  }
  const WorkingTexts working = workingTexts(request.scene, timeline);
  const std::string alt_text = withSentence(
      report::describePanels(panels, titleOf(request.scene), request.at_s), working.spoken_steps);
  figure.title = titleOf(request.scene);
  figure.description = alt_text;
  figure.png_text = {
      {"Title", titleOf(request.scene)},
      {"Software", std::string("collide ") + kVersion},
      {"Description", alt_text},
      {"Comment", madeWith(request.scene) + "; " + report::describeParameters(timeline)}};
  frame::FrameModel model = source.frameAtSimulated(request.at_s);
  if (request.options.transparent) model.style.background.a = 0.0f;
  writeFigure(request.target, model, figure);

  RenderSummary summary{1, figureFrameSize(figure), {}, animation.warnings};
  // Beside a file only: a device, FIFO or stdout has no name to put NAME.alt.txt beside (the
  // PNG's Description chunk still carries the text).
  if (request.options.alt_text && !request.target.streamed) {
    const std::string path = output::besidePath(request.target.path, ".alt.txt");
    output::writeTextOutput(path, std::cout, [&](std::ostream& out) { out << alt_text << "\n"; });
    summary.side_files.push_back(path);
  }
  if (request.target.streamed) return summary;  // nothing to put a bundle beside
  // TRANSLATORS: a still's figure caption (LaTeX, Markdown): "Inelastic collision, at t = 2.000 s."
  const std::string caption = text::fill(
      text::tr("{title}, at {time}."),
      {{"title", titleOf(request.scene)},
       {"time",
        text::equation(text::symbol(text::Symbol::kTime),
                       text::formatScaled(std::llround(request.at_s * 1000.0), 3) + " s")}});
  const std::vector<std::string> bundle = request.bundle.write(pictureBundle(
      request.target.path, caption, alt_text,
      request.print ? std::optional<double>(request.print->width_cm) : std::nullopt, working));
  summary.side_files.insert(summary.side_files.end(), bundle.begin(), bundle.end());
  return summary;
}

}  // namespace collide::app
