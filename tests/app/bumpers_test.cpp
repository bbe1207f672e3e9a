// A glider's spring bumpers (issue 18): drawn at both ends, their tips where the glider collides,
// and during a soft contact shortened so that the tips meet the partner exactly. Expected
// positions come from the bodies' centres and the scene's widths, not from compose's constants.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "app/animation.hpp"
#include "physics/timeline.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

constexpr double kTol = 1e-9;

struct Bumper {
  double face_x = 0.0, tip_x = 0.0;  // where it leaves the block, its free end
};

// The springs of one glider's two bumpers: those starting on the block's faces.
std::vector<Bumper> bumpersOf(const frame::PanelModel& panel, const frame::BodyModel& body) {
  std::vector<Bumper> found;
  for (const frame::SpringModel& spring : panel.springs) {
    const double face = std::abs(spring.from_m.x() - body.center_m.x());
    if (std::abs(face - body.half_extent_m.x()) < kTol && spring.from_m.y() == body.center_m.y()) {
      found.push_back({spring.from_m.x(), spring.to_m.x()});
    }
  }
  return found;
}

double sideOf(const Bumper& b) {
  return b.tip_x > b.face_x ? 1.0 : -1.0;
}

class BumpersTest : public ::testing::Test {
 protected:
  scene::SceneDesc scene = scene::loadPreset("air-track");
  app::Animation animation = app::animate(scene, {1280, 720});
  const physics::Timeline& timeline = animation.frames.timeline();
};

TEST_F(BumpersTest, AtRestTheTipsAreWhereTheGliderCollides) {
  ASSERT_EQ(scene.bodies.size(), 2u);
  const frame::FrameModel frame = animation.frames.frameAtSimulated(0.5);
  ASSERT_EQ(frame.panels.size(), 1u);
  const frame::PanelModel& panel = frame.panels.front();
  EXPECT_EQ(panel.springs.size(), 4u);
  for (std::size_t i = 0; i < 2; ++i) {
    const frame::BodyModel& body = panel.bodies[i];
    EXPECT_LT(body.half_extent_m.x(), 0.5 * scene.bodies[i].size_m);  // room for the bumpers
    const std::vector<Bumper> bumpers = bumpersOf(panel, body);
    ASSERT_EQ(bumpers.size(), 2u) << "glider " << i + 1;
    EXPECT_EQ(sideOf(bumpers[0]) * sideOf(bumpers[1]), -1.0);  // one each end
    for (const Bumper& b : bumpers) {
      EXPECT_NEAR(std::abs(b.tip_x - body.center_m.x()), 0.5 * scene.bodies[i].size_m, kTol);
    }
  }
}

TEST_F(BumpersTest, InAContactBetweenGlidersBothGiveWayAndTheirTipsMeet) {
  const physics::CollisionEvent& first = timeline.collisions().at(0);
  ASSERT_EQ(first.body_a, 0);
  ASSERT_EQ(first.body_b, 1);
  const double t = first.time_s + 0.5 * scene.contact.duration_s;
  const frame::PanelModel panel = animation.frames.frameAtSimulated(t).panels.front();
  const frame::BodyModel &left = panel.bodies[0], &right = panel.bodies[1];
  // How far the colliding widths overlap: the compression the two bumpers share.
  const double overlap = (left.center_m.x() + 0.5 * scene.bodies[0].size_m) -
                         (right.center_m.x() - 0.5 * scene.bodies[1].size_m);
  ASSERT_GT(overlap, 1e-4);
  double left_tip = 0.0, right_tip = 0.0;
  for (const Bumper& b : bumpersOf(panel, left)) {
    if (sideOf(b) > 0.0) left_tip = b.tip_x;
  }
  for (const Bumper& b : bumpersOf(panel, right)) {
    if (sideOf(b) < 0.0) right_tip = b.tip_x;
  }
  EXPECT_NEAR(left_tip, right_tip, kTol);
  EXPECT_NEAR(left_tip, left.center_m.x() + 0.5 * scene.bodies[0].size_m - 0.5 * overlap, kTol);
  EXPECT_TRUE(panel.flashes.empty()) << "a flash would hide the compressed bumpers";
  // The outer bumpers are not touched.
  for (const Bumper& b : bumpersOf(panel, left)) {
    if (sideOf(b) < 0.0) {
      EXPECT_NEAR(b.tip_x, left.center_m.x() - 0.5 * scene.bodies[0].size_m, kTol);
    }
  }
}

TEST_F(BumpersTest, AgainstAnEndStopTheBumperTipStaysOnTheStop) {
  const std::vector<physics::CollisionEvent>& events = timeline.collisions();
  const auto wall = std::find_if(events.begin(), events.end(),
                                 [](const physics::CollisionEvent& e) { return e.hitsWall(); });
  ASSERT_NE(wall, events.end());
  const double t = wall->time_s + 0.5 * scene.contact.duration_s;
  const frame::PanelModel panel = animation.frames.frameAtSimulated(t).panels.front();
  const frame::BodyModel& body = panel.bodies[static_cast<std::size_t>(wall->body_a)];
  const frame::WallModel& stop = panel.walls.at(static_cast<std::size_t>(wall->wallIndex()));
  const double toward = stop.normal.x() > 0.0 ? -1.0 : 1.0;  // the stop's side of the glider
  int found = 0;
  for (const Bumper& b : bumpersOf(panel, body)) {
    if (sideOf(b) != toward) continue;
    ++found;
    EXPECT_NEAR(b.tip_x, stop.point_m.x(), kTol);
    EXPECT_LT(
        std::abs(b.tip_x - b.face_x),
        0.5 * scene.bodies[static_cast<std::size_t>(wall->body_a)].size_m - body.half_extent_m.x());
  }
  EXPECT_EQ(found, 1);
}

}  // namespace
}  // namespace collide
