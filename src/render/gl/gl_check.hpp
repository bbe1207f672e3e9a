#pragma once
// Private: turns pending GL errors into RenderError. Call after each group of GL calls that can
// fail for reasons outside the program (allocation, limits), naming what was being done.
#include <string>

namespace collide::render {

// Throws RenderError("<what>: GL error GL_OUT_OF_MEMORY ...") if glGetError reports anything.
void checkGl(const std::string& what);

// Throws RenderError if the framebuffer bound to `target` is not complete.
void checkFramebufferComplete(unsigned target, const std::string& what);

}  // namespace collide::render
