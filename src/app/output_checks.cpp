// SPDX-License-Identifier: MIT
#include "app/output_checks.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/error.hpp"
#include "core/typed_text.hpp"
#include "report/csv_table.hpp"
#include "report/figure_bundle.hpp"

namespace collide::app {
namespace {

// Bytes a frame's pixel comes to, about, by output kind: H.264 and VP9 at their default quality
// keep flat shapes in well under a bit (a gas of moving disks needs the most); GIF's palette and
// LZW take a little more; PNG frames, each compressed alone, far more.
double bytesPerPixel(output::OutputKind kind) {
  switch (kind) {
    case output::OutputKind::kPngFrames:
      return 0.25;
    case output::OutputKind::kGif:
      return 0.03;
    default:
      return 0.01;
  }
}

// Drawing and encoding a pixel takes some 10 ns on two cores (llvmpipe and x264): days show.
std::string drawingTime(double pixels) {
  const double hours = pixels * 10e-9 / 3600.0;
  if (hours < 1.0) return "";
  char text[64];
  if (hours < 48.0) {
    std::snprintf(text, sizeof text, "; about %.0f hours to draw", hours);
  } else {
    std::snprintf(text, sizeof text, "; about %.0f days to draw", hours / 24.0);
  }
  return text;
}

output::PlannedOutput plannedVideo(const output::OutputTarget& target, int frames, FrameSize size) {
  const double pixels = static_cast<double>(frames) * size.width_px * size.height_px;
  output::PlannedOutput planned{"-o", target.path, target.kind == output::OutputKind::kPngFrames};
  planned.estimated_bytes = pixels * bytesPerPixel(target.kind);
  planned.estimate_basis = std::to_string(frames) + " frames of " + std::to_string(size.width_px) +
                           "x" + std::to_string(size.height_px) + drawingTime(pixels);
  planned.smaller_with = "a shorter --duration, a smaller --size or fewer --fps";
  return planned;
}

void addBundle(const BundleOptions& bundle, const output::OutputTarget& target,
               std::vector<output::PlannedOutput>& outputs) {
  if (target.streamed) return;  // nothing to put a bundle beside
  if (bundle.latex && !report::latexNamesFile(target.path)) {
    throw core::InputError("--latex: -o '" + core::echoTyped(target.path) +
                           "': LaTeX cannot name that file in \\includegraphics; allowed: a file "
                           "name without \\ { } % # $ & ^ ~ or control characters");
  }
  if (bundle.latex) outputs.push_back({"--latex", output::besidePath(target.path, ".tex")});
  if (bundle.markdown) outputs.push_back({"--markdown", output::besidePath(target.path, ".md")});
}

}  // namespace

std::vector<output::PlannedOutput> videoOutputs(const VideoRequest& request) {
  std::vector<output::PlannedOutput> outputs = {plannedVideo(
      request.target, frameCount(request.scene.duration_s, request.fps), request.size)};
  if (request.target.streamed) return outputs;
  const std::string& path = request.target.path;
  if (request.options.captions) outputs.push_back({"--captions", output::besidePath(path, ".vtt")});
  if (request.options.srt) outputs.push_back({"--srt", output::besidePath(path, ".srt")});
  return outputs;
}

std::vector<output::PlannedOutput> stillOutputs(const StillRequest& request) {
  std::vector<output::PlannedOutput> outputs = {{"-o", request.target.path}};
  if (request.options.alt_text && !request.target.streamed) {
    outputs.push_back({"alt text (--no-alt-text leaves it out)",
                       output::besidePath(request.target.path, ".alt.txt")});
  }
  addBundle(request.bundle, request.target, outputs);
  return outputs;
}

std::vector<output::PlannedOutput> pictureOutputs(const PictureRequest& request) {
  std::vector<output::PlannedOutput> outputs = {{"-o", request.target.path}};
  addBundle(request.bundle, request.target, outputs);
  return outputs;
}

output::PlannedOutput csvOutput(const std::string& path, const scene::SceneDesc& scene,
                                double step_s) {
  const report::CsvSize size =
      report::estimateCsvSize(scene.dimensions, scene.bodies.size(), scene.duration_s, step_s,
                              !scene.releases.empty() || scene.super_elastic);
  output::PlannedOutput planned{"--csv", path};
  planned.estimated_bytes = size.bytes;
  planned.estimate_basis =
      std::to_string(size.rows) + " rows of " + std::to_string(size.columns) + " columns";
  planned.smaller_with = "a shorter --duration or a larger --dt";
  return planned;
}

std::vector<output::PlannedOutput> batchOutputs(const std::vector<BatchJob>& jobs,
                                                const std::vector<JobShape>& shapes,
                                                const JobSettings& settings,
                                                const std::string& manifest_path) {
  std::vector<output::PlannedOutput> outputs;
  const auto in = [&](const std::string& file) {
    return (std::filesystem::path(settings.directory) / file).string();
  };
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    for (const BatchFormat format : settings.formats) {
      const std::string path = in(outputFileName(jobs[i].stem, format));
      output::PlannedOutput planned{"-o", path};
      // A lesson is a folder of files (collide lesson), checked as a folder of frames is.
      if (format == BatchFormat::kLesson) planned = {"-o", path.substr(0, path.size() - 1), true};
      if (format == BatchFormat::kMp4 && shapes[i].loaded) {
        const FrameSize even{settings.size.width_px & ~1, settings.size.height_px & ~1};
        planned = plannedVideo({output::OutputKind::kMp4, path},
                               frameCount(shapes[i].duration_s, settings.fps), even);
      } else if (format == BatchFormat::kCsv && shapes[i].loaded) {
        const report::CsvSize size = report::estimateCsvSize(
            shapes[i].dimensions, shapes[i].bodies, shapes[i].duration_s, settings.csv_step_s);
        planned.estimated_bytes = size.bytes;
        planned.estimate_basis =
            std::to_string(size.rows) + " rows of " + std::to_string(size.columns) + " columns";
        planned.smaller_with = "a shorter --duration or a larger --csv-step";
      }
      outputs.push_back(planned);
      if (format == BatchFormat::kWorking) {
        outputs.push_back({"-o", in(workingMarkdownName(jobs[i].stem))});
      }
    }
    // The png, svg and pdf of a job share one alt text (STEM.alt.txt).
    for (const BatchFormat format : settings.formats) {
      if (format == BatchFormat::kPng || format == BatchFormat::kSvg ||
          format == BatchFormat::kPdf) {
        outputs.push_back({"alt text", in(jobs[i].stem + ".alt.txt")});
        break;
      }
    }
  }
  if (std::find(settings.formats.begin(), settings.formats.end(), BatchFormat::kLesson) !=
      settings.formats.end()) {
    outputs.push_back({"lesson index", in("index.html")});
  }
  outputs.push_back({"manifest", manifest_path});
  return outputs;
}

}  // namespace collide::app
