// Frames drawn by the module collide-gl.so, opened the first time a picture is drawn (see
// render/gl/frame_rasterizer.hpp): `presets`, `check` and `data` never map libOSMesa and LLVM.
#include <mutex>
#include <string>
#include <vector>

#include "core/module_loader.hpp"
#include "render/gl/frame_rasterizer.hpp"

namespace collide::render {
namespace {

constexpr const char* kModuleFile = "collide-gl.so";

std::mutex module_mutex;
MakeRasterizerEntry make_entry = nullptr;  // guarded by module_mutex; set once, never cleared

MakeRasterizerEntry loadModule() {
  std::vector<std::string> built_in;
#ifdef COLLIDE_GL_MODULE_INSTALLED
  built_in.emplace_back(COLLIDE_GL_MODULE_INSTALLED);
#endif
#ifdef COLLIDE_GL_MODULE_BUILT
  built_in.emplace_back(COLLIDE_GL_MODULE_BUILT);
#endif
  std::string error;
  void* entry = core::loadModuleSymbol(kModuleFile, kMakeRasterizerSymbol, built_in, error);
  if (entry == nullptr) throw RenderError("cannot draw pictures: " + error);
  return reinterpret_cast<MakeRasterizerEntry>(entry);
}

}  // namespace

std::unique_ptr<FrameRasterizer> makeRasterizer(Backend backend, int width_px, int height_px,
                                                const RendererOptions& options) {
  MakeRasterizerEntry entry = nullptr;
  {
    const std::lock_guard<std::mutex> lock(module_mutex);
    if (make_entry == nullptr) make_entry = loadModule();
    entry = make_entry;
  }
  return std::unique_ptr<FrameRasterizer>(entry(backend, width_px, height_px, options));
}

}  // namespace collide::render
