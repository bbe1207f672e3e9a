// Frames drawn by the GL code linked into this binary: the renderer's own tests and the
// collide-gl.so module itself (see render/gl/frame_rasterizer.hpp).
#include <utility>

#include "render/gl/frame_rasterizer.hpp"
#include "render/renderer.hpp"

namespace collide::render {

std::unique_ptr<FrameRasterizer> makeRasterizer(Backend backend, int width_px, int height_px,
                                                const RendererOptions& options) {
  return makeGlRasterizer(createContext(backend), width_px, height_px, options);
}

Renderer::Renderer(std::unique_ptr<GlContext> context, int width_px, int height_px,
                   const RendererOptions& options)
    : Renderer(makeGlRasterizer(std::move(context), width_px, height_px, withDefaultFont(options)),
               width_px, height_px) {}

}  // namespace collide::render
