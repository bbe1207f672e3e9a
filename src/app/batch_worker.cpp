#include "app/batch_worker.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <iostream>
#include <optional>
#include <set>

#include "app/batch_threads.hpp"
#include "app/lesson_pipeline.hpp"
#include "app/picture_pipeline.hpp"
#include "app/render_pipeline.hpp"
#include "app/world_from_scene.hpp"
#include "core/error.hpp"
#include "output/output_target.hpp"
#include "output/stop_signals.hpp"
#include "output/text_output.hpp"
#include "physics/simulate.hpp"
#include "report/csv_table.hpp"
#include "report/json_summary.hpp"
#include "report/json_writer.hpp"
#include "report/physics_warnings.hpp"
#include "scene/scene_io.hpp"
#include "text/language.hpp"
#include "working/working.hpp"
#include "working/writers.hpp"

namespace collide::app {
namespace {

std::string pathIn(const JobSettings& settings, const std::string& file) {
  return (std::filesystem::path(settings.directory) / file).string();
}

// One report line: the kind, then each value as a JSON string, so that no text from a scene (a
// title with a newline, say) can end the line or add one (batch_pool.hpp reads them back).
void writeReportLine(std::ostream& out, const char* kind,
                     std::initializer_list<std::string> values) {
  out << kind;
  for (const std::string& value : values) out << ' ' << report::jsonQuoted(value);
  out << '\n';
}

// The next line from the pool, without its newline; nothing once the channel is closed. Read a
// byte at a time: the lines are short and nothing after one may be taken from the channel.
std::optional<std::string> readLine(int fd) {
  std::string line;
  for (;;) {
    char c = 0;
    const ssize_t n = read(fd, &c, 1);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return std::nullopt;
    if (c == '\n') return line;
    line += c;
  }
}

// Sends this process's stdout and stderr to the end of `log`.
void redirectOutput(const std::string& log, std::ostream& out) {
  out.flush();
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0600);
  if (fd < 0) {
    throw core::RuntimeError("batch: cannot open the worker log '" + log +
                             "': " + std::strerror(errno));
  }
  dup2(fd, STDOUT_FILENO);
  dup2(fd, STDERR_FILENO);
  close(fd);
}

}  // namespace

void serveBatchJobs(const std::vector<BatchJob>& all, const JobSettings& settings, int channel_fd,
                    std::ostream& out) {
  while (const std::optional<std::string> line = readLine(channel_fd)) {
    const std::size_t space = line->find(' ');
    std::size_t index = all.size();
    try {
      index = std::stoul(line->substr(0, space));
    } catch (const std::exception&) {
    }
    if (space == std::string::npos || index >= all.size()) {
      throw core::RuntimeError("batch: the worker was handed no job it knows: '" + *line + "'");
    }
    redirectOutput(line->substr(space + 1), out);
    runBatchJob(all[index], settings, out);
    out.flush();
    constexpr char kDone[] = "done\n";
    if (write(channel_fd, kDone, sizeof kDone - 1) != static_cast<ssize_t>(sizeof kDone - 1)) {
      throw core::RuntimeError(std::string("batch: cannot answer the pool: ") +
                               std::strerror(errno));
    }
  }
}

namespace {

// The job's language (--langs), else the scene's own `lang`, else English: chosen before the
// scene loads, so that a preset's words come in it.
scene::SceneDesc loadJobScene(const BatchJob& job, const JobSettings& settings) {
  text::setActiveLanguage(job.lang.empty() ? text::shippedLanguages().front()
                                           : text::findLanguage(job.lang, "--langs"));
  scene::SceneDesc scene = scene::loadScene(job.scene, job.overrides);
  if (job.lang.empty() && !scene.lang.empty()) {
    text::setActiveLanguage(text::findLanguage(scene.lang, "lang"));
    scene = scene::loadScene(job.scene, job.overrides);
  }
  if (!job.lang.empty()) scene.lang = job.lang;
  if (settings.duration_s) scene.duration_s = *settings.duration_s;
  return scene;
}

// What the pool's manifest records of the job before its outputs.
void announceJob(const scene::SceneDesc& scene, std::ostream& out) {
  writeReportLine(out, "scene", {scene.name});
  writeReportLine(out, "lang", {text::activeLanguage().tag});
  writeReportLine(out, "title", {scene.title});
  for (const auto& [key, value] : scene.parameters) {
    writeReportLine(out, "parameter", {key, report::shortestDecimal(value)});
  }
  out.flush();
}

// One job's outputs, format by format. The data formats share one simulation; the picture
// formats run their own through the pipeline. Every format simulates the same scene, so a
// physics warning is reported once.
class JobOutputs {
 public:
  JobOutputs(const BatchJob& job, const scene::SceneDesc& scene, const JobSettings& settings,
             std::ostream& out)
      : job_(job), scene_(scene), settings_(settings), out_(out) {}

