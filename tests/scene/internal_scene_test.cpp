// SPDX-License-Identifier: MIT
// The scene key `internal` (molecules with insides): 0, 1 or 2 internal degrees of freedom, for
// free disks in a plane whose impacts keep energy; refused elsewhere with one line saying so.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_io.hpp"
#include "scene_problem.hpp"

namespace collide::scene {
namespace internal_scene_test {

const char* const kTwoDisks = R"(
dimensions = 2
[[body]]
name = "a"
shape = "disk"
mass = 1
radius = 0.1
position = [-0.5, 0]
velocity = [1, 0]
[[body]]
name = "b"
shape = "disk"
mass = 1
radius = 0.1
position = [0.5, 0]
)";

using testing::problemOf;

TEST(InternalSceneTest, DisksTakeOneOrTwoInternalDegreesOfFreedomAndWriteThemBack) {
  EXPECT_EQ(parseSceneText(kTwoDisks, "s").internal_dof, 0);
  for (int dof : {1, 2}) {
    const SceneDesc scene =
        parseSceneText("internal = " + std::to_string(dof) + "\n" + kTwoDisks, "s");
    EXPECT_EQ(scene.internal_dof, dof);
    EXPECT_EQ(parseSceneText(sceneToToml(scene), "again"), scene);
  }
  // The gas preset takes it as an override.
  EXPECT_EQ(loadScene("ideal-gas", {parseSetExpression("internal=1")}).internal_dof, 1);
}

TEST(InternalSceneTest, RefusedBeyondTwoOnALineAndWhereImpactsLoseEnergy) {
  const std::string three = problemOf(std::string("internal = 3\n") + kTwoDisks);
  EXPECT_NE(three.find("internal: 3: out of range; allowed: internal degrees of freedom per disk, "
                       "a whole number from 0 to 2"),
            std::string::npos)
      << three;
  const std::string line = problemOf(
      "internal = 1\ndimensions = 1\n[[body]]\nmass = 1\nwidth = 0.5\nposition = 0\n"
      "[[body]]\nmass = 1\nwidth = 0.5\nposition = 2\n");
  EXPECT_NE(line.find("allowed: internal with dimensions = 2 (disks)"), std::string::npos) << line;
  const std::string lossy = problemOf(std::string("internal = 2\nrestitution = 0.9\n") + kTwoDisks);
  EXPECT_NE(lossy.find("allowed: internal with restitution = 1 (walls may take their own e)"),
            std::string::npos)
      << lossy;
  const std::string soft = problemOf(std::string("internal = 2\n") + kTwoDisks +
                                     "[contact]\nmodel = \"spring-damper\"\n");
  EXPECT_NE(soft.find("allowed: internal with contact.model = \"impulse\""), std::string::npos)
      << soft;
}

}  // namespace internal_scene_test
}  // namespace collide::scene
