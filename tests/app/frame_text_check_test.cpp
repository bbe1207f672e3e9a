// The text on the frames of five presets, read back and checked against physics worked out here
// from the preset's inputs alone (closed forms: the 1D collision formulas with e, a smooth
// two-disk impact, free fall): the worked example, an elastic 1D pair, the comparison with three
// panels, the bouncing ball (2D, gravity, potential energy) and the glancing billiard shot (2D,
// momentum diagram), each before and after its collision.
#include "frame_text_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "closed_forms.hpp"
#include "scene/scene_io.hpp"

namespace collide {
namespace {

using test::BodyTruth;
using test::bouncingBall;
using test::FrameTruth;
using test::PanelTruth;
using test::twoBlocks;
using test::twoDisks;

frame::FrameModel frameOf(const scene::SceneDesc& scene, double t_s) {
  return app::animate(scene, {1280, 720}).frames.frameAtSimulated(t_s);
}

FrameTruth truthFor(const scene::SceneDesc& scene, double t_s, std::vector<PanelTruth> panels) {
  return {scene.title, t_s, scene.dimensions, std::move(panels)};
}

// Checks the frame at each instant; every instant must compare a good many numbers.
void checkAt(const scene::SceneDesc& scene, const std::vector<double>& instants_s,
             const std::function<std::vector<PanelTruth>(double)>& truth) {
  for (double t : instants_s) {
    SCOPED_TRACE(scene.name + " at t = " + std::to_string(t));
    const int compared = test::checkFrameText(frameOf(scene, t), truthFor(scene, t, truth(t)));
    EXPECT_GE(compared, 10) << "the check read too little of the frame";
  }
}

// Carts meet at t = 3.5 m / 3 m/s = 1.1667 s.
TEST(FrameTextCheckTest, WorkedExample) {
  const scene::SceneDesc scene = scene::loadPreset("worked-example");
  checkAt(scene, {0.0, 0.5, 1.1, 1.25, 2.5, 3.999}, [&](double t) {
    return std::vector<PanelTruth>{twoBlocks(scene, scene.restitution, t)};
  });
}

TEST(FrameTextCheckTest, ElasticCartBouncesBack) {
  const scene::SceneDesc scene = scene::loadPreset("elastic");
  checkAt(scene, {0.4, 1.3, 3.0}, [&](double t) {
    return std::vector<PanelTruth>{twoBlocks(scene, scene.restitution, t)};
  });
}

// One panel per e, headed by it.
TEST(FrameTextCheckTest, CompareRestitutionPanels) {
  const scene::SceneDesc scene = scene::loadPreset("compare-restitution");
  ASSERT_EQ(scene.view.panel_values, (std::vector<double>{1.0, 0.5, 0.0}));
  checkAt(scene, {0.6, 1.3, 2.5, 3.5}, [&](double t) {
    std::vector<PanelTruth> panels;
    for (double e : {1.0, 0.5, 0.0}) {
      panels.push_back(twoBlocks(scene, e, t));
      char heading[32];
      std::snprintf(heading, sizeof heading, "e = %g", e);
      panels.back().heading = heading;
    }
    return panels;
  });
}

// 2D with gravity: the potential energy segment, signed directions, momentum changing in y.
TEST(FrameTextCheckTest, BouncingBall) {
  const scene::SceneDesc scene = scene::loadPreset("bouncing-ball");
  checkAt(scene, {0.3, 0.6, 0.9, 1.2},
          [&](double t) { return std::vector<PanelTruth>{bouncingBall(scene, t)}; });
}

// 2D without gravity, with the momentum diagram: equal masses leave at right angles.
TEST(FrameTextCheckTest, BilliardsGlancing) {
  const scene::SceneDesc scene = scene::loadPreset("billiards-glancing");
  checkAt(scene, {0.2, 0.5, 1.0, 1.45},
          [&](double t) { return std::vector<PanelTruth>{twoDisks(scene, scene.restitution, t)}; });
}

}  // namespace
}  // namespace collide
