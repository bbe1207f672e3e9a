// SPDX-License-Identifier: MIT
// Strobes that tell the story (issue 37 item 4), checked on the frame description (no pixels
// read): a glider's faint images are gliders, drawn with their spring bumpers as its last image
// is, not plain blocks. A glider is size_m wide from bumper tip to bumper tip (its block and two
// bumpers at rest); the places and contacts are read from the simulation here, independently of
// compose.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

// Where body i's centre is drawn at t on a 1D track (at half its height).
core::Vec2 drawnAt(const scene::SceneDesc& scene, const physics::Timeline& timeline, std::size_t i,
                   double t_s) {
  return {timeline.sample(t_s).bodies[i].position_m.x(), 0.5 * scene.bodies[i].size_m};
}

// Whether glider i is clear of every other body and every wall at t: bumpers at rest, so its
// image spans its whole width size_m.
bool freeAt(const scene::SceneDesc& scene, const physics::Timeline& timeline, std::size_t i,
            double t_s) {
  const double x = timeline.sample(t_s).bodies[i].position_m.x();
  const double half = 0.5 * scene.bodies[i].size_m;
  for (std::size_t j = 0; j < scene.bodies.size(); ++j) {
    if (j == i) continue;
    const double other_x = timeline.sample(t_s).bodies[j].position_m.x();
    if (std::abs(other_x - x) <= half + 0.5 * scene.bodies[j].size_m) return false;
  }
  for (const scene::WallDesc& wall : scene::allWalls(scene)) {
    if (std::abs((x - wall.position_m.x()) * wall.normal.normalized().x()) <= half) return false;
  }
  return true;
}

// The flash (t = k / rate) at which body i stood where `ghost` stands; none: another instant (a
// collision's).
std::optional<double> flashOf(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                              std::size_t i, const frame::BodyModel& ghost, double rate_hz,
                              double end_s) {
  for (int k = 0; k / rate_hz <= end_s + 1e-9; ++k) {
    const core::Vec2 at = drawnAt(scene, timeline, i, k / rate_hz);
    if ((ghost.center_m - at).norm() <= 1e-9 * (1.0 + at.norm())) return k / rate_hz;
  }
  return std::nullopt;
}

// Checks every ghost of a glider in `panel`: two bumpers, one from each face of its block,
// pointing away from it, its tips no further apart than the glider's width, and exactly that far
// at a flash where it touches nothing. Returns the ghosts checked at such a flash.
int checkGhostBumpers(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                      const frame::PanelModel& panel, double rate_hz, double end_s) {
  int free_checked = 0;
  for (const frame::BodyModel& ghost : panel.ghosts) {
    std::optional<std::size_t> body;
    for (std::size_t i = 0; i < panel.bodies.size() && !body; ++i) {
      const frame::Rgba& fill = panel.bodies[i].fill;
      if (ghost.fill.r == fill.r && ghost.fill.g == fill.g && ghost.fill.b == fill.b) body = i;
    }
    if (!body) {
      ADD_FAILURE() << "a ghost of no body's colour";
      continue;
    }
    const double width_m = scene.bodies[*body].size_m;
    SCOPED_TRACE("body " + std::to_string(*body + 1) +
                 " at x = " + std::to_string(ghost.center_m.x()));
    if (ghost.bumpers.size() != 2u) {
      ADD_FAILURE() << "a faint glider drawn with " << ghost.bumpers.size() << " bumpers, not 2";
      continue;
    }
    double left_tip = 0.0, right_tip = 0.0;
    for (const frame::SpringModel& bumper : ghost.bumpers) {
      const double side = bumper.to_m.x() > bumper.from_m.x() ? 1.0 : -1.0;
      EXPECT_NEAR(bumper.from_m.x(), ghost.center_m.x() + side * ghost.half_extent_m.x(), 1e-12)
          << "a bumper not on its block's face";
      EXPECT_NEAR(bumper.from_m.y(), ghost.center_m.y(), 1e-12);
      EXPECT_NEAR(bumper.to_m.y(), ghost.center_m.y(), 1e-12);
      (side > 0.0 ? right_tip : left_tip) = bumper.to_m.x();
    }
    EXPECT_LT(left_tip, ghost.center_m.x() - ghost.half_extent_m.x()) << "no left bumper";
    EXPECT_GT(right_tip, ghost.center_m.x() + ghost.half_extent_m.x()) << "no right bumper";
    EXPECT_LE(right_tip - left_tip, width_m * (1.0 + 1e-9));
    const std::optional<double> t_s = flashOf(scene, timeline, *body, ghost, rate_hz, end_s);
    if (t_s && freeAt(scene, timeline, *body, *t_s)) {
      EXPECT_NEAR(right_tip - left_tip, width_m, 1e-9 * width_m) << "at t = " << *t_s;
      ++free_checked;
    }
  }
  return free_checked;
}

TEST(StrobeStoryTest, FaintGlidersCarryTheirBumpers) {
  const scene::SceneDesc scene = scene::loadPreset("air-track");
  ASSERT_EQ(scene.bodies.size(), 2u);
  const app::Animation animation = app::animate(scene, {640, 360});
  const compose::FrameSource& source = animation.frames;
  const physics::Timeline& timeline = source.timeline();
  // The picture's own rate (images kept apart) and a rate the user gives (every flash drawn).
  const double own_hz = source.strobeRate_hz();
  const frame::FrameModel own = source.strobeFrame(0.0);
  ASSERT_EQ(own.panels.size(), 1u);
  ASSERT_GE(own.panels.front().ghosts.size(), 4u);
  const int own_free =
      checkGhostBumpers(scene, timeline, own.panels.front(), own_hz, source.strobeSpan_s());
  EXPECT_GE(own_free, 3) << "too few images clear of the others to check their width";
  const frame::FrameModel every = source.strobeFrame(2.0, false);
  ASSERT_GE(every.panels.front().ghosts.size(), 20u);
  const int every_free =
      checkGhostBumpers(scene, timeline, every.panels.front(), 2.0, source.strobeSpan_s(false));
  EXPECT_GE(every_free, 20);
}

// A body's images other than gliders carry no bumpers.
TEST(StrobeStoryTest, BlocksCarryNoBumpers) {
  const scene::SceneDesc scene = scene::loadPreset("soft-contact");
  const app::Animation animation = app::animate(scene, {640, 360});
  const frame::FrameModel frame = animation.frames.strobeFrame(0.0);
  ASSERT_FALSE(frame.panels.front().ghosts.empty());
  for (const frame::BodyModel& ghost : frame.panels.front().ghosts)
    EXPECT_TRUE(ghost.bumpers.empty());
}

}  // namespace
}  // namespace collide
