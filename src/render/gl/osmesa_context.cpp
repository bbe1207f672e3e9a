// OSMesa backend of GlContext: a core-profile context drawing into a tiny client buffer. Nothing
// is drawn into that buffer; the renderer uses its own framebuffer objects, so its size is moot.
#include <GL/osmesa.h>

#include <array>
#include <cstdint>

#include "render/gl/gl.hpp"
#include "render/gl_context.hpp"

namespace collide::render {
namespace {

constexpr int kBufferSidePx = 1;  // OSMesa needs some buffer to make a context current

class OsmesaContext final : public GlContext {
 public:
  OsmesaContext() {
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              0,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_ACCUM_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context_ == nullptr) {
      throw RenderError(
          "osmesa: cannot create an OpenGL 3.3 core context (is libosmesa6 from Mesa >= 20 "
          "installed?)");
    }
    makeCurrent();
  }

  ~OsmesaContext() override { OSMesaDestroyContext(context_); }

  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  void makeCurrent() override {
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kBufferSidePx,
                           kBufferSidePx)) {
      throw RenderError("osmesa: cannot make the OpenGL context current");
    }
  }

  std::string backendName() const override { return "osmesa"; }

 private:
  OSMesaContext context_ = nullptr;
  std::array<std::uint8_t, 4 * kBufferSidePx * kBufferSidePx> buffer_{};  // RGBA8
};

}  // namespace

std::unique_ptr<GlContext> createOsmesaContext() {
  return std::make_unique<OsmesaContext>();
}

}  // namespace collide::render
