// EGL backends of GlContext, both without any surface (EGL_KHR_surfaceless_context): the renderer
// draws into its own framebuffer objects. Surfaceless = Mesa's llvmpipe, the same rasteriser as
// OSMesa; device = a hardware GPU found through EGL_EXT_device_enumeration.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <string>

#include "render/backend.hpp"

namespace collide::render {
namespace {

std::string hex(EGLint code) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%04x", static_cast<unsigned>(code));
  return text;
}

bool hasExtension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t length = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += length) {
    const bool starts = p == list || p[-1] == ' ';
    const bool ends = p[length] == ' ' || p[length] == '\0';
    if (starts && ends) return true;
  }
  return false;
}

template <typename Function>
Function eglFunction(const char* name, const std::string& backend) {
  auto function = reinterpret_cast<Function>(eglGetProcAddress(name));
  if (function == nullptr) throw RenderError(backend + ": EGL lacks " + name);
  return function;
}

class EglContext final : public GlContext {
 public:
  // Takes an uninitialised display; initialises it and creates a GL 3.3 core context.
  EglContext(EGLDisplay display, std::string name) : display_(display), name_(std::move(name)) {
    if (display_ == EGL_NO_DISPLAY) throw RenderError(name_ + ": no EGL display");
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display_, &major, &minor)) {
      throw RenderError(name_ + ": eglInitialize failed (" + hex(eglGetError()) + ")");
    }
    if (!hasExtension(eglQueryString(display_, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
      throw RenderError(name_ + ": EGL_KHR_surfaceless_context is not supported");
    }
    if (!eglBindAPI(EGL_OPENGL_API)) throw RenderError(name_ + ": desktop OpenGL not supported");
    const EGLint config_attributes[] = {EGL_SURFACE_TYPE, 0, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                        EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    eglChooseConfig(display_, config_attributes, &config, 1, &configs);
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         3,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         3,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
    // Without a config, EGL_KHR_no_config_context lets the context be created anyway.
    context_ = eglCreateContext(display_, configs > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT,
                                context_attributes);
    if (context_ == EGL_NO_CONTEXT) {
      throw RenderError(name_ + ": cannot create an OpenGL 3.3 core context (" +
                        hex(eglGetError()) + ")");
    }
    makeCurrent();
  }

  ~EglContext() override {
    if (context_ != EGL_NO_CONTEXT) {
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglDestroyContext(display_, context_);
    }
    // The display is left initialised on purpose: EGL displays are process-wide (a later context
    // gets the same one back), and eglTerminate makes Mesa unload its driver, which leaves the
    // driver's own allocations unreachable and unattributable (LeakSanitizer reports them as
    // leaks in an unknown module). Initialising an initialised display again is a no-op.
    eglReleaseThread();
  }

  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  void makeCurrent() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      throw RenderError(name_ + ": cannot make the context current (" + hex(eglGetError()) + ")");
    }
  }

  std::string backendName() const override { return name_; }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::string name_;
};

}  // namespace

std::unique_ptr<GlContext> createEglSurfacelessContext() {
  const std::string name = "egl";
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!hasExtension(client, "EGL_MESA_platform_surfaceless")) {
    throw RenderError(name +
                      ": EGL_MESA_platform_surfaceless is not available (install "
                      "libegl-mesa0)");
  }
  auto getPlatformDisplay =
      eglFunction<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT", name);
  return std::make_unique<EglContext>(
      getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), name);
}

std::unique_ptr<GlContext> createEglDeviceContext() {
  const std::string name = "gpu";
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!hasExtension(client, "EGL_EXT_device_enumeration") ||
      !hasExtension(client, "EGL_EXT_platform_device")) {
    throw RenderError(name + ": EGL device enumeration is not available");
  }
  auto queryDevices = eglFunction<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT", name);
  auto queryDeviceString =
      eglFunction<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT", name);
  auto getPlatformDisplay =
      eglFunction<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT", name);
  constexpr EGLint kMaxDevices = 16;
  EGLDeviceEXT devices[kMaxDevices];
  EGLint count = 0;
  if (!queryDevices(kMaxDevices, devices, &count)) count = 0;
  std::string reasons;
  for (EGLint i = 0; i < count; ++i) {
    // Mesa lists its software rasteriser as a device too; only hardware counts as a GPU.
    const char* extensions = queryDeviceString(devices[i], EGL_EXTENSIONS);
    if (hasExtension(extensions, "EGL_MESA_device_software")) continue;
    try {
      return std::make_unique<EglContext>(
          getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr), name);
    } catch (const RenderError& e) {
      reasons += std::string("; ") + e.what();
    }
  }
  throw RenderError(name + ": no GPU found through EGL (" + std::to_string(count) +
                    " EGL devices, none usable as hardware)" + reasons);
}

}  // namespace collide::render