  void write(BatchFormat format, const std::string& path) {
    switch (format) {
      case BatchFormat::kMp4:
        return writeVideo(path);
      case BatchFormat::kPng:
      case BatchFormat::kSvg:
      case BatchFormat::kPdf:
        return writeStill(path);
      case BatchFormat::kJson:
        output::writeTextOutput(path, out_, [&](std::ostream& stream) {
          report::writeJsonSummary(stream, simulated(), {scene_.name, settings_.json_events});
        });
        return reportWarnings(report::physicsWarnings(simulated()));
      case BatchFormat::kCsv:
        output::writeTextOutput(path, out_, [&](std::ostream& stream) {
          report::writeCsv(stream, simulated(), settings_.csv_step_s);
        });
        return reportWarnings(report::physicsWarnings(simulated()));
      case BatchFormat::kStrobe:
        return writeStrobe(path);
      case BatchFormat::kLesson:
        return writeLessonFolder(path);
      case BatchFormat::kWorking:
        return writeWorkingFiles(path);
    }
  }

 private:
  const physics::Timeline& simulated() {
    if (!timeline_) timeline_.emplace(physics::simulate(worldFromScene(scene_)));
    return *timeline_;
  }

  void reportWarnings(const std::vector<std::string>& warnings) {
    for (const std::string& warning : warnings) {
      if (warned_.insert(warning).second) writeReportLine(out_, "warning", {warning});
    }
  }

  // Files the pipeline wrote beside the main output (alt text, captions), as manifest entries,
  // each once: the still formats (png, svg, pdf) of a job share one STEM.alt.txt.
  void reportSideFiles(const RenderSummary& summary) {
    for (const std::string& side : summary.side_files) {
      const std::string file = std::filesystem::path(side).filename().string();
      if (!side_files_.insert(file).second) continue;
      const bool alt = file.size() > 8 && file.compare(file.size() - 8, 8, ".alt.txt") == 0;
      writeReportLine(out_, "output", {alt ? "alt-text" : "side-file", file});
    }
  }

  void writeVideo(const std::string& path) {
    VideoRequest request;
    request.scene = scene_;
    request.size = {settings_.size.width_px & ~1, settings_.size.height_px & ~1};
    request.fps = settings_.fps;
    request.target = {output::OutputKind::kMp4, path};
    request.options.force = settings_.force;
    if (settings_.cores > 0) {
      const WorkerThreads threads = workerThreads(settings_.cores);
      request.encoder_threads = threads.encoder_threads;
      request.one_thread = !threads.overlap;
    }
    const RenderSummary summary = renderVideo(request);
    reportSideFiles(summary);
    reportWarnings(summary.warnings);
  }

  void writeStill(const std::string& path) {
    StillRequest request;
    request.scene = scene_;
    request.size = settings_.size;
    // Without --at: the scene's best still, where it names one (its strobe cannot teach it),
    // else the middle of the run.
    request.at_s =
        settings_.at_s.value_or(scene_.view.best_still_s.value_or(0.5 * scene_.duration_s));
    if (request.at_s > scene_.duration_s) request.at_s = scene_.duration_s;
    // The still's kind from its file name, as `collide still` picks it.
    request.target = output::stillTarget(path);
    const RenderSummary summary = renderStill(request);
    reportSideFiles(summary);
    reportWarnings(summary.warnings);
  }

