// SPDX-License-Identifier: MIT
// A scene drawn at one instant and compared with golden_frames/app/<golden>.png: the shape the
// preset goldens and the working goldens share (a golden test names the shot; the shot is drawn
// by the GL renderer at the test's size).
#pragma once

#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "app/animation.hpp"
#include "golden.hpp"
#include "render/renderer.hpp"
#include "scene/scene_desc.hpp"

namespace collide::test {

// A preset at the instant it teaches.
struct GoldenShot {
  const char* preset;
  double t_s;
  const char* golden;  // the baseline's name, also the test's name
};

inline void PrintTo(const GoldenShot& shot, std::ostream* out) {
  *out << shot.preset << " at " << shot.t_s << " s";
}

inline std::string goldenShotName(const ::testing::TestParamInfo<GoldenShot>& info) {
  return info.param.golden;
}

inline ::testing::AssertionResult sceneMatchesGolden(const scene::SceneDesc& scene, double t_s,
                                                     int width, int height,
                                                     const std::string& golden) {
  const compose::FrameSource source = app::animate(scene, {width, height}).frames;
  render::Renderer renderer(width, height);
  GoldenOptions options;
  options.renderer = renderer.glRendererName();
  return compareWithGolden(renderer.render(source.frameAtSimulated(t_s)), "app/" + golden + ".png",
                           options);
}

}  // namespace collide::test
