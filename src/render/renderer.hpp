#pragma once
// Draws FrameModels (analytically anti-aliased shapes and FreeType text from a glyph atlas) into
// the project's own single-sample framebuffer and reads the pixels back. Where each thing lands in
// pixels (panels, scene areas, energy bars, segment edges): frame/layout.hpp.
#include <memory>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/image.hpp"
#include "frame/frame_model.hpp"
#include "render/backend.hpp"
#include "render/errors.hpp"
#include "render/gl_context.hpp"
#include "render/renderer_options.hpp"
#include "render/text/text_metrics.hpp"

namespace collide::render {

class FrameRasterizer;  // render/gl/frame_rasterizer.hpp

class Renderer {
 public:
  // Draws on a context of defaultBackend() (render/backend.hpp). Throws RenderError if no GL 3.3
  // context can be made or the size exceeds GL limits (16384 px on llvmpipe), FontError if the
  // font cannot be loaded, core::InputError if the language's font is not installed. Sizes must be
  // > 0: the caller validates user input first (a non-positive size is an assertion failure).
  Renderer(int width_px, int height_px, const RendererOptions& options = {});
  // The same on a context of `backend` (kAuto: the first that works).
  Renderer(Backend backend, int width_px, int height_px, const RendererOptions& options = {});
  // On a context the caller made. Only in binaries that link the GL renderer itself
  // (collide_render: the renderer's tests); the program draws through the collide-gl.so module
  // instead.
  Renderer(std::unique_ptr<GlContext> context, int width_px, int height_px,
           const RendererOptions& options = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Renders one frame. The returned view runs bottom-up (negative stride) and stays valid, its
  // pixels unchanged, until the second call to render() after this one (frames are read back into
  // two buffers in turn, so one may be converted while the next is drawn) or the renderer's
  // destruction.
  core::ImageView render(const frame::FrameModel& frame);
  // The rectangles (apart) outside which the frame render() returned last equals the one it
  // returned before, or nullptr where any pixel may differ (the first frame, a frame drawn
  // whole). Valid until the next render(). A video's converter redoes only these.
  const std::vector<core::ImageRect>* changedRects() const;

  int width_px() const;
  int height_px() const;
  std::string glRendererName() const;  // GL_RENDERER of the live context, e.g. "llvmpipe (...)"

 private:
  Renderer(std::unique_ptr<FrameRasterizer> rasterizer, int width_px, int height_px);

  std::unique_ptr<FrameRasterizer> rasterizer_;
  int width_px_;
  int height_px_;
};

}  // namespace collide::render