  void writeStrobe(const std::string& path) {
    // A strobe that cannot teach the scene (a cloud of images): its best still in its place.
    if (scene_.view.best_still_s) {
      StillRequest request{scene_,
                           settings_.size,
                           std::min(*scene_.view.best_still_s, scene_.duration_s),
                           output::stillTarget(path),
                           {},
                           {},
                           {}};
      const RenderSummary summary = renderStill(request);
      reportSideFiles(summary);
      reportWarnings(summary.warnings);
      return;
    }
    // The scene's strobe rate, lowered for long scenes to the 2000 images `collide strobe`
    // allows; none: chosen so the images do not overlap.
    const double rate_hz = std::min(scene_.view.strobe_rate_hz, 2000.0 / scene_.duration_s);
    reportWarnings(
        renderStrobe(
            {scene_, settings_.size, {output::OutputKind::kPngStill, path}, std::nullopt, {}},
            rate_hz)
            .warnings);
  }

  // The job's scene read in English, for a lesson's data files (the same in every language).
  scene::SceneDesc englishScene() const {
    const text::Language& language = text::activeLanguage();
    text::setActiveLanguage(text::shippedLanguages().front());
    scene::SceneDesc english = scene::loadScene(job_.scene, job_.overrides);
    text::setActiveLanguage(language);
    english.duration_s = scene_.duration_s;
    return english;
  }

  void writeLessonFolder(const std::string& path) {
    LessonRequest request{scene_,
                          englishScene(),
                          {settings_.size.width_px & ~1, settings_.size.height_px & ~1},
                          settings_.fps,
                          path};
    if (settings_.cores > 0) {
      const WorkerThreads threads = workerThreads(settings_.cores);
      request.encoder_threads = threads.encoder_threads;
      request.one_thread = !threads.overlap;
    }
    reportWarnings(writeLesson(request).warnings);
  }

  // The working of the first impact, as `collide solve --format latex` and `--format markdown`
  // write it: STEM.working.tex at `path`, STEM.working.md beside it (a side file).
  void writeWorkingFiles(const std::string& path) {
    const physics::Timeline& timeline = simulated();
    reportWarnings(report::physicsWarnings(timeline));
    if (working::impactCount(timeline) == 0) {
      throw core::InputError("--formats working: '" + job_.stem +
                             "': no impact in its simulated time; allowed: a scene whose bodies "
                             "collide (a longer --duration?)");
    }
    const working::Working shown = working::workingFor(timeline, 0);
    output::writeTextOutput(path, out_, [&](std::ostream& stream) {
      stream << working::writeWorking(shown, working::Format::kLatex);
    });
    const std::string markdown = workingMarkdownName(job_.stem);
    output::writeTextOutput(pathIn(settings_, markdown), out_, [&](std::ostream& stream) {
      stream << working::writeWorking(shown, working::Format::kMarkdown);
    });
    writeReportLine(out_, "output", {"side-file", markdown});
  }

  const BatchJob& job_;
  const scene::SceneDesc& scene_;
  const JobSettings& settings_;
  std::ostream& out_;
  std::optional<physics::Timeline> timeline_;
  std::set<std::string> warned_;
  std::set<std::string> side_files_;
};

}  // namespace

void runBatchJob(const BatchJob& job, const JobSettings& settings, std::ostream& out) {
  // The batch stops its workers with SIGTERM: every format then ends at its next check point and
  // removes its temporary file (without this, CSV and JSON died with the default action).
  const output::StopSignals stop_signals;
  const scene::SceneDesc scene = loadJobScene(job, settings);
  announceJob(scene, out);
  JobOutputs outputs(job, scene, settings, out);
  for (const BatchFormat format : settings.formats) {
    const std::string file = outputFileName(job.stem, format);
    outputs.write(format, pathIn(settings, file));
    writeReportLine(out, "output", {formatName(format), file});
    out.flush();
  }
}

}  // namespace collide::app
