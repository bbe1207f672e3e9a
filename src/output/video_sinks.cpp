#include "output/video_sinks.hpp"

#include <dlfcn.h>

#include <mutex>
#include <string>
#include <system_error>
#include <vector>

namespace collide::output {
namespace {

namespace fs = std::filesystem;

constexpr const char* kModuleFile = "collide-video.so";

std::mutex module_mutex;
MakeVideoSinkEntry make_entry = nullptr;  // guarded by module_mutex; set once, never cleared
CodecLogLevel log_level = CodecLogLevel::kErrors;

// Beside the program (the build tree, a relocated install), in ../lib/collide (an install
// prefix), where `make install` puts it, and where this build wrote it (tests running in-process
// from their own folders).
std::vector<fs::path> moduleCandidates() {
  std::vector<fs::path> candidates;
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    candidates.push_back(program.parent_path() / kModuleFile);
    candidates.push_back(program.parent_path() / ".." / "lib" / "collide" / kModuleFile);
  }
#ifdef COLLIDE_VIDEO_MODULE_INSTALLED
  candidates.emplace_back(COLLIDE_VIDEO_MODULE_INSTALLED);
#endif
#ifdef COLLIDE_VIDEO_MODULE_BUILT
  candidates.emplace_back(COLLIDE_VIDEO_MODULE_BUILT);
#endif
  return candidates;
}

MakeVideoSinkEntry loadModule() {
  std::string tried;
  for (const fs::path& candidate : moduleCandidates()) {
    std::error_code error;
    if (!fs::exists(candidate, error)) {
      tried += (tried.empty() ? "" : ", ") + candidate.string();
      continue;
    }
    // Never closed: sinks made by it may live until the process ends. Global, so that libav's
    // symbols are found like a linked library's (an LD_PRELOAD wrapper's RTLD_NEXT sees them);
    // the module itself exports nothing else.
    void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (handle == nullptr) {
      throw OutputError("cannot load the video module '" + candidate.string() + "': " + dlerror());
    }
    auto* entry = reinterpret_cast<MakeVideoSinkEntry>(dlsym(handle, kMakeVideoSinkSymbol));
    if (entry == nullptr) {
      throw OutputError("the video module '" + candidate.string() + "' has no " +
                        kMakeVideoSinkSymbol);
    }
    return entry;
  }
  throw OutputError(std::string("cannot write video: the video module ") + kModuleFile +
                    " is not installed (looked for " + tried + ")");
}

}  // namespace

std::unique_ptr<FrameSink> makeVideoSink(VideoSinkRequest request) {
  MakeVideoSinkEntry entry = nullptr;
  CodecLogLevel level{};
  {
    const std::lock_guard<std::mutex> lock(module_mutex);
    if (make_entry == nullptr) make_entry = loadModule();
    entry = make_entry;
    level = log_level;
  }
  return std::unique_ptr<FrameSink>(entry(request, level));
}

void setVideoLogLevel(CodecLogLevel level) {
  const std::lock_guard<std::mutex> lock(module_mutex);
  log_level = level;
}

bool videoModuleLoaded() {
  const std::lock_guard<std::mutex> lock(module_mutex);
  return make_entry != nullptr;
}

}  // namespace collide::output
