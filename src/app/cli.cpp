#include "app/cli.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <ostream>

#include "app/render_pipeline.hpp"
#include "app/text_output.hpp"
#include "app/world_from_scene.hpp"
#include "core/error.hpp"
#include "output/codec_log.hpp"
#include "physics/simulate.hpp"
#include "report/json_summary.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {
namespace {

constexpr const char* kVersion = "0.1.0";

struct CommonOptions {
  std::string scene;
  std::string output;
  std::string size = "1280x720";
  double duration_s = 0.0;
  CLI::Option* duration_option = nullptr;  // count() > 0 when --duration was given
};

void addCommonOptions(CLI::App& command, CommonOptions& options) {
  command.add_option("SCENE", options.scene, "Preset name (see 'collide presets')")->required();
  command.add_option("-o,--output", options.output, "Output path")->required();
  command.add_option("--size", options.size, "Frame size WIDTHxHEIGHT")->capture_default_str();
  options.duration_option =
      command.add_option("--duration", options.duration_s,
                         "Simulated seconds to show (default: the scene's duration)");
}

// Loads the scene and applies the duration override, validating it.
scene::SceneDesc sceneFor(const CommonOptions& options) {
  scene::SceneDesc scene = scene::loadPreset(options.scene);
  if (options.duration_option->count() > 0) {
    checkDuration(options.duration_s, "--duration");
    scene.duration_s = options.duration_s;
  }
  return scene;
}

// H.264 needs even dimensions: round an odd width or height down, and say so.
FrameSize evenForVideo(FrameSize size, std::ostream& err) {
  const FrameSize even{size.width_px & ~1, size.height_px & ~1};
  if (even.width_px != size.width_px || even.height_px != size.height_px) {
    err << "note: --size " << size.width_px << "x" << size.height_px << " rounded to "
        << even.width_px << "x" << even.height_px << " (H.264 needs even dimensions)\n";
  }
  return even;
}

int runRender(const CommonOptions& options, int fps, std::ostream& out, std::ostream& err) {
  checkFps(fps);
  VideoRequest request{sceneFor(options), parseFrameSize(options.size), fps,
                       videoTarget(options.output)};
  if (request.target.kind == OutputKind::kMp4) request.size = evenForVideo(request.size, err);
  const RenderSummary summary = renderVideo(request);
  out << "wrote " << request.target.path << " (" << summary.frames << " frames, "
      << summary.size.width_px << "x" << summary.size.height_px << ", " << fps << " fps, "
      << std::fixed << std::setprecision(3) << static_cast<double>(summary.frames) / fps << " s)\n";
  return 0;
}

int runStill(const CommonOptions& options, double at_s, std::ostream& out) {
  StillRequest request{sceneFor(options), parseFrameSize(options.size), at_s,
                       stillTarget(options.output)};
  if (!std::isfinite(at_s) || at_s < 0.0 || at_s > request.scene.duration_s) {
    char text[160];
    std::snprintf(text, sizeof text, "--at: %g: allowed: a time from 0 to %g s (the duration)",
                  at_s, request.scene.duration_s);
    throw core::InputError(text);
  }
  renderStill(request);
  out << "wrote " << request.target.path << " (t = " << std::fixed << std::setprecision(3) << at_s
      << " s)\n";
  return 0;
}

struct DataOptions {
  std::string scene;
  std::string json_path;
  bool events = false;
  double duration_s = 0.0;
  CLI::Option* duration_option = nullptr;
};

int runData(const DataOptions& options, std::ostream& out) {
  scene::SceneDesc scene = scene::loadPreset(options.scene);
  if (options.duration_option->count() > 0) {
    checkDuration(options.duration_s, "--duration");
    scene.duration_s = options.duration_s;
  }
  if (options.json_path != "-") requireParentDirectory("--json", options.json_path);
  const physics::Timeline timeline = physics::simulate(worldFromScene(scene));
  writeTextOutput(options.json_path, out, [&](std::ostream& stream) {
    report::writeJsonSummary(stream, timeline, {scene.name, options.events});
  });
  return 0;
}

int runPresets(std::ostream& out) {
  for (const scene::PresetInfo& preset : scene::presetList()) {
    out << std::left << std::setw(22) << preset.name << preset.summary << "\n";
  }
  return 0;
}

}  // namespace

int runCli(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{"collide: exact collision simulations rendered as teaching videos and stills",
               "collide"};
  app.set_version_flag("--version", std::string("collide ") + kVersion);
  app.require_subcommand(1);
  app.footer(
      "Examples:\n  collide render worked-example -o out/worked-example.mp4\n"
      "  collide still worked-example --at 2 -o still.png\n  collide presets");

  CommonOptions render_options;
  int fps = 60;
  CLI::App* render = app.add_subcommand("render", "Render a scene to an MP4 video or PNG frames");
  addCommonOptions(*render, render_options);
  render->add_option("--fps", fps, "Frames per second")->capture_default_str();
  render->footer(
      "OUT ending in .mp4 writes an H.264 video; an existing directory or a path ending "
      "in '/' receives frame_00000.png, ...\nExamples:\n"
      "  collide render worked-example -o lesson.mp4 --size 1920x1080 --fps 30\n"
      "  collide render worked-example -o frames/ --duration 2");

  CommonOptions still_options;
  double at_s = 0.0;
  CLI::App* still = app.add_subcommand("still", "Render one instant of a scene to a PNG image");
  addCommonOptions(*still, still_options);
  still->add_option("--at", at_s, "Simulated time of the image, in seconds")->required();
  still->footer("Example:\n  collide still worked-example --at 2.5 -o after.png");

  DataOptions data_options;
  CLI::App* data = app.add_subcommand("data", "Write a scene's simulated numbers as JSON");
  data->add_option("SCENE", data_options.scene, "Preset name (see 'collide presets')")->required();
  data->add_option("--json", data_options.json_path, "Output path, or - for stdout")->required();
  data->add_flag("--events", data_options.events,
                 "Include every collision in a \"collisions\" array");
  data_options.duration_option = data->add_option(
      "--duration", data_options.duration_s, "Simulated seconds (default: the scene's duration)");
  data->footer(
      "Examples:\n  collide data worked-example --json -\n"
      "  collide data worked-example --json summary.json --events");

  CLI::App* presets = app.add_subcommand("presets", "List the built-in scenes");

  // libx264 and libav print their settings and statistics otherwise; errors still show.
  output::setCodecLogLevel(output::CodecLogLevel::kErrors);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    out << (app.get_subcommands().empty() ? app.help() : app.get_subcommands().front()->help());
    return 0;
  } catch (const CLI::CallForVersion&) {
    out << "collide " << kVersion << "\n";
    return 0;
  } catch (const CLI::ParseError& e) {
    err << "collide: " << e.what() << " (run 'collide --help')\n";
    return static_cast<int>(core::ExitCode::kBadInput);
  }

  try {
    if (render->parsed()) return runRender(render_options, fps, out, err);
    if (still->parsed()) return runStill(still_options, at_s, out);
    if (data->parsed()) return runData(data_options, out);
    if (presets->parsed()) return runPresets(out);
  } catch (const core::Error& e) {
    err << "collide: " << e.what() << "\n";
    return static_cast<int>(e.code());
  }
  return static_cast<int>(core::ExitCode::kBadInput);
}

}  // namespace collide::app
