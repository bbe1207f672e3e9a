#pragma once
// Draws FrameModels into the project's own multisampled framebuffer and reads the pixels back.
// Where each thing lands in pixels (scene area, energy bar, segment edges): render/layout.hpp.
#include <memory>
#include <string>

#include "core/error.hpp"
#include "core/image.hpp"
#include "render/frame_model.hpp"
#include "render/gl_context.hpp"

namespace collide::render {

class Renderer {
 public:
  // Creates the default (OSMesa) context. Throws RenderError if no GL 3.3 context can be made or
  // the size exceeds GL limits (16384 px on llvmpipe). Sizes must be > 0: the caller validates
  // user input first (a non-positive size is an assertion failure).
  Renderer(int width_px, int height_px);
  Renderer(std::unique_ptr<GlContext> context, int width_px, int height_px);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Renders one frame. The returned view runs bottom-up (negative stride) and stays valid until the
  // next call to render() or the renderer's destruction.
  core::ImageView render(const FrameModel& frame);

  int width_px() const;
  int height_px() const;
  std::string glRendererName() const;  // GL_RENDERER of the live context, e.g. "llvmpipe (...)"

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace collide::render
