// SPDX-License-Identifier: MIT
// Issue 38: many disks that lose energy at each impact gather into clusters whose collisions come
// ever faster while time hardly advances. `collide data ideal-gas --set disks=1000 --set
// restitution=0.5` ran on to the 400-million collision cap; the clustering guard stops it where the
// cluster forms, says why, and what was simulated up to there stays exact.
#include <gtest/gtest.h>

#include <cmath>

#include "app/world_from_scene.hpp"
#include "physics/simulate.hpp"
#include "scene/scene_io.hpp"

namespace collide {
namespace {

TEST(ClusteringPhysicsTest, ManyInelasticDisksStopWhereTheyClusterAndSaySo) {
  const scene::SceneDesc scene = scene::loadScene(
      "ideal-gas",
      {scene::parseSetExpression("disks=1000"), scene::parseSetExpression("restitution=0.5")});
  const physics::WorldDef world = app::worldFromScene(scene);
  const physics::Timeline timeline = physics::simulate(world);
  EXPECT_EQ(timeline.status(), physics::SimulationStatus::kStalled);
  EXPECT_LT(timeline.simulatedUntil_s(), world.duration_s);
  // Stopped at the cluster, orders of magnitude before the cap.
  EXPECT_LT(timeline.collisionCount(), world.max_collisions / 100);
  ASSERT_FALSE(timeline.warnings().empty());
  const std::string& said = timeline.warnings().back().message;
  EXPECT_NE(said.find("inelastic collapse"), std::string::npos) << said;
  EXPECT_NE(said.find("later states are not simulated"), std::string::npos) << said;
  // What was simulated is exact: the energy the impacts dissipated is the kinetic energy that
  // is gone (no gravity, no potential energy in this box).
  const physics::Snapshot end = timeline.sample(timeline.simulatedUntil_s());
  const double before_J = timeline.initialKineticEnergy();
  EXPECT_NEAR(timeline.kineticEnergy(end) + end.energy_lost_J, before_J, 1e-9 * before_J);
  EXPECT_GT(end.energy_lost_J, 0.5 * before_J) << "a cluster forms once the gas has cooled";
}

}  // namespace
}  // namespace collide
