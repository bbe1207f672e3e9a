// The GL backends side by side: EGL surfaceless runs the same llvmpipe as OSMesa into the same kind
// of framebuffer object, so the pixels must be identical, byte for byte.
#include <gtest/gtest.h>

#include <cstring>

#include "app/animation.hpp"
#include "render/backend.hpp"
#include "render/renderer.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

bool compiledIn(render::Backend backend) {
  for (render::Backend b : render::compiledBackends()) {
    if (b == backend) return true;
  }
  return false;
}

core::Image renderWith(render::Backend backend, double t_s) {
  const compose::FrameSource source = app::animate(scene::loadPreset("worked-example")).frames;
  render::Renderer renderer(render::createContext(backend), 320, 180);
  return core::Image::copyOf(renderer.render(source.frameAt(t_s)));
}

TEST(BackendGLTest, OsmesaAndEglSurfacelessGiveTheSamePixels) {
  if (!compiledIn(render::Backend::kOsmesa)) GTEST_SKIP() << "built without OSMesa";
  for (double t : {0.0, 7.0 / 6.0, 2.5}) {
    const core::Image osmesa = renderWith(render::Backend::kOsmesa, t);
    const core::Image egl = renderWith(render::Backend::kEgl, t);
    ASSERT_EQ(osmesa.width(), egl.width());
    ASSERT_EQ(osmesa.height(), egl.height());
    EXPECT_EQ(std::memcmp(osmesa.data(), egl.data(), 4u * osmesa.width() * osmesa.height()), 0)
        << "t = " << t;
  }
}

TEST(BackendGLTest, AutoFindsAWorkingBackend) {
  render::Renderer renderer(render::createContext(render::Backend::kAuto), 32, 32);
  EXPECT_FALSE(renderer.glRendererName().empty());
}

TEST(BackendGLTest, NamesRoundTrip) {
  for (render::Backend b : {render::Backend::kOsmesa, render::Backend::kEgl, render::Backend::kGpu,
                            render::Backend::kAuto}) {
    EXPECT_EQ(render::parseBackend(render::backendName(b)), b);
  }
  EXPECT_FALSE(render::parseBackend("vulkan").has_value());
}

}  // namespace
}  // namespace collide
