// SPDX-License-Identifier: MIT
// Scene keys that let energy in: e above 1 only with super_elastic = true (the refusal says how to
// opt in), [[release]] between touching bodies of a 1D scene, and the presets that use them.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_io.hpp"
#include "scene_problem.hpp"

namespace collide::scene {
namespace energy_release_scene_test {

const char* const kTwoCarts = R"(
dimensions = 1
[[body]]
name = "a"
mass = 1
width = 0.5
position = -0.25
[[body]]
name = "b"
mass = 2
width = 0.6
position = 0.3
)";

using testing::problemOf;

TEST(EnergyReleaseSceneTest, EAboveOneIsRefusedWithHowToOptIn) {
  const std::string problem = problemOf(std::string("restitution = 1.5\n") + kTwoCarts);
  EXPECT_NE(problem.find("restitution: 1.5: out of range"), std::string::npos) << problem;
  EXPECT_NE(problem.find("from 0 to 1 (above 1, to 10, with super_elastic = true"),
            std::string::npos)
      << problem;
  EXPECT_NE(problem.find("super_elastic = true"), std::string::npos) << problem;
  // The same for a wall and a pair.
  EXPECT_NE(problemOf(std::string(kTwoCarts) + "[[wall]]\nposition = 3\nrestitution = 2\n")
                .find("super_elastic = true"),
            std::string::npos);
  EXPECT_NE(problemOf(std::string(kTwoCarts) + "[[pair]]\nbodies = [1, 2]\nrestitution = 1.2\n")
                .find("super_elastic = true"),
            std::string::npos);
}

TEST(EnergyReleaseSceneTest, SuperElasticAllowsEToTenWithRigidImpactsOnly) {
  const SceneDesc scene =
      parseSceneText(std::string("super_elastic = true\nrestitution = 1.5\n") + kTwoCarts, "s");
  EXPECT_TRUE(scene.super_elastic);
  EXPECT_EQ(scene.restitution, 1.5);
  const std::string beyond =
      problemOf(std::string("super_elastic = true\nrestitution = 10.5\n") + kTwoCarts);
  ASSERT_NE(beyond.find("allowed: "), std::string::npos) << beyond;
  EXPECT_EQ(beyond.substr(beyond.find("allowed: ")),
            "allowed: a coefficient of restitution from 0 to 10");
  const std::string soft = problemOf(std::string("super_elastic = true\nrestitution = 1.5\n") +
                                     kTwoCarts + "[contact]\nmodel = \"spring-damper\"\n");
  EXPECT_NE(soft.find("allowed: e above 1 with contact.model = \"impulse\""), std::string::npos)
      << soft;
  // Written back, it reads the same.
  EXPECT_EQ(parseSceneText(sceneToToml(scene), "again"), scene);
}

TEST(EnergyReleaseSceneTest, ReleaseBetweenTouchingBodiesReadsAndWritesBack) {
  const SceneDesc scene = parseSceneText(
      std::string(kTwoCarts) + "[[release]]\nbodies = [\"b\", \"a\"]\ntime = 0.5\nenergy = 3\n",
      "s");
  ASSERT_EQ(scene.releases.size(), 1u);
  const ReleaseDesc& release = scene.releases[0];
  EXPECT_EQ(release.body_a, 0);  // the left one first, however written
  EXPECT_EQ(release.body_b, 1);
  EXPECT_EQ(release.time_s, 0.5);
  EXPECT_EQ(release.energy_J, 3.0);
  EXPECT_FALSE(release.speed_mps.has_value());
  EXPECT_EQ(parseSceneText(sceneToToml(scene), "again"), scene);
}

TEST(EnergyReleaseSceneTest, ReleaseProblemsNameTheKeyAndWhatIsAllowed) {
  const std::string base = std::string(kTwoCarts) + "[[release]]\nbodies = [1, 2]\n";
  EXPECT_NE(problemOf(base + "time = 0.5\n").find("give one of energy and speed"),
            std::string::npos);
  EXPECT_NE(problemOf(base + "time = 0.5\nenergy = 1\nspeed = 2\n").find("give one of"),
            std::string::npos);
  EXPECT_NE(problemOf(base + "time = 9\nenergy = 1\n").find("after the scene's end"),
            std::string::npos);
  EXPECT_NE(
      problemOf(base + "time = 0.5\nenergy = -1\n").find("release.1.energy: -1: out of range"),
      std::string::npos);
  std::string apart = kTwoCarts;
  apart.replace(apart.find("position = 0.3\n"), 14, "position = 0.4");
  EXPECT_NE(problemOf(apart + "[[release]]\nbodies = [1, 2]\ntime = 0\nenergy = 1\n")
                .find("they do not touch at t = 0;"),
            std::string::npos);
  const std::string plane = problemOf(
      "dimensions = 2\n[[body]]\nmass = 1\nradius = 0.1\nposition = [0, 0]\n[[body]]\nmass = 1\n"
      "radius = 0.1\nposition = [0.2, 0]\n[[release]]\nbodies = [1, 2]\ntime = 0\nenergy = 1\n");
  EXPECT_NE(plane.find("releases in 1D scenes only"), std::string::npos) << plane;
}

TEST(EnergyReleaseSceneTest, PresetsReleaseBetweenTouchingBodies) {
  for (const char* name : {"spring-carts", "recoil"}) {
    const SceneDesc scene = loadPreset(name);
    ASSERT_EQ(scene.releases.size(), 1u) << name;
    EXPECT_TRUE(scene.releases[0].energy_J.has_value()) << name;
    EXPECT_EQ(parseSceneText(sceneToToml(scene), "again").releases, scene.releases) << name;
  }
}

}  // namespace energy_release_scene_test
}  // namespace collide::scene
