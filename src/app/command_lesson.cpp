// SPDX-License-Identifier: MIT
// collide lesson SCENE -o DIR/ [--lang TAG] [--size WxH] [--fps N]: a folder with index.html, the
// video, pictures and data, that a teacher uploads as it is (app/lesson_pipeline.hpp).
#include "app/command.hpp"
#include "app/lesson_pipeline.hpp"
#include "app/picture_options.hpp"
#include "app/scene_options.hpp"
#include "core/error.hpp"

namespace collide::app {
namespace {

class LessonCommand : public Command {
 public:
  explicit LessonCommand(CLI::App& root)
      : app_(*root.add_subcommand(
            "lesson",
            "Write a lesson folder: a web page with the video, captions, pictures and data")) {
    options_.addTo(app_, "Output folder, made if missing (its lesson files are replaced)",
                   [this](CLI::App& command) {
                     command
                         .add_option("--fps", fps_,
                                     "The video's frames per second, 1 to 240 (the Tracker "
                                     "model's rows follow its frames)")
                         ->capture_default_str();
                   });
    app_.footer(
        "The folder holds index.html (open it from disk or put the folder on any web host: no "
        "script, nothing from the network), video.mp4 and video.webm with captions "
        "(video.vtt) in the page's language and a calibration stick for Tracker, stills, a "
        "stroboscope photograph, the energy chart (SVG) and the data: data.csv, summary.json, "
        "tracker.txt and vernier.txt (docs/data-format.md).\nExamples:\n"
        "  collide lesson worked-example -o lesson/\n"
        "  collide lesson ballistic-pendulum --lang ar -o pendulum-ar/ --size 960x540");
  }

  CLI::App& cliApp() override { return app_; }

  int run(CommandStreams& streams) override {
    checkFps(fps_);
    if (options_.output == "-") {
      throw core::InputError("-o: '-': a lesson is a folder of files; allowed: a folder path");
    }
    // The data files in English, read first: loading the page's scene chooses the language.
    SceneOptions english = options_.scene;
    english.words = false;
    scene::SceneDesc data_scene = english.load();
    LessonRequest request{options_.loadScene(), data_scene, options_.size.parse(), fps_,
                          options_.output};
    // H.264 needs even dimensions.
    request.size.width_px &= ~1;
    request.size.height_px &= ~1;
    const LessonSummary summary = writeLesson(request);
    streams.out << "wrote " << summary.files.back() << "\n";
    for (std::size_t i = 0; i + 1 < summary.files.size(); ++i) {
      streams.out << "wrote " << summary.files[i] << "\n";
    }
    return 0;
  }

 private:
  CLI::App& app_;
  PictureOptions options_;
  int fps_ = 30;
};

}  // namespace

std::unique_ptr<Command> makeLessonCommand(CLI::App& root) {
  return std::make_unique<LessonCommand>(root);
}

}  // namespace collide::app
