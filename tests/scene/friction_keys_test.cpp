// SPDX-License-Identifier: MIT
// Sliding friction's scene keys: a body's friction and static_friction, the scene's
// surface_gravity; what they cannot go with is refused, one line naming what is allowed.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_io.hpp"
#include "scene_problem.hpp"

namespace collide::scene {
namespace friction_keys_test {

// Two cars, the first with a static coefficient, the second with none; `car_static` and
// `parked_kinetic` are the lines that give them.
std::string skidding(const std::string& car_static = "static_friction = 0.8",
                     const std::string& parked_kinetic = "friction = 0.5") {
  return R"(
dimensions = 1
surface_gravity = "9.7 m/s^2"
[[body]]
name = "car"
mass = 1500
width = 4.5
position = 0
velocity = 20
friction = 0.7
)" + car_static +
         R"(
[[body]]
name = "parked"
mass = 1000
width = 4.2
position = 10
)" + parked_kinetic +
         "\n";
}

using testing::problemOf;

TEST(FrictionKeysTest, ReadsTheCoefficientsAndWritesThemBack) {
  const SceneDesc scene = parseSceneText(skidding(), "s");
  EXPECT_EQ(scene.surface_gravity_mps2, 9.7);
  EXPECT_EQ(scene.bodies[0].friction, 0.7);
  EXPECT_EQ(scene.bodies[0].static_friction, 0.8);
  EXPECT_EQ(scene.bodies[1].friction, 0.5);
  EXPECT_FALSE(scene.bodies[1].static_friction.has_value());  // the kinetic one then
  EXPECT_EQ(parseSceneText(sceneToToml(scene), "again"), scene);
}

TEST(FrictionKeysTest, RefusesAStaticCoefficientBelowTheKineticOne) {
  const std::string problem = problemOf(skidding("static_friction = 0.6"));
  EXPECT_NE(problem.find("body.1.static_friction: 0.6: below the body's friction (0.7);"),
            std::string::npos)
      << problem;
  EXPECT_NE(problem.find("allowed: a static coefficient at least the kinetic one"),
            std::string::npos)
      << problem;
}

TEST(FrictionKeysTest, RefusesANegativeCoefficientAndFrictionWhereItIsNotModelled) {
  const std::string negative = problemOf(skidding("static_friction = 0.8", "friction = -0.5"));
  EXPECT_NE(negative.find("body.2.friction: -0.5: out of range; allowed: a coefficient of friction "
                          "from 0 to 10"),
            std::string::npos)
      << negative;
  const std::string soft = problemOf(skidding() + "[contact]\nmodel = \"spring-damper\"\n");
  EXPECT_NE(soft.find("allowed: friction with contact.model = \"impulse\""), std::string::npos)
      << soft;
  const std::string tilted = problemOf(R"(
dimensions = 2
gravity = [0, -9.81]
[[body]]
mass = 1
radius = 0.1
position = [0, 0]
friction = 0.3
)");
  EXPECT_NE(tilted.find("gravity: [0, -9.81]: gravity in the plane with sliding friction on a "
                        "body; allowed: friction on a level table"),
            std::string::npos)
      << tilted;
}

TEST(FrictionKeysTest, ALevelTableTakesFriction) {
  const SceneDesc scene = parseSceneText(R"(
dimensions = 2
[[body]]
mass = 1
radius = 0.1
position = [0, 0]
velocity = [1, 0]
friction = 0.3
)",
                                         "table.toml");
  ASSERT_EQ(scene.bodies.size(), 1u);
  EXPECT_EQ(scene.bodies[0].friction, 0.3);
}

TEST(FrictionKeysTest, ThePresetLocksTwoSkiddingCars) {
  const SceneDesc scene = loadPreset("accident-reconstruction");
  ASSERT_EQ(scene.bodies.size(), 2u);
  EXPECT_EQ(scene.restitution, 0.0);
  for (const BodyDesc& car : scene.bodies) EXPECT_GT(car.friction, 0.0);
}

}  // namespace friction_keys_test
}  // namespace collide::scene
