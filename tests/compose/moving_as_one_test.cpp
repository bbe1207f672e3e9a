// Bodies that stick at e = 0 and move on together are drawn and labelled as one body with one
// arrow, checked on the frame description: the bullet inside its block, coupled carts. Expected
// velocities come from momentum conservation, masses from the scene.
#include <gtest/gtest.h>

#include <string>

#include "app/animation.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

// Bodies that draw their own arrow: moving, and not riding on another.
int arrowsDrawn(const frame::PanelModel& panel) {
  int arrows = 0;
  for (const frame::BodyModel& body : panel.bodies) {
    arrows += body.moves_with < 0 && body.velocity_mps.norm() > 1e-6 ? 1 : 0;
  }
  return arrows;
}

struct Joined {
  frame::FrameModel before, after;
  scene::SceneDesc scene;
};

Joined framesAround(const char* preset) {
  Joined joined{{}, {}, scene::loadPreset(preset)};
  const app::Animation animation = app::animate(joined.scene, {1280, 720});
  const double t_hit = animation.frames.timeline().collisions().front().time_s;
  joined.before = animation.frames.frameAtSimulated(0.5 * t_hit);
  joined.after =
      animation.frames.frameAtSimulated(0.5 * (t_hit + animation.frames.simulatedDuration_s()));
  return joined;
}

TEST(MovingAsOneTest, BulletDrawnInsideItsBlockWithOneArrowAndOneLabel) {
  const Joined joined = framesAround("bullet-block");
  const double m1 = joined.scene.bodies[0].mass_kg, m2 = joined.scene.bodies[1].mass_kg;
  const double u1 = joined.scene.bodies[0].velocity_mps.x();
  ASSERT_LT(m1, m2);
  {
    const frame::PanelModel& panel = joined.before.panels.front();
    EXPECT_EQ(panel.bodies[0].moves_with, -1);
    EXPECT_EQ(panel.bodies[1].moves_with, -1);
    EXPECT_FALSE(panel.bodies[0].label.empty());
    EXPECT_FALSE(panel.bodies[1].label.empty());
  }
  const frame::PanelModel& panel = joined.after.panels.front();
  const frame::BodyModel &bullet = panel.bodies[0], &block = panel.bodies[1];
  EXPECT_EQ(bullet.moves_with, 1);
  EXPECT_EQ(block.moves_with, -1);
  // Momentum kept: m1·u1 = (m1 + m2)·v.
  const double v = m1 * u1 / (m1 + m2);
  EXPECT_NEAR(block.velocity_mps.x(), v, 1e-9 * u1);
  EXPECT_EQ(arrowsDrawn(panel), 1);
  EXPECT_TRUE(bullet.label.empty());
  EXPECT_TRUE(bullet.velocity_label.empty());
  EXPECT_EQ(block.label, "m\u2081 + m\u2082 = 1.01 kg") << block.label;  // 0.01 + 1 kg
  EXPECT_EQ(block.velocity_label.rfind("v\u2081\u2032 = v\u2082\u2032 = +", 0), 0u)
      << block.velocity_label;
  // Inside the block, not poking out of it; no bond bar.
  EXPECT_LT(std::abs(bullet.center_m.x() - block.center_m.x()) + bullet.half_extent_m.x(),
            block.half_extent_m.x());
  EXPECT_LT(std::abs(bullet.center_m.y() - block.center_m.y()) + bullet.half_extent_m.y(),
            block.half_extent_m.y());
  EXPECT_TRUE(panel.bonds.empty());
}

TEST(MovingAsOneTest, CoupledCartsCarryOneArrowAndTheirTotalMass) {
  const Joined joined = framesAround("perfectly-inelastic");
  const double m1 = joined.scene.bodies[0].mass_kg, m2 = joined.scene.bodies[1].mass_kg;
  const double u1 = joined.scene.bodies[0].velocity_mps.x();
  ASSERT_GT(m1, m2);  // cart 1 is the heavier: it speaks for both
  EXPECT_EQ(arrowsDrawn(joined.before.panels.front()), 1);  // cart 2 starts at rest
  const frame::PanelModel& panel = joined.after.panels.front();
  EXPECT_EQ(panel.bodies[1].moves_with, 0);
  EXPECT_EQ(arrowsDrawn(panel), 1);
  EXPECT_NEAR(panel.bodies[0].velocity_mps.x(), m1 * u1 / (m1 + m2), 1e-9 * u1);
  EXPECT_EQ(panel.bodies[0].label.rfind("m\u2081 + m\u2082 = 3", 0), 0u) << panel.bodies[0].label;
  EXPECT_TRUE(panel.bodies[1].label.empty());
  EXPECT_TRUE(panel.bodies[1].velocity_label.empty());
  EXPECT_TRUE(panel.bonds.empty());
}

TEST(MovingAsOneTest, ASpinningStuckPairKeepsBothArrowsAndItsBond) {
  // stick-2d: the partners turn about their centre of mass, so they move differently.
  const Joined joined = framesAround("stick-2d");
  const frame::PanelModel& panel = joined.after.panels.front();
  for (const frame::BodyModel& body : panel.bodies) EXPECT_EQ(body.moves_with, -1);
  EXPECT_EQ(panel.bonds.size(), 1u);
  EXPECT_EQ(arrowsDrawn(panel), 2);
}

}  // namespace
}  // namespace collide
