#pragma once
// Choosing a GL backend. OSMesa is the default; EGL surfaceless runs the same llvmpipe renderer
// (same pixels) on Mesa builds without OSMesa (removed in Mesa 25.1); the EGL device platform
// reaches a GPU when one is present.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/gl_context.hpp"

namespace collide::render {

enum class Backend {
  kOsmesa,  // libOSMesa, software (llvmpipe)
  kEgl,     // EGL_PLATFORM_SURFACELESS_MESA, software (llvmpipe): the same pixels as OSMesa
  kGpu,     // EGL_PLATFORM_DEVICE_EXT on a hardware device (e.g. NVIDIA): fast, pixels may differ
  kAuto,    // the first that works of kGpu, kEgl, kOsmesa
};

// "osmesa", "egl", "gpu", "auto".
std::string backendName(Backend backend);
// Parses a name accepted by backendName(); std::nullopt for anything else.
std::optional<Backend> parseBackend(const std::string& name);
// Backends compiled into this build, in the order `auto` tries them.
std::vector<Backend> compiledBackends();

// Creates a context for `backend` and makes it current. Throws RenderError naming the backend
// and the reason when it cannot.
std::unique_ptr<GlContext> createContext(Backend backend);

// The backend Renderer(width, height) uses: the one set by setDefaultBackend() (the CLI's
// --backend), else $COLLIDE_BACKEND if set (lets CI run every GL test on each backend), else
// OSMesa when compiled in, else EGL. Throws RenderError for an invalid $COLLIDE_BACKEND.
Backend defaultBackend();
void setDefaultBackend(Backend backend);

// EGL contexts; each throws RenderError when unavailable (no EGL, no suitable device).
std::unique_ptr<GlContext> createEglSurfacelessContext();
std::unique_ptr<GlContext> createEglDeviceContext();

}  // namespace collide::render
