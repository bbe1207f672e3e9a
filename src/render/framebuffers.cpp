#include "render/framebuffers.hpp"

#include <algorithm>
#include <string>

#include "render/gl.hpp"
#include "render/gl_check.hpp"
#include "render/gl_context.hpp"

namespace collide::render {
namespace {

void attachColorRenderbuffer(GLuint fbo, GLuint renderbuffer, int samples, int w, int h) {
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
  if (samples > 1) {
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, w, h);
  } else {
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffer);
}

}  // namespace

Framebuffers::Framebuffers(int width_px, int height_px)
    : width_px_(width_px), height_px_(height_px) {
  const std::string size = std::to_string(width_px) + "x" + std::to_string(height_px);
  GLint max_renderbuffer = 0, max_samples = 0;
  GLint max_viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_renderbuffer);
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max_viewport);
  if (width_px > max_renderbuffer || height_px > max_renderbuffer || width_px > max_viewport[0] ||
      height_px > max_viewport[1]) {
    throw RenderError("frame size " + size + " exceeds the OpenGL limit of " +
                      std::to_string(std::min(max_renderbuffer, max_viewport[0])) + " pixels");
  }
  if (max_samples < kSamples) {
    throw RenderError("OpenGL offers " + std::to_string(max_samples) +
                      " samples per pixel; the renderer needs " + std::to_string(kSamples));
  }

  glGenFramebuffers(1, &multisample_fbo_);
  glGenRenderbuffers(1, &multisample_color_);
  glGenFramebuffers(1, &resolve_fbo_);
  glGenRenderbuffers(1, &resolve_color_);
  attachColorRenderbuffer(multisample_fbo_, multisample_color_, kSamples, width_px, height_px);
  checkGl("allocating the " + size + " multisampled framebuffer");
  checkFramebufferComplete(GL_FRAMEBUFFER, "multisampled " + size + " framebuffer");
  attachColorRenderbuffer(resolve_fbo_, resolve_color_, 1, width_px, height_px);
  checkGl("allocating the " + size + " resolve framebuffer");
  checkFramebufferComplete(GL_FRAMEBUFFER, "resolve " + size + " framebuffer");
}

Framebuffers::~Framebuffers() {
  glDeleteFramebuffers(1, &resolve_fbo_);
  glDeleteRenderbuffers(1, &resolve_color_);
  glDeleteFramebuffers(1, &multisample_fbo_);
  glDeleteRenderbuffers(1, &multisample_color_);
}

void Framebuffers::bindForDrawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, multisample_fbo_);
  glViewport(0, 0, width_px_, height_px_);
}

void Framebuffers::resolveAndRead(std::vector<std::uint8_t>& pixels) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, multisample_fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
  glBlitFramebuffer(0, 0, width_px_, height_px_, 0, 0, width_px_, height_px_, GL_COLOR_BUFFER_BIT,
                    GL_NEAREST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_);
  pixels.resize(static_cast<std::size_t>(width_px_) * height_px_ * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_px_, height_px_, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  checkGl("reading back the rendered frame");
}

}  // namespace collide::render
