#pragma once
// Which kind of output a path asks for, decided by the app from the path alone (sinks never
// choose).
#include <memory>
#include <string>

#include "output/frame_sink.hpp"

namespace collide::app {

enum class OutputKind {
  kMp4,        // "*.mp4": H.264 video
  kPngFrames,  // an existing directory or a path ending in '/': frame_00000.png, ...
  kPngStill,   // "*.png": one image
};

struct OutputTarget {
  OutputKind kind;
  std::string path;
};

// Classifies `path` for `collide render` (video or frames). Throws core::InputError for an unknown
// extension or a missing parent directory.
OutputTarget videoTarget(const std::string& path);

// Checks `path` for `collide still` (must end in .png, parent directory must exist).
OutputTarget stillTarget(const std::string& path);

// Throws core::InputError, naming `option`, when the directory that would hold `path` is missing.
void requireParentDirectory(const std::string& option, const std::string& path);

// The sink that writes `target`.
std::unique_ptr<output::FrameSink> makeSink(const OutputTarget& target);

}  // namespace collide::app
