#pragma once
// The mirror check shared by the property tests over random table scenes (property_test.cpp,
// plane_friction_property_test.cpp): the scene reflected about x = 0 and renumbered is the same
// motion, reflected. Only short runs are compared: beyond a few collisions a box of disks is
// chaotic, and rounding-level differences between a scene and its image (the order of a sum)
// grow by orders of magnitude per collision.
#include <gtest/gtest.h>

#include <algorithm>

#include "physics/simulate.hpp"
#include "random_scenes.hpp"

namespace collide::physics::testing {

// Runs of at most this many collisions stay within 1e-12 of their image.
inline constexpr int kPlaneMirrorMaxCollisions = 20;

// Whether the run was short enough to compare; a difference ASSERTs (callers stop at
// HasFailure()).
inline bool checkPlaneMirror(const Timeline& timeline, int scene) {
  if (timeline.collisionCount() > kPlaneMirrorMaxCollisions) return false;
  const WorldDef& world = timeline.world();
  const Timeline image = simulate(mirroredAndRenumbered(world));
  EXPECT_EQ(image.collisionCount(), timeline.collisionCount()) << "scene " << scene;
  EXPECT_EQ(image.status(), timeline.status()) << "scene " << scene;
  if (image.collisionCount() != timeline.collisionCount()) return true;
  double speed_mps = 1.0, extent_m = 1.0;
  for (const BodyDef& body : world.bodies) {
    speed_mps = std::max(speed_mps, body.velocity_mps.norm());
    extent_m = std::max(extent_m, body.position_m.norm());
  }
  const int n = static_cast<int>(world.bodies.size());
  const double t = timeline.simulatedUntil_s();
  const Snapshot s = timeline.sample(t), m = image.sample(t);
  for (int i = 0; i < n; ++i) {
    const BodyState& a = s.bodies[i];
    const BodyState& b = m.bodies[n - 1 - i];
    EXPECT_NEAR(a.position_m.x(), -b.position_m.x(), 1e-12 * extent_m) << "scene " << scene;
    EXPECT_NEAR(a.position_m.y(), b.position_m.y(), 1e-12 * extent_m) << "scene " << scene;
    EXPECT_NEAR(a.velocity_mps.x(), -b.velocity_mps.x(), 1e-12 * speed_mps) << "scene " << scene;
    EXPECT_NEAR(a.velocity_mps.y(), b.velocity_mps.y(), 1e-12 * speed_mps) << "scene " << scene;
  }
  return true;
}

}  // namespace collide::physics::testing
