#include "render/gl/gl_check.hpp"

#include "render/gl/gl.hpp"
#include "render/gl_context.hpp"

namespace collide::render {
namespace {

const char* glErrorName(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    default:
      return "unknown GL error";
  }
}

const char* framebufferStatusName(GLenum status) {
  switch (status) {
    case GL_FRAMEBUFFER_UNDEFINED:
      return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_UNSUPPORTED:
      return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
      return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    default:
      return "unknown framebuffer status";
  }
}

}  // namespace

void checkGl(const std::string& what) {
  const GLenum first = glGetError();
  if (first == GL_NO_ERROR) return;
  // Drain the remaining flags so the next check starts clean.
  while (glGetError() != GL_NO_ERROR) {
  }
  throw RenderError(what + ": OpenGL reported " + glErrorName(first));
}

void checkFramebufferComplete(unsigned target, const std::string& what) {
  const GLenum status = glCheckFramebufferStatus(target);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw RenderError(what + ": framebuffer incomplete (" + framebufferStatusName(status) + ")");
  }
}

}  // namespace collide::render
