// Scene keys of bodies on strings: pivot, length and angle, string_restitution and arc_trail,
// read, checked and written back.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "scene/scene_io.hpp"

namespace collide::scene {
namespace string_keys_test {

const std::string kHanging = R"(dimensions = 2
gravity = [0, -9.81]
string_restitution = 0.25
[[body]]
name = "bob"
mass = 1
size = 0.1
pivot = [1, 2]
length = 0.8
angle = -30
[view]
arc_trail = true
)";

TEST(StringKeysTest, LengthAndAngleSetThePositionBelowThePivot) {
  const SceneDesc scene = parseSceneText(kHanging, "s.toml");
  ASSERT_EQ(scene.bodies.size(), 1u);
  const BodyDesc& bob = scene.bodies[0];
  ASSERT_TRUE(bob.pivot_m.has_value());
  EXPECT_EQ(*bob.pivot_m, core::Vec2(1.0, 2.0));
  // 30 degrees to the left of straight down: (1 - 0.8 sin 30, 2 - 0.8 cos 30).
  const double a = 30.0 * std::numbers::pi / 180.0;
  EXPECT_NEAR(bob.position_m.x(), 1.0 - 0.8 * std::sin(a), 1e-15);
  EXPECT_NEAR(bob.position_m.y(), 2.0 - 0.8 * std::cos(a), 1e-15);
  EXPECT_EQ(scene.string_restitution, 0.25);
  EXPECT_TRUE(scene.view.arc_trail);
}

TEST(StringKeysTest, WrittenSceneReadsBackEqual) {
  const SceneDesc scene = parseSceneText(kHanging, "s.toml");
  const std::string text = sceneToToml(scene);
  EXPECT_NE(text.find("pivot = [1.0, 2.0]"), std::string::npos) << text;
  EXPECT_EQ(parseSceneText(text, "again.toml"), scene) << text;
}

TEST(StringKeysTest, APivotWithAPositionTakesTheLengthFromIt) {
  const SceneDesc scene = parseSceneText(
      "dimensions = 2\ngravity = [0, -9.81]\n[[body]]\nmass = 1\nsize = 0.1\n"
      "position = [0.6, -0.8]\npivot = [0, 0]\n",
      "s.toml");
  EXPECT_EQ(scene.bodies[0].position_m, core::Vec2(0.6, -0.8));
  EXPECT_EQ(*scene.bodies[0].pivot_m, core::Vec2(0.0, 0.0));
}

}  // namespace string_keys_test
}  // namespace collide::scene
