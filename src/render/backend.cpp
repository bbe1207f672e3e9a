#include "render/backend.hpp"

#include <cstdlib>

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

// One backend, no fallback. Errors read "<backend>: <reason>".
std::unique_ptr<GlContext> createSingleContext(Backend backend) {
  switch (backend) {
    case Backend::kOsmesa:
#ifdef COLLIDE_HAVE_OSMESA
      return createOsmesaContext();
#else
      throw RenderError("osmesa: this build has no OSMesa");
#endif
    case Backend::kEgl:
      return createEglSurfacelessContext();
    case Backend::kGpu:
      return createEglDeviceContext();
    case Backend::kAuto:
      break;
  }
  throw RenderError("unknown backend");
}

// "; try --backend egl or --backend auto": the software backends of this build other than
// `failed` (a GPU is rarely the way out when software rendering failed), then auto.
std::string alternativesTo(Backend failed) {
  std::string advice;
  for (Backend other : compiledBackends()) {
    if (other == failed || other == Backend::kGpu) continue;
    advice += (advice.empty() ? "; try --backend " : " or --backend ") + backendName(other);
  }
  return advice + (advice.empty() ? "; try --backend " : " or --backend ") + "auto";
}

}  // namespace

std::unique_ptr<GlContext> createContext(Backend backend) {
  if (backend != Backend::kAuto) {
    try {
      return createSingleContext(backend);
    } catch (const RenderError& e) {
      throw RenderError(std::string("GL backend ") + e.what() + alternativesTo(backend));
    }
  }
  std::string reasons;
  for (Backend candidate : compiledBackends()) {
    try {
      return createSingleContext(candidate);
    } catch (const RenderError& e) {
      reasons += std::string(reasons.empty() ? "" : "; ") + e.what();
    }
  }
  throw RenderError("GL backend auto: no backend works (" + reasons +
                    "); install Mesa's libegl-mesa0 or libosmesa6");
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
