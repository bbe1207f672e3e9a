// SPDX-License-Identifier: MIT
#include "app/lesson_pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <sstream>

#include "app/lab_data.hpp"
#include "app/picture_pipeline.hpp"
#include "app/render_pipeline.hpp"
#include "app/simulation_progress.hpp"
#include "app/world_from_scene.hpp"
#include "compose/palette.hpp"
#include "core/error.hpp"
#include "output/output_target.hpp"
#include "output/text_output.hpp"
#include "report/csv_table.hpp"
#include "report/json_summary.hpp"
#include "report/lab_tables.hpp"
#include "text/language.hpp"
#include "text/translate.hpp"
#include "working/working.hpp"
#include "working/writers.hpp"

namespace collide::app {
namespace {

constexpr const char* kMp4 = "video.mp4";
constexpr const char* kWebm = "video.webm";
constexpr const char* kCaptions = "video.vtt";  // written beside video.mp4
constexpr const char* kStart = "start.png";
constexpr const char* kEnd = "end.png";
constexpr const char* kStrobe = "strobe.png";
constexpr const char* kChart = "energy.svg";
constexpr const char* kCsv = "data.csv";
constexpr const char* kJson = "summary.json";
constexpr const char* kTracker = "tracker.txt";
constexpr const char* kVernier = "vernier.txt";
constexpr const char* kPage = "index.html";

std::string in(const std::string& directory, const std::string& name) {
  return directory + (directory.empty() || directory.back() == '/' ? "" : "/") + name;
}

// A file this run wrote (a still's alt text, the captions), whole; its last line end dropped.
std::string readWritten(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw core::RuntimeError("lesson: cannot read back '" + path + "'");
  std::ostringstream text;
  text << file.rdbuf();
  std::string content = text.str();
  if (!content.empty() && content.back() == '\n') content.pop_back();
  return content;
}

// The text of each cue of a WebVTT file as report/captions.cpp writes it: blocks separated by
// an empty line, a cue's text the lines after its "-->" line.
std::vector<std::string> cueTexts(const std::string& vtt) {
  std::vector<std::string> cues;
  std::istringstream lines(vtt);
  std::string line, cue;
  bool in_cue = false;
  while (std::getline(lines, line)) {
    if (line.empty()) {
      if (in_cue && !cue.empty()) cues.push_back(cue);
      in_cue = false;
      cue.clear();
    } else if (line.find("-->") != std::string::npos) {
      in_cue = true;
    } else if (in_cue) {
      cue += (cue.empty() ? "" : "\n") + line;
    }
  }
  if (in_cue && !cue.empty()) cues.push_back(cue);
  return cues;
}

RenderSummary renderLessonVideo(const LessonRequest& request, const char* name, bool captions) {
  VideoRequest video{request.scene,
                     request.size,
                     request.fps,
                     output::videoTarget(in(request.directory, name)),
                     {}};
  video.scene.view.calibration = request.calibration;
  video.options.captions = captions;
  video.encoder_threads = request.encoder_threads;
  video.one_thread = request.one_thread;
  return renderVideo(video);
}

report::LessonPicture lessonStill(const LessonRequest& request, const char* name, double t_s,
                                  const std::string& caption) {
  const std::string path = in(request.directory, name);
  StillRequest still{request.scene, request.size, t_s, output::stillTarget(path), {}, {}, {}};
  renderStill(still);
  return {name, readWritten(output::besidePath(path, ".alt.txt")), caption, request.size.width_px,
          request.size.height_px};
}

// The strobe picture of the run; where the scene's strobe cannot teach it (a cloud of images,
// view.best_still), its best still in that place.
report::LessonPicture lessonStrobe(const LessonRequest& request) {
  if (request.scene.view.best_still_s) {
    return lessonStill(request, kStrobe,
                       std::min(*request.scene.view.best_still_s, request.scene.duration_s), "");
  }
  const PictureRequest strobe{
      request.scene, request.size, output::stillTarget(in(request.directory, kStrobe)), {}, {}};
  return {kStrobe, renderStrobe(strobe, request.scene.view.strobe_rate_hz).description, "",
          request.size.width_px, request.size.height_px};
}

report::LessonPicture lessonChart(const LessonRequest& request) {
  PictureRequest chart{
      request.scene, request.size, output::stillTarget(in(request.directory, kChart)), {}, {}};
  chart.scene.view.chart_quantity = "energy";
  return {kChart, renderChart(chart).description, "", request.size.width_px,
          request.size.height_px};
}

// What the page shows of the numbers: its table, and the working of the first impact (MathML).
struct LessonNumbers {
  std::vector<report::LessonRow> rows;
  std::string working_mathml;  // empty: no impact
};

// The tables, from one simulation: the Tracker model follows the lesson's video frame by frame.
LessonNumbers writeLessonData(const LessonRequest& request) {
  const physics::Timeline timeline = simulateReporting(worldFromScene(request.data_scene));
  const auto write = [&](const char* name, const std::function<void(std::ostream&)>& body) {
    output::writeTextOutput(in(request.directory, name), std::cout, body);
  };
  write(kCsv,
        [&](std::ostream& out) { report::writeCsv(out, timeline, report::kDefaultCsvStepS); });
  write(kJson, [&](std::ostream& out) {
    report::writeJsonSummary(out, timeline, {request.data_scene.name, false});
  });
  const std::vector<report::TrackerRow> rows =
      trackerRows(request.data_scene, timeline, request.fps);
  write(kTracker, [&](std::ostream& out) {
    report::writeTrackerModel(out, timeline, request.data_scene.name, rows);
  });
  write(kVernier, [&](std::ostream& out) {
    report::writeVernierTable(out, timeline, request.data_scene.name, report::kDefaultCsvStepS);
  });
  // The page's numbers and working name the bodies in the page's language.
  const physics::Timeline shown = simulateReporting(worldFromScene(request.scene));
  LessonNumbers numbers{report::lessonNumbers(shown), ""};
  if (working::impactCount(shown) > 0) {
    numbers.working_mathml =
        working::writeWorking(working::workingFor(shown, 0), working::Format::kMathml);
  }
  return numbers;
}

std::vector<report::LessonLink> dataLinks() {
  return {
      // TRANSLATORS: a link of the lesson page to a data file.
      {kCsv, text::trc("lesson page", "Table for spreadsheets (CSV)")},
      // TRANSLATORS: a link of the lesson page to a data file.
      {kJson, text::trc("lesson page", "Summary for scripts (JSON)")},
      // TRANSLATORS: a link of the lesson page to a data file; Tracker is a video analysis
      // program (its name is not translated).
      {kTracker, text::trc("lesson page", "Model for Tracker, frame by frame over the video")},
      // TRANSLATORS: a link of the lesson page to a data file; Logger Pro and Graphical Analysis
      // are programs (their names are not translated).
      {kVernier, text::trc("lesson page", "Table for Logger Pro and Graphical Analysis")},
      // TRANSLATORS: a link of the lesson page to the video's captions file.
      {kCaptions, text::trc("lesson page", "Captions (WebVTT)")},
  };
}

std::string titleOf(const scene::SceneDesc& scene) {
  return scene.title.empty() ? scene.name : scene.title;
}

std::string cssColor(const frame::Rgba& c) {
  const auto byte = [](float v) {
    return static_cast<int>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
  };
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return text;
}

void makeDirectory(const std::string& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (!std::filesystem::is_directory(directory)) {
    throw core::InputError("-o: '" + directory +
                           "': cannot make a folder there; allowed: a folder, made if missing");
  }
}

}  // namespace

std::vector<std::string> lessonFileNames() {
  return {kMp4,    kCaptions, kWebm, kStart, kEnd,     "start.alt.txt", "end.alt.txt",
          kStrobe, kChart,    kCsv,  kJson,  kTracker, kVernier,        kPage};
}

report::LessonColors lessonColors(const std::string& theme) {
  const compose::Theme& t = compose::themeNamed(theme);
  return {cssColor(t.style.background), cssColor(t.style.text), cssColor(t.style.muted_text),
          cssColor(t.style.bar_frame), cssColor(t.bodies.front())};
}

LessonSummary writeLesson(const LessonRequest& request) {
  makeDirectory(request.directory);
  const text::Language& language = text::activeLanguage();
  report::LessonPage page;
  page.lang = language.tag;
  page.right_to_left = language.right_to_left;
  page.title = titleOf(request.scene);
  page.light = lessonColors("light");
  page.dark = lessonColors("dark");
  const std::vector<std::string> warnings = renderLessonVideo(request, kMp4, true).warnings;
  renderLessonVideo(request, kWebm, false);
  page.video_mp4 = kMp4;
  page.video_webm = kWebm;
  page.video_width_px = request.size.width_px;
  page.video_height_px = request.size.height_px;
  page.captions_file = kCaptions;
  page.captions_vtt = readWritten(in(request.directory, kCaptions)) + "\n";
  page.transcript = cueTexts(page.captions_vtt);
  // TRANSLATORS: the caption under the lesson page's still of the scene's first moment.
  page.pictures.push_back(
      lessonStill(request, kStart, 0.0, text::trc("lesson page", "At the start")));
  // TRANSLATORS: the caption under the lesson page's still of the scene's last moment.
  page.pictures.push_back(
      lessonStill(request, kEnd, request.scene.duration_s, text::trc("lesson page", "At the end")));
  page.poster = kStart;
  page.pictures.push_back(lessonStrobe(request));
  page.chart = lessonChart(request);
  LessonNumbers numbers = writeLessonData(request);
  page.numbers = std::move(numbers.rows);
  page.working_mathml = std::move(numbers.working_mathml);
  page.data = dataLinks();
  output::writeTextOutput(in(request.directory, kPage), std::cout,
                          [&](std::ostream& out) { out << report::lessonPageHtml(page); });

  LessonSummary summary;
  for (const std::string& name : lessonFileNames()) {
    summary.files.push_back(in(request.directory, name));
  }
  summary.entry = {"", page.title, page.pictures.front()};
  summary.warnings = warnings;
  return summary;
}

report::LessonEntry lessonEntry(const std::string& directory, const std::string& folder,
                                const std::string& title, FrameSize size) {
  const std::string alt_text = readWritten(in(in(directory, folder), "start.alt.txt"));
  return {folder, title, {kStart, alt_text, "", size.width_px, size.height_px}};
}

std::string writeLessonIndex(const std::string& dir,
                             const std::vector<report::LessonEntry>& lessons) {
  const text::Language& language = text::activeLanguage();
  const std::string path = in(dir, kPage);
  output::writeTextOutput(path, std::cout, [&](std::ostream& out) {
    out << report::lessonIndexHtml(language.tag, language.right_to_left, lessonColors("light"),
                                   lessonColors("dark"), lessons);
  });
  return path;
}

}  // namespace collide::app
