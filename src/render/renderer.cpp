// The Renderer facade: GL-free, so that the program links it without OpenGL; the drawing happens
// in a FrameRasterizer (render/gl/frame_rasterizer.hpp).
#include "render/renderer.hpp"

#include <utility>

#include "render/gl/frame_rasterizer.hpp"
#include "render/text/text_metrics.hpp"

namespace collide::render {

// Resolved on the program's side: the module keeps its own copy of the process-wide font choice
// and of the active language.
RendererOptions withDefaultFont(RendererOptions options) {
  if (options.font_path.empty()) options.font_path = defaultFontPath();
  if (options.text_fonts.files.empty()) options.text_fonts = textFontsFor(options.font_path);
  return options;
}

Renderer::Renderer(int width_px, int height_px, const RendererOptions& options)
    : Renderer(defaultBackend(), width_px, height_px, options) {}

Renderer::Renderer(Backend backend, int width_px, int height_px, const RendererOptions& options)
    : Renderer(makeRasterizer(backend, width_px, height_px, withDefaultFont(options)), width_px,
               height_px) {}

Renderer::Renderer(std::unique_ptr<FrameRasterizer> rasterizer, int width_px, int height_px)
    : rasterizer_(std::move(rasterizer)), width_px_(width_px), height_px_(height_px) {
  COLLIDE_ASSERT(width_px > 0 && height_px > 0, "frame size must be positive (validate input)");
}

Renderer::~Renderer() = default;

core::ImageView Renderer::render(const frame::FrameModel& frame) {
  return rasterizer_->render(frame);
}

const std::vector<core::ImageRect>* Renderer::changedRects() const {
  return rasterizer_->changedRects();
}

int Renderer::width_px() const {
  return width_px_;
}
int Renderer::height_px() const {
  return height_px_;
}
std::string Renderer::glRendererName() const {
  return rasterizer_->glRendererName();
}

}  // namespace collide::render
