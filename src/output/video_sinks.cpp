#include "output/video_sinks.hpp"

#include <mutex>
#include <string>
#include <vector>

#include "core/module_loader.hpp"

namespace collide::output {
namespace {

constexpr const char* kModuleFile = "collide-video.so";

std::mutex module_mutex;
MakeVideoSinkEntry make_entry = nullptr;  // guarded by module_mutex; set once, never cleared
CodecLogLevel log_level = CodecLogLevel::kErrors;

MakeVideoSinkEntry loadModule() {
  std::vector<std::string> built_in;
#ifdef COLLIDE_VIDEO_MODULE_INSTALLED
  built_in.emplace_back(COLLIDE_VIDEO_MODULE_INSTALLED);
#endif
#ifdef COLLIDE_VIDEO_MODULE_BUILT
  built_in.emplace_back(COLLIDE_VIDEO_MODULE_BUILT);
#endif
  std::string error;
  void* entry = core::loadModuleSymbol(kModuleFile, kMakeVideoSinkSymbol, built_in, error);
  if (entry == nullptr) throw OutputError("cannot write video: " + error);
  return reinterpret_cast<MakeVideoSinkEntry>(entry);
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
