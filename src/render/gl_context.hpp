#pragma once
// A current OpenGL 3.3+ core context with no window. Backends (OSMesa now, EGL later) implement
// this; drawing code only needs a live context and renders into its own framebuffer object.
#include <memory>
#include <string>

#include "render/errors.hpp"

namespace collide::render {

class GlContext {
 public:
  virtual ~GlContext() = default;
  virtual void makeCurrent() = 0;
  virtual std::string backendName() const = 0;  // "osmesa", "egl-surfaceless", ...
};

// Creates an OSMesa core-profile context. Throws RenderError on failure.
std::unique_ptr<GlContext> createOsmesaContext();

}  // namespace collide::render
