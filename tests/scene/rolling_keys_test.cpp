// SPDX-License-Identifier: MIT
// Rolling balls' scene keys: the scene's rolling, a body's rolling_mu and spin; read,
// written back, and refused where a rolling table cannot be, one line naming what is allowed.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_io.hpp"
#include "scene_problem.hpp"

namespace collide::scene {
namespace rolling_keys_test {

using testing::problemOf;

// A rolling table with one ball; `extra_top` and `extra_body` add lines.
std::string table(const std::string& extra_top = "", const std::string& extra_body = "") {
  return "dimensions = 2\nrolling = true\n" + extra_top +
         "\n[[body]]\nname = \"cue\"\nmass = 0.17\nradius = 0.03\nposition = [0, 0]\n"
         "velocity = [1, 0]\nfriction = 0.2\nrolling_mu = 0.01\nspin = \"draw\"\n" +
         extra_body;
}

TEST(RollingKeysTest, ReadsTheKeysAndWritesThemBack) {
  const SceneDesc scene = parseSceneText(table(), "s");
  EXPECT_TRUE(scene.rolling);
  EXPECT_EQ(scene.bodies[0].rolling_friction, 0.01);
  EXPECT_EQ(scene.bodies[0].spin, "draw");
  EXPECT_EQ(parseSceneText(sceneToToml(scene), "again"), scene);
}

TEST(RollingKeysTest, RefusesWhatARollingTableCannotGoWith) {
  // Without sliding friction, whose own check would speak first.
  std::string slope = table("gravity = [0, -9.81]");
  slope.erase(slope.find("friction = 0.2\n"), 15);
  const std::string tilted = problemOf(slope);
  EXPECT_NE(tilted.find("rolling balls with gravity in the plane; allowed: a level table"),
            std::string::npos)
      << tilted;
  const std::string sticking = problemOf(table("[contact]\ninelastic = \"stick\""));
  EXPECT_NE(sticking.find("allowed: contact.model = \"impulse\" with inelastic = \"slip\""),
            std::string::npos)
      << sticking;
  std::string masse = table();
  masse.replace(masse.find("\"draw\""), 6, "\"masse\"");
  const std::string spin = problemOf(masse);
  EXPECT_NE(spin.find("body.1.spin: "), std::string::npos) << spin;
  std::string flat = table();
  flat.replace(flat.find("rolling = true"), 14, "rolling = false");
  const std::string keyed = problemOf(flat);
  EXPECT_NE(keyed.find("allowed: them with rolling = true"), std::string::npos) << keyed;
}

}  // namespace rolling_keys_test
}  // namespace collide::scene
