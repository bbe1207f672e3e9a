#include "app/output_target.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/error.hpp"
#include "output/png_sinks.hpp"
#include "output/video_sinks.hpp"

namespace collide::app {
namespace fs = std::filesystem;
namespace {

bool endsWithNoCase(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  return std::equal(suffix.rbegin(), suffix.rend(), text.rbegin(), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) ==
           std::tolower(static_cast<unsigned char>(b));
  });
}

OutputTarget framesTarget(const std::string& path) {
  std::string directory = path;
  while (directory.size() > 1 && directory.back() == '/') directory.pop_back();
  requireParentDirectory("-o", directory);
  return {OutputKind::kPngFrames, directory};
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

OutputTarget videoTarget(const std::string& path, const std::string& format) {
  if (!format.empty()) {
    if (format == "frames") return framesTarget(path);
    const OutputKind kind = format == "mp4"    ? OutputKind::kMp4
                            : format == "webm" ? OutputKind::kWebm
                            : format == "gif"  ? OutputKind::kGif
                                               : OutputKind::kPngStill;
    if (kind == OutputKind::kPngStill) {
      throw core::InputError("--format: '" + format + "': allowed: mp4, webm, gif, frames");
    }
    requireParentDirectory("-o", path);
    return {kind, path};
  }
  std::error_code error;
  if (!path.empty() && (path.back() == '/' || fs::is_directory(path, error))) {
    return framesTarget(path);
  }
  for (const auto& [extension, kind] :
       {std::pair{".mp4", OutputKind::kMp4}, std::pair{".webm", OutputKind::kWebm},
        std::pair{".gif", OutputKind::kGif}}) {
    if (endsWithNoCase(path, extension)) {
      requireParentDirectory("-o", path);
      return {kind, path};
    }
  }
  throw core::InputError(
      "-o: '" + path +
      "': unknown output kind; allowed: a .mp4 file (H.264), a .webm file (VP9), a "
      ".gif file, or a directory (an existing one or a path ending in '/') "
      "for PNG frames");
}

OutputTarget stillTarget(const std::string& path) {
  if (!endsWithNoCase(path, ".png")) {
    throw core::InputError("-o: '" + path + "': unknown image kind; allowed: a .png file");
  }
  requireParentDirectory("-o", path);
  return {OutputKind::kPngStill, path};
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
      return std::make_unique<output::PngStillSink>(target.path, std::move(settings.png_text));
  }
  COLLIDE_ASSERT(false, "unhandled output kind");
}

}  // namespace collide::app
