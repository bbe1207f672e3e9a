// SPDX-License-Identifier: MIT
#pragma once
// `collide lesson SCENE -o DIR/`: a folder a teacher uploads as it is, index.html and its files
// (report/lesson_page.hpp): the video as MP4 and WebM with WebVTT captions and a poster, stills at
// the start and the end, the stroboscope photograph, the energy chart as SVG, and the data (CSV,
// JSON, a Tracker model at the video's frame rate, a Vernier table). Every file is made by the
// pipeline its own command uses (render, still, strobe, chart, data), so the lesson shows what
// those commands write.
#include <iosfwd>
#include <string>
#include <vector>

#include "app/render_settings.hpp"
#include "report/lesson_page.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {

struct LessonRequest {
  scene::SceneDesc scene;  // loaded in its language, which is the active language
  // The same scene read in English: the data files are the same in every language (their body
  // names too).
  scene::SceneDesc data_scene;
  FrameSize size;  // even (H.264)
  int fps = 30;
  std::string directory;    // created when missing; its files are replaced
  int encoder_threads = 0;  // as VideoRequest
  bool one_thread = false;  // as VideoRequest
  // The video's calibration stick and origin (render --calibration): Tracker's model of the
  // lesson (tracker.txt) is measured against them.
  bool calibration = true;
};

struct LessonSummary {
  std::vector<std::string> files;  // every file written, index.html last
  report::LessonEntry entry;       // for a batch's index page (folder left empty)
  std::vector<std::string> warnings;
};

// The folder names the lesson's files take in `directory`.
std::vector<std::string> lessonFileNames();

// Writes the lesson. Throws what the pipelines throw (InputError, OutputError, RenderError,
// InterruptedError).
LessonSummary writeLesson(const LessonRequest& request);

// The page's colours: the tool's light and dark themes (compose/palette.hpp).
report::LessonColors lessonColors(const std::string& theme);

// The entry of the lesson in `directory`/`folder` (folder ending in '/') for an index page: its
// title and its first still with that still's alt text.
report::LessonEntry lessonEntry(const std::string& directory, const std::string& folder,
                                const std::string& title, FrameSize size);

// Writes `dir`/index.html listing `lessons` (their folders relative to `dir`).
std::string writeLessonIndex(const std::string& dir,
                             const std::vector<report::LessonEntry>& lessons);

}  // namespace collide::app
