// SPDX-License-Identifier: MIT
// The strobe of a gas, checked on the frame description (no pixels read): a few marked molecules
// along their paths, the rest of the gas drawn once, faint, at the end.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "scene/scene_desc.hpp"
#include "strobe_images.hpp"

namespace collide {
namespace {

using strobe_images::drawnAt;
using strobe_images::Image;
using strobe_images::imagesByBody;
using strobe_images::kFaint;

// The strobe of a gas photographs a few marked molecules along their zig-zag paths and draws the
// rest of the gas once, faint, at the end, instead of a field of overlapping dots. The corners
// of each path are the molecule's collisions, read here from the simulation's event log.
TEST(StrobeSpacingTest, GasShowsAFewMarkedMoleculesAlongTheirPaths) {
  const scene::SceneDesc scene = scene::loadPreset("ideal-gas");
  ASSERT_GT(scene.bodies.size(), 100u);
  const app::Animation animation = app::animate(scene, {640, 360});
  const compose::FrameSource& source = animation.frames;
  const physics::Timeline& timeline = source.timeline();
  const double rate_hz = source.strobeRate_hz();
  const frame::FrameModel frame = source.strobeFrame(0.0);
  ASSERT_EQ(frame.panels.size(), 1u);
  const frame::PanelModel& panel = frame.panels.front();
  ASSERT_EQ(panel.bodies.size(), scene.bodies.size());
  const int flashes = static_cast<int>(std::floor(scene.duration_s * rate_hz + 1e-9)) + 1;

  std::vector<std::size_t> marked;
  for (std::size_t i = 0; i < panel.bodies.size(); ++i) {
    const frame::BodyModel& body = panel.bodies[i];
    const core::Vec2 end = drawnAt(scene, timeline, i, scene.duration_s);
    EXPECT_LE((body.center_m - end).norm(), 1e-9) << "disk " << i + 1 << " not where it ends";
    if (body.fill.a >= kFaint) {
      marked.push_back(i);
    } else {
      EXPECT_TRUE(body.trail_m.empty()) << "unmarked disk " << i + 1 << " has a path";
    }
  }
  ASSERT_GE(marked.size(), 2u);
  ASSERT_LE(marked.size(), 5u) << "a few marked molecules, not the whole gas";

  // Every ghost is an image of a marked molecule at a flash (imagesByBody fails any other).
  ASSERT_EQ(source.strobeSpan_s(), scene.duration_s) << "a gas never rests all at once";
  const std::vector<std::vector<Image>> images =
      imagesByBody(scene, timeline, panel, rate_hz, scene.duration_s);
  std::size_t ghosts_of_marked = 0;
  for (std::size_t a = 0; a < marked.size(); ++a) {
    const std::size_t i = marked[a];
    SCOPED_TRACE("disk " + std::to_string(i + 1));
    for (std::size_t b = a + 1; b < marked.size(); ++b) {
      const frame::Rgba &x = panel.bodies[i].fill, &y = panel.bodies[marked[b]].fill;
      EXPECT_FALSE(x.r == y.r && x.g == y.g && x.b == y.b) << "two marked molecules alike";
    }
    ghosts_of_marked += images[i].size() - 1;
    // Images along its path: its first, and several more (a molecule crosses the box).
    EXPECT_GE(images[i].size(), 6u);
    EXPECT_LE(images[i].size(), static_cast<std::size_t>(flashes));
    // The path starts where it started, ends where it is, and turns at each of its collisions.
    const std::vector<core::Vec2>& path = panel.bodies[i].trail_m;
    ASSERT_GE(path.size(), 2u);
    EXPECT_LE((path.front() - drawnAt(scene, timeline, i, 0.0)).norm(), 1e-9);
    EXPECT_LE((path.back() - drawnAt(scene, timeline, i, scene.duration_s)).norm(), 1e-9);
    int corners = 0;
    for (const physics::CollisionEvent& event : timeline.collisions()) {
      if (event.body_a != static_cast<int>(i) && event.body_b != static_cast<int>(i)) continue;
      const core::Vec2 at = drawnAt(scene, timeline, i, event.time_s);
      bool on_path = false;
      for (const core::Vec2& point : path) on_path = on_path || (point - at).norm() <= 1e-9;
      EXPECT_TRUE(on_path) << "the path misses its collision at t = " << event.time_s << " s";
      ++corners;
    }
    EXPECT_GE(corners, 3) << "a zig-zag path: this molecule should collide several times";
  }
  EXPECT_EQ(ghosts_of_marked, panel.ghosts.size());
  EXPECT_NE(panel.caption.find("marked molecules"), std::string::npos) << panel.caption;
}
}  // namespace
}  // namespace collide
