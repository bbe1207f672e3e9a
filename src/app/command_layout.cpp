// SPDX-License-Identifier: MIT
// collide layout SCENE [--at T | --fps N] [--size WxH] --json FILE|-: what the painters draw in
// each frame, in pixels, item by item (render/frame_layout.hpp), for tests and for anyone who
// builds an overlay from collide's layout.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "app/command.hpp"
#include "app/layout_json.hpp"
#include "app/render_pipeline.hpp"
#include "app/scene_options.hpp"
#include "app/style_options.hpp"
#include "core/error.hpp"
#include "core/typed_text.hpp"
#include "output/output_target.hpp"
#include "output/stop_signals.hpp"
#include "output/text_output.hpp"
#include "render/frame_layout.hpp"
#include "report/json_writer.hpp"
#include "report/physics_warnings.hpp"

namespace collide::app {
namespace {

// One frame: its simulated time, the video's frame number (-1: a still) and its items.
void writeFrame(report::JsonWriter& json, const frame::FrameModel& model, double t_s, int index,
                const FrameSize& size) {
  json.beginObject().key("t").value(t_s);
  if (index >= 0) json.key("frame").value(index);
  json.key("items").beginArray();
  for (const frame::DrawnItem& item : render::drawnItems(model, size.width_px, size.height_px)) {
    writeDrawnItem(json, item);
  }
  json.endArray().endObject();
}

class LayoutCommand : public Command {
 public:
  explicit LayoutCommand(CLI::App& root)
      : app_(*root.add_subcommand(
            "layout", "Write what each frame draws, in pixels, as JSON: boxes, texts, arrows")) {
    scene_.addSceneArgument(app_);
    app_.add_option("--json", json_path_, "Output path for the layout, or - for stdout")
        ->required();
    at_option_ =
        app_.add_option("--at", at_s_, "One frame: the still at this simulated time, in seconds");
    fps_option_ = app_.add_option("--fps", fps_,
                                  "Every frame of the video at this rate, 1 to 240 (the default, "
                                  "at 60)");
    size_.addTo(app_);
    scene_.addChanges(app_);
    style_.addTo(app_);
    app_.footer(
        "Items: {\"id\", \"kind\", \"text\", \"lines\", \"box\": [x0, y0, x1, y1], \"body\"}; ids "
        "stay the same from frame to frame (body.2, velocity.2, mass.1, arrow.2, "
        "legend.velocity.3, title, caption); an arrow adds \"from\", \"to\", \"value\" (m/s), "
        "\"scale\" (px per m/s) and \"drawn\": on_scale, off_scale or below_scale; the calibration "
        "stick (--calibration) adds \"stick\": {\"from\", \"to\", \"length_m\", \"px_per_m\"}; "
        "a text (or its leader) fading in or out adds \"opacity\", below 1 (absent: solid; "
        "one too faint to show, under 1/255, is left out). "
        "\"events\" "
        "lists the collisions' simulated times.\nExamples:\n"
        "  collide layout worked-example --json layout.json\n"
        "  collide layout newtons-cradle --at 0.35 --size 640x360 --json -");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    const bool still = at_option_->count() > 0;
    if (still && fps_option_->count() > 0) {
      throw core::InputError("--at: " + core::echoTyped(at_option_->results().back()) +
                             " with --fps: allowed: one frame (--at) or every frame (--fps)");
    }
    checkFps(fps_);
    const FrameSize size = size_.parse();
    scene::SceneDesc scene = scene_.load();
    style_.applyTo(scene);
    if (still && (!std::isfinite(at_s_) || at_s_ < 0.0 || at_s_ > scene.duration_s)) {
      char duration[40];
      std::snprintf(duration, sizeof duration, "%g", scene.duration_s);
      throw core::InputError("--at: " + core::echoTyped(at_option_->results().back()) +
                             ": allowed: a time from 0 to " + duration + " s (the duration)");
    }
    output::checkOutputPath("--json", json_path_);
    const output::StopSignals signals;
    const std::string target = json_path_ == "-" ? "stdout" : "'" + json_path_ + "'";
    const Animation animation = output::beforeWriting(target, [&] {
      return animate(scene, {size.width_px, size.height_px});
    });
    output::writeTextOutput(json_path_, streams.out, [&](std::ostream& out) {
      writeLayout(out, animation.frames, size, still);
    });
    report::printWarnings(animation.warnings, streams.err);
    return 0;
  }

 private:
  void writeLayout(std::ostream& out, const compose::FrameSource& source, const FrameSize& size,
                   bool still) const {
    report::JsonWriter json(out);
    json.beginObject().key("scene").value(source.scene().name);
    json.key("size").beginArray().value(size.width_px).value(size.height_px).endArray();
    if (!still) json.key("fps").value(fps_);
    json.key("events").beginArray();
    for (std::size_t p = 0; p < source.panelCount(); ++p) {
      for (const physics::CollisionEvent& event : source.panelTimeline(p).collisions()) {
        json.value(event.time_s);
      }
    }
    json.endArray().key("frames").beginArray();
    if (still) {
      writeFrame(json, source.frameAtSimulated(at_s_), at_s_, -1, size);
    } else {
      // The video's frames: frame k at playback time k / fps, as `collide render` draws them.
      const int frames = frameCount(source.duration_s(), fps_);
      for (int k = 0; k < frames; ++k) {
        const double playback_s = static_cast<double>(k) / fps_;
        const double t_s =
            std::clamp(source.simulatedAt(playback_s), 0.0, source.simulatedDuration_s());
        writeFrame(json, source.frameAt(playback_s), t_s, k, size);
      }
    }
    json.endArray().endObject();
    out << "\n";
  }

  CLI::App& app_;
  SceneOptions scene_;
  SizeOption size_;
  StyleOptions style_;
  std::string json_path_;
  double at_s_ = 0.0;
  int fps_ = 60;
  CLI::Option* at_option_ = nullptr;
  CLI::Option* fps_option_ = nullptr;
};

}  // namespace

std::unique_ptr<Command> makeLayoutCommand(CLI::App& root) {
  return std::make_unique<LayoutCommand>(root);
}

}  // namespace collide::app
