#include "output/output_target.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>

#include "core/error.hpp"
#include "output/output_file.hpp"
#include "output/png_sinks.hpp"
#include "output/video_sinks.hpp"

namespace collide::output {
namespace fs = std::filesystem;
namespace {

bool endsWithNoCase(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  return std::equal(suffix.rbegin(), suffix.rend(), text.rbegin(), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) ==
           std::tolower(static_cast<unsigned char>(b));
  });
}

const char* const kFileAllowed =
    "allowed: a file path (a new or regular file, or a link to one), a character device, a FIFO, "
    "or - for stdout";

// The extension `path` names an output kind by, if any: ".mp4", ".webm", ".gif", ".png".
std::optional<OutputKind> kindOfExtension(const std::string& path) {
  for (const auto& [extension, kind] :
       {std::pair{".mp4", OutputKind::kMp4}, std::pair{".webm", OutputKind::kWebm},
        std::pair{".gif", OutputKind::kGif}, std::pair{".png", OutputKind::kPngStill}}) {
    if (endsWithNoCase(path, extension)) return kind;
  }
  return std::nullopt;
}

// Binary data on a terminal is noise and can upset it; every Unix tool that writes binary refuses.
void refuseTerminal(const std::string& what) {
  if (::isatty(STDOUT_FILENO) == 1) {
    throw core::InputError("-o: '-': standard output is a terminal, not a place for " + what +
                           "; allowed: redirect stdout to a file or a pipe, or give a file path");
  }
}

OutputTarget fileTarget(OutputKind kind, const std::string& path) {
  if (path == output::kStdoutName) {
    refuseTerminal(kindName(kind));
    return {kind, path, true};
  }
  checkOutputPath("-o", path);
  return {kind, path, output::placeOutput(path).route != output::OutputRoute::kReplace};
}

OutputTarget framesTarget(const std::string& path) {
  if (path == output::kStdoutName) {
    throw core::InputError(
        "-o: '-': PNG frames are many files and cannot go to stdout; allowed: a directory, or "
        "--format mp4, webm or gif for a video on stdout");
  }
  std::string directory = path;
  while (directory.size() > 1 && directory.back() == '/') directory.pop_back();
  requireParentDirectory("-o", directory);
  std::error_code error;
  if (fs::exists(directory, error) && !fs::is_directory(directory, error)) {
    throw core::InputError("-o: '" + path + "': '" + directory +
                           "' exists and is not a directory; allowed: a directory for PNG frames "
                           "(an existing one or a new path ending in '/')");
  }
  return {OutputKind::kPngFrames, directory, false};
}

}  // namespace

std::string kindName(OutputKind kind) {
  switch (kind) {
    case OutputKind::kMp4:
      return "MP4";
    case OutputKind::kWebm:
      return "WebM";
    case OutputKind::kGif:
      return "GIF";
    case OutputKind::kPngFrames:
      return "PNG frames";
    case OutputKind::kPngStill:
      return "PNG";
    case OutputKind::kSvgFigure:
      return "SVG";
    case OutputKind::kPdfFigure:
      return "PDF";
  }
  return "?";
}

void requireParentDirectory(const std::string& option, const std::string& path) {
  fs::path parent = fs::path(path).parent_path();
  if (parent.empty()) return;
  std::error_code error;
  if (!fs::is_directory(parent, error)) {
    throw core::InputError(option + ": '" + path + "': directory '" + parent.string() +
                           "' does not exist; allowed: a path in an existing directory");
  }
}

void checkOutputPath(const std::string& option, const std::string& path) {
  if (path == output::kStdoutName) return;
  requireParentDirectory(option, path);
  const output::OutputPlace place = output::placeOutput(path);
  if (place.route == output::OutputRoute::kRefused) {
    throw core::InputError(option + ": '" + path + "': is " + place.what + "; " + kFileAllowed);
  }
}

