#include "render/backend.hpp"

#include "render/gl/mesa_shader_cache.hpp"

namespace collide::render {

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
  switchOffAnUnusableShaderCache();  // before Mesa starts: it reads its environment then
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

}  // namespace collide::render
