#include "app/output_target.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/error.hpp"
#include "output/mp4_sink.hpp"
#include "output/png_sinks.hpp"

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

}  // namespace

void requireParentDirectory(const std::string& option, const std::string& path) {
  fs::path parent = fs::path(path).parent_path();
  if (parent.empty()) return;
  std::error_code error;
  if (!fs::is_directory(parent, error)) {
    throw core::InputError(option + ": '" + path + "': directory '" + parent.string() +
                           "' does not exist; allowed: a path in an existing directory");
  }
}

OutputTarget videoTarget(const std::string& path) {
  std::error_code error;
  if (!path.empty() && (path.back() == '/' || fs::is_directory(path, error))) {
    std::string directory = path;
    while (directory.size() > 1 && directory.back() == '/') directory.pop_back();
    requireParentDirectory("-o", directory);
    return {OutputKind::kPngFrames, directory};
  }
  if (endsWithNoCase(path, ".mp4")) {
    requireParentDirectory("-o", path);
    return {OutputKind::kMp4, path};
  }
  throw core::InputError("-o: '" + path +
                         "': unknown output kind; allowed: a .mp4 file, or a directory (an "
                         "existing one or a path ending in '/') for PNG frames");
}

OutputTarget stillTarget(const std::string& path) {
  if (!endsWithNoCase(path, ".png")) {
    throw core::InputError("-o: '" + path + "': unknown image kind; allowed: a .png file");
  }
  requireParentDirectory("-o", path);
  return {OutputKind::kPngStill, path};
}

std::unique_ptr<output::FrameSink> makeSink(const OutputTarget& target) {
  switch (target.kind) {
    case OutputKind::kMp4:
      return std::make_unique<output::Mp4Sink>(target.path, output::Mp4Options{});
    case OutputKind::kPngFrames:
      return std::make_unique<output::PngSequenceSink>(target.path);
    case OutputKind::kPngStill:
      return std::make_unique<output::PngStillSink>(target.path);
  }
  COLLIDE_ASSERT(false, "unhandled output kind");
}

}  // namespace collide::app