OutputTarget videoTarget(const std::string& path, const std::string& format) {
  const std::optional<OutputKind> named = kindOfExtension(path);
  if (!format.empty()) {
    const std::optional<OutputKind> chosen = format == "mp4"    ? std::optional{OutputKind::kMp4}
                                             : format == "webm" ? std::optional{OutputKind::kWebm}
                                             : format == "gif"  ? std::optional{OutputKind::kGif}
                                             : format == "frames"
                                                 ? std::optional{OutputKind::kPngFrames}
                                                 : std::nullopt;
    if (!chosen)
      throw core::InputError("--format: '" + format + "': allowed: mp4, webm, gif, frames");
    // A name that says one format and a --format that says another would leave a file whose
    // extension lies about its contents.
    if (named && *named != *chosen) {
      throw core::InputError("--format: '" + format + "': -o '" + path + "' ends in " +
                             fs::path(path).extension().string() + " (" + kindName(*named) +
                             "); allowed: --format matching the extension, or a path without "
                             ".mp4, .webm, .gif or .png");
    }
    if (*chosen == OutputKind::kPngFrames) return framesTarget(path);
    return fileTarget(*chosen, path);
  }
  if (path == output::kStdoutName) {
    throw core::InputError(
        "-o: '-': the format cannot be told from a name on stdout; allowed: add --format mp4, "
        "webm or gif");
  }
  std::error_code error;
  const bool directory = fs::is_directory(path, error);
  if (named && *named != OutputKind::kPngStill) {
    if (directory) {
      throw core::InputError("-o: '" + path + "': is a directory; allowed: a " + kindName(*named) +
                             " file path, or --format frames for PNG frames in it");
    }
    return fileTarget(*named, path);
  }
  if (!path.empty() && (path.back() == '/' || directory)) return framesTarget(path);
  // A device, FIFO or socket has no extension to go by: it receives MP4, the default video.
  if (!named && output::placeOutput(path).route == output::OutputRoute::kInPlace) {
    return fileTarget(OutputKind::kMp4, path);
  }
  if (endsWithNoCase(path, ".png") || endsWithNoCase(path, ".svg") ||
      endsWithNoCase(path, ".pdf")) {
    throw core::InputError("-o: '" + path +
                           "': render writes videos; a single picture comes from still, strobe "
                           "or chart; allowed: a .mp4, .webm or .gif file or a directory");
  }
  throw core::InputError(
      "-o: '" + path +
      "': unknown output kind; allowed: a .mp4 file (H.264), a .webm file (VP9), a "
      ".gif file, or a directory (an existing one or a path ending in '/') "
      "for PNG frames");
}

OutputTarget stillTarget(const std::string& path) {
  if (path == output::kStdoutName) return fileTarget(OutputKind::kPngStill, path);
  for (const auto& [extension, kind] :
       {std::pair{".svg", OutputKind::kSvgFigure}, std::pair{".pdf", OutputKind::kPdfFigure}}) {
    if (endsWithNoCase(path, extension)) return fileTarget(kind, path);
  }
  const std::optional<OutputKind> named = kindOfExtension(path);
  // A device, FIFO or socket has no extension to go by: PNG is the image kind.
  const bool in_place = !named && output::placeOutput(path).route == output::OutputRoute::kInPlace;
  if (named != OutputKind::kPngStill && !in_place) {
    throw core::InputError("-o: '" + path +
                           "': unknown image kind; allowed: a .png, .svg or .pdf file, a device, "
                           "a FIFO or - for stdout");
  }
  return fileTarget(OutputKind::kPngStill, path);
}

int vp9SpeedForPreset(const std::string& preset) {
  static const std::pair<const char*, int> kSpeeds[] = {
      {"ultrafast", 8}, {"superfast", 7}, {"veryfast", 6}, {"faster", 5},   {"fast", 4},
      {"medium", 3},    {"slow", 2},      {"slower", 1},   {"veryslow", 0}, {"placebo", 0}};
  for (const auto& [name, speed] : kSpeeds) {
    if (preset == name) return speed;
  }
  return 6;
}

std::string besidePath(const std::string& path, const std::string& extension) {
  return fs::path(path).replace_extension(extension).string();
}

std::unique_ptr<output::FrameSink> makeSink(const OutputTarget& target, SinkSettings settings) {
  switch (target.kind) {
    case OutputKind::kMp4: {
      output::VideoSinkRequest request;
      request.format = output::VideoFormat::kMp4;
      request.path = target.path;
      if (settings.quality) request.mp4.crf = *settings.quality;
      request.mp4.preset = settings.preset;
      request.mp4.threads = settings.encoder_threads;
      request.extras = std::move(settings.extras);
      return output::makeVideoSink(std::move(request));
    }
    case OutputKind::kWebm: {
      output::VideoSinkRequest request;
      request.format = output::VideoFormat::kWebm;
      request.path = target.path;
      if (settings.quality) request.webm.crf = *settings.quality;
      request.webm.speed = vp9SpeedForPreset(settings.preset);
      request.webm.alpha = settings.transparent;
      request.extras = std::move(settings.extras);
      return output::makeVideoSink(std::move(request));
    }
    case OutputKind::kGif: {
      output::VideoSinkRequest request;
      request.format = output::VideoFormat::kGif;
      request.path = target.path;
      request.gif.transparency = settings.transparent;
      return output::makeVideoSink(std::move(request));
    }
    case OutputKind::kPngFrames:
      return std::make_unique<output::PngSequenceSink>(target.path, std::move(settings.png_text));
    case OutputKind::kPngStill:
      return std::make_unique<output::PngStillSink>(target.path, std::move(settings.png_text),
                                                    settings.png_dpi, settings.png_threads);
    case OutputKind::kSvgFigure:
    case OutputKind::kPdfFigure:
      break;
  }
  COLLIDE_ASSERT(false, "unhandled output kind");
}

}  // namespace collide::output
