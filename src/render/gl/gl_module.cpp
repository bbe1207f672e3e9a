// The entry point of collide-gl.so, the module that holds everything linked to OpenGL (libOSMesa
// and its LLVM, libEGL): see render/gl/frame_rasterizer.hpp.
#include <type_traits>

#include "render/gl/frame_rasterizer.hpp"

extern "C" __attribute__((visibility("default"))) collide::render::FrameRasterizer*
collide_make_rasterizer(collide::render::Backend backend, int width_px, int height_px,
                        const collide::render::RendererOptions& options) {
  using namespace collide::render;
  static_assert(std::is_same_v<decltype(&collide_make_rasterizer), MakeRasterizerEntry>);
  return makeRasterizer(backend, width_px, height_px, options).release();
}
