// Backend names and the process-wide choice: GL-free, so the program decides which backend to ask
// the collide-gl.so module for without loading it (render/gl/frame_rasterizer.hpp).
#include <cstdlib>

#include "render/backend.hpp"

namespace collide::render {

std::string backendName(Backend backend) {
  switch (backend) {
    case Backend::kOsmesa:
      return "osmesa";
    case Backend::kEgl:
      return "egl";
    case Backend::kGpu:
      return "gpu";
    case Backend::kAuto:
      return "auto";
  }
  return "?";
}

std::optional<Backend> parseBackend(const std::string& name) {
  for (Backend b : {Backend::kOsmesa, Backend::kEgl, Backend::kGpu, Backend::kAuto}) {
    if (backendName(b) == name) return b;
  }
  return std::nullopt;
}

std::vector<Backend> compiledBackends() {
  std::vector<Backend> backends{Backend::kGpu, Backend::kEgl};
#ifdef COLLIDE_HAVE_OSMESA
  backends.push_back(Backend::kOsmesa);
#endif
  return backends;
}

namespace {
std::optional<Backend> chosen_backend;  // process-wide choice of the command line
}  // namespace

void setDefaultBackend(Backend backend) {
  chosen_backend = backend;
}

Backend defaultBackend() {
  if (chosen_backend) return *chosen_backend;
  if (const char* name = std::getenv("COLLIDE_BACKEND"); name != nullptr && *name != '\0') {
    if (std::optional<Backend> backend = parseBackend(name)) return *backend;
    throw RenderError(std::string("COLLIDE_BACKEND: '") + name +
                      "': allowed: osmesa, egl, gpu, auto");
  }
#ifdef COLLIDE_HAVE_OSMESA
  return Backend::kOsmesa;
#else
  return Backend::kEgl;
#endif
}

}  // namespace collide::render
