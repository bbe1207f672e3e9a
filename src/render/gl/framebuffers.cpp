#include "render/gl/framebuffers.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"
#include "render/gl/gl.hpp"
#include "render/gl/gl_check.hpp"
#include "render/gl_context.hpp"

namespace collide::render {

Framebuffers::Framebuffers(int width_px, int height_px)
    : width_px_(width_px), height_px_(height_px) {
  const std::string size = std::to_string(width_px) + "x" + std::to_string(height_px);
  GLint max_renderbuffer = 0;
  GLint max_viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_renderbuffer);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max_viewport);
  if (width_px > max_renderbuffer || height_px > max_renderbuffer || width_px > max_viewport[0] ||
      height_px > max_viewport[1]) {
    throw RenderError("frame size " + size + " exceeds the OpenGL limit of " +
                      std::to_string(std::min(max_renderbuffer, max_viewport[0])) + " pixels");
  }
  glGenFramebuffers(1, &fbo_);
  glGenRenderbuffers(1, &color_);
  glBindRenderbuffer(GL_RENDERBUFFER, color_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_px, height_px);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
  checkGl("allocating the " + size + " framebuffer");
  checkFramebufferComplete(GL_FRAMEBUFFER, size + " framebuffer");
}

Framebuffers::~Framebuffers() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &color_);
}

void Framebuffers::bindForDrawing() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_px_, height_px_);
}

void Framebuffers::read(std::vector<std::uint8_t>& pixels) const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  pixels.resize(static_cast<std::size_t>(width_px_) * height_px_ * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_px_, height_px_, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  checkGl("reading back the rendered frame");
}

void Framebuffers::readRect(std::vector<std::uint8_t>& pixels, int x, int first_row, int width,
                            int height) const {
  COLLIDE_ASSERT(pixels.size() == static_cast<std::size_t>(width_px_) * height_px_ * 4,
                 "Framebuffers::readRect: the buffer holds a whole frame");
  COLLIDE_ASSERT(x >= 0 && width >= 0 && x + width <= width_px_ && first_row >= 0 && height >= 0 &&
                     first_row + height <= height_px_,
                 "Framebuffers::readRect: a rectangle inside the frame");
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  // Rows land a whole frame's row apart, each at its own place.
  glPixelStorei(GL_PACK_ROW_LENGTH, width_px_);
  glReadPixels(x, first_row, width, height, GL_RGBA, GL_UNSIGNED_BYTE,
               pixels.data() + (static_cast<std::size_t>(first_row) * width_px_ + x) * 4);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  checkGl("reading back the rendered frame's changed pixels");
}

}  // namespace collide::render
