#pragma once
// Private: what turns a FrameModel into pixels behind render::Renderer. The GL implementation
// (render/gl/gl_rasterizer.cpp) links libOSMesa or libOpenGL, and libOSMesa pulls in LLVM: loading
// it costs most of a `collide presets` (bench/results.md). So the program reaches it through a
// module, collide-gl.so, opened the first time a picture is drawn (rasterizer_module.cpp), while
// the renderer's own tests link it directly (rasterizer_direct.cpp). Exactly one of those two files
// is linked into any binary.
#include <memory>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "frame/frame_model.hpp"
#include "render/backend.hpp"
#include "render/gl_context.hpp"
#include "render/renderer_options.hpp"

namespace collide::render {

class FrameRasterizer {
 public:
  virtual ~FrameRasterizer() = default;
  // See Renderer::render().
  virtual core::ImageView render(const frame::FrameModel& frame) = 0;
  // See Renderer::changedRects().
  virtual const std::vector<core::ImageRect>* changedRects() const = 0;
  virtual std::string glRendererName() const = 0;
};

// Draws with OpenGL in `context`. options.font_path must be set (the caller resolves the default:
// the module has its own copy of the process-wide font choice).
std::unique_ptr<FrameRasterizer> makeGlRasterizer(std::unique_ptr<GlContext> context, int width_px,
                                                  int height_px, const RendererOptions& options);

// `options` with the process-wide default font (defaultFontPath()) filled in when none is given.
RendererOptions withDefaultFont(RendererOptions options);

// A rasterizer on a context of `backend` (never kAuto's own choice: createContext resolves it).
// Throws RenderError when no context can be made or the module cannot be loaded.
std::unique_ptr<FrameRasterizer> makeRasterizer(Backend backend, int width_px, int height_px,
                                                const RendererOptions& options);

// The module's entry point, looked up by its C name. Returns a rasterizer allocated with new;
// errors travel as exceptions (the module and the program share libstdc++).
using MakeRasterizerEntry = FrameRasterizer* (*)(Backend backend, int width_px, int height_px,
                                                 const RendererOptions& options);
inline constexpr const char* kMakeRasterizerSymbol = "collide_make_rasterizer";

}  // namespace collide::render
