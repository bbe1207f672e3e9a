// SPDX-License-Identifier: MIT
// Air drag's scene keys: a body's drag_linear (kg/s) and drag_quadratic (kg/m); what they cannot
// go with is refused, one line naming what was typed and what is allowed.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_io.hpp"
#include "scene_problem.hpp"

namespace collide::scene {
namespace drag_keys_test {

// A glider with a sail and one without on a 1D track; `sail` gives the first one's drag, `top`
// goes before the bodies.
std::string gliders(const std::string& sail = "drag_linear = \"50 g/s\"",
                    const std::string& top = "dimensions = 1") {
  return top + R"(
[[body]]
name = "sail"
mass = 0.2
width = 0.15
position = -1
velocity = 1.2
)" + sail +
         R"(
[[body]]
name = "glider"
mass = 0.2
width = 0.15
position = 0.5
drag_quadratic = 0.01
)";
}

using testing::problemOf;

TEST(DragKeysTest, ReadsTheCoefficientsInTheirUnitsAndWritesThemBack) {
  const SceneDesc scene = parseSceneText(gliders(), "s");
  EXPECT_DOUBLE_EQ(scene.bodies[0].drag_linear_kgps, 0.05);
  EXPECT_EQ(scene.bodies[0].drag_quadratic_kgpm, 0.0);
  EXPECT_EQ(scene.bodies[1].drag_quadratic_kgpm, 0.01);
  EXPECT_EQ(parseSceneText(sceneToToml(scene), "again"), scene);
  EXPECT_DOUBLE_EQ(
      parseSceneText(gliders("drag_quadratic = \"3 g/m\""), "s").bodies[0].drag_quadratic_kgpm,
      0.003);
}

TEST(DragKeysTest, RefusesANegativeCoefficientAndAUnitOfTheWrongKind) {
  const std::string negative = problemOf(gliders("drag_linear = -0.5"));
  EXPECT_NE(negative.find("body.1.drag_linear: -0.5: out of range; allowed: a linear drag "
                          "coefficient in kg/s from 0 to 1e+18"),
            std::string::npos)
      << negative;
  const std::string wrong = problemOf(gliders("drag_quadratic = \"2 kg/s\""));
  EXPECT_NE(wrong.find("a linear drag coefficient, not a quadratic drag coefficient"),
            std::string::npos)
      << wrong;
}

TEST(DragKeysTest, RefusesQuadraticDragInAPlaneOrWithGravityAlongTheTrack) {
  const std::string plane = problemOf(R"(
dimensions = 2
[[body]]
mass = 1
radius = 0.1
position = [0, 0]
drag_quadratic = 0.3
)");
  EXPECT_NE(plane.find("allowed: drag_quadratic on a 1D track (dimensions = 1)"), std::string::npos)
      << plane;
  const std::string sloped =
      problemOf(gliders("drag_quadratic = 0.02", "dimensions = 1\ngravity = -2"));
  EXPECT_NE(sloped.find("allowed: drag_quadratic without gravity along the track, or "
                        "drag_linear with it"),
            std::string::npos)
      << sloped;
  // Linear drag with gravity along the track is the falling ball's, and allowed.
  const SceneDesc falling = parseSceneText(R"(
dimensions = 1
gravity = -9.81
[[body]]
mass = 0.1
width = 0.05
position = 2
drag_linear = 0.02
)",
                                           "s");
  EXPECT_EQ(falling.bodies[0].drag_linear_kgps, 0.02);
}

TEST(DragKeysTest, TakesLinearDragInAPlaneButNotWithStickingClusters) {
  const std::string thrown = R"(
dimensions = 2
gravity = [0, -9.81]
[[body]]
mass = 0.06
radius = 0.03
position = [0, 0.03]
velocity = [8, 8]
drag_linear = "12 g/s"
)";
  EXPECT_DOUBLE_EQ(parseSceneText(thrown, "s").bodies[0].drag_linear_kgps, 0.012);
  const std::string stuck = problemOf(thrown + "[contact]\ninelastic = \"stick\"\n");
  EXPECT_NE(stuck.find("contact.inelastic = \"stick\" with air drag"), std::string::npos) << stuck;
  EXPECT_NE(stuck.find("allowed: drag with contact.inelastic = \"slip\""), std::string::npos)
      << stuck;
}

TEST(DragKeysTest, RefusesDragWithFrictionOrSoftContacts) {
  const std::string rough = problemOf(gliders("drag_linear = 0.05\nfriction = 0.3"));
  EXPECT_NE(rough.find("sliding friction and air drag in one scene; allowed: one of the two"),
            std::string::npos)
      << rough;
  const std::string soft = problemOf(gliders() + "[contact]\nmodel = \"spring-damper\"\n");
  EXPECT_NE(soft.find("allowed: drag with contact.model = \"impulse\""), std::string::npos) << soft;
}

}  // namespace drag_keys_test
}  // namespace collide::scene
