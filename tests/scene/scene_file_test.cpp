// Reading valid scene files: every key lands in the SceneDesc with its unit, defaults apply, and a
// file with `preset = "NAME"` changes a preset.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scene/scene_io.hpp"
#include "scratch.hpp"

namespace collide::scene {
namespace {

TEST(SceneFileTest, ReadsEveryKeyOfA1DScene) {
  const SceneDesc scene = parseSceneText(R"(
name = "carts"
title = "Two carts"
dimensions = 1
duration = 3        # an integer is a number too
gravity = 0
restitution = 0.25

[[body]]
name = "left"
mass = 2
size = 0.4
position = -1.5
velocity = 1.0
color = "#ff8000"

[[body]]
shape = "disk"
mass = 0.5
size = 0.1
position = [1.0, 0]
color = [0, 128, 255]

[[wall]]
position = -3.0

[[pair]]
bodies = ["left", 2]
restitution = 0.75

[restitution_law]
kind = "table"
table = [[0, 0.9], [2.5, 0.5]]

[contact]
model = "spring-damper"
duration = 0.05

[view]
theme = "dark"
chart = "momentum"
trail = 0.5
panels = { parameter = "restitution", values = [1, 0] }
)",
                                         "carts.toml");
  EXPECT_EQ(scene.name, "carts");
  EXPECT_EQ(scene.title, "Two carts");
  EXPECT_EQ(scene.dimensions, 1);
  EXPECT_EQ(scene.duration_s, 3.0);
  EXPECT_EQ(scene.restitution, 0.25);
  ASSERT_EQ(scene.bodies.size(), 2u);
  EXPECT_EQ(scene.bodies[0].name, "left");
  EXPECT_EQ(scene.bodies[0].shape, "block");
  EXPECT_EQ(scene.bodies[0].mass_kg, 2.0);
  EXPECT_EQ(scene.bodies[0].position_m, core::Vec2(-1.5, 0.0));
  EXPECT_EQ(scene.bodies[0].velocity_mps, core::Vec2(1.0, 0.0));
  EXPECT_EQ(scene.bodies[0].color, (Rgb{255, 128, 0}));
  EXPECT_EQ(scene.bodies[1].name, "body 2");
  EXPECT_EQ(scene.bodies[1].shape, "disk");
  EXPECT_EQ(scene.bodies[1].velocity_mps, core::Vec2(0.0, 0.0));
  EXPECT_EQ(scene.bodies[1].color, (Rgb{0, 128, 255}));
  ASSERT_EQ(scene.walls.size(), 1u);
  EXPECT_EQ(scene.walls[0].name, "wall 1");
  EXPECT_EQ(scene.walls[0].normal, core::Vec2(1.0, 0.0)) << "inferred: the bodies are right of it";
  EXPECT_FALSE(scene.walls[0].restitution.has_value());
  EXPECT_EQ(wallRestitution(scene, scene.walls[0]), 0.25);
  ASSERT_EQ(scene.pairs.size(), 1u);
  EXPECT_EQ(scene.pairs[0], (PairDesc{0, 1, 0.75}));
  EXPECT_EQ(scene.restitution_law.kind, RestitutionLawKind::kTable);
  ASSERT_EQ(scene.restitution_law.table.size(), 2u);
  EXPECT_EQ(scene.restitution_law.table[1], std::make_pair(2.5, 0.5));
  EXPECT_EQ(scene.contact.model, ContactModelKind::kSpringDamper);
  EXPECT_EQ(scene.contact.duration_s, 0.05);
  EXPECT_EQ(scene.view.theme, "dark");
  EXPECT_TRUE(scene.view.chart);
  EXPECT_EQ(scene.view.chart_quantity, "momentum");
  EXPECT_EQ(scene.view.trail_s, 0.5);
  EXPECT_EQ(scene.view.panel_parameter, "restitution");
  EXPECT_EQ(scene.view.panel_values, (std::vector<double>{1.0, 0.0}));
}

TEST(SceneFileTest, ReadsA2DSceneWithABoxAndGravity) {
  const SceneDesc scene = parseSceneText(R"(
dimensions = 2
gravity = [0, -9.81]
[[body]]
mass = 1
size = 0.1
position = [0, 0.5]
velocity = [1, 2]
[[wall]]
name = "ramp"
position = [0, 0]
normal = [0, 2]
restitution = 0.5
[box]
min = [-1, -1]
max = [1, 1]
[contact]
inelastic = "stick"
)",
                                         "My Scene (2).toml");
  EXPECT_EQ(scene.name, "My-Scene--2-") << "the file stem, made safe for output names";
  EXPECT_EQ(scene.title, scene.name);
  EXPECT_EQ(scene.gravity_mps2, core::Vec2(0.0, -9.81));
  EXPECT_EQ(scene.bodies[0].shape, "disk");
  EXPECT_EQ(scene.walls[0].normal, core::Vec2(0.0, 1.0)) << "normalized";
  EXPECT_EQ(scene.walls[0].restitution, 0.5);
  ASSERT_TRUE(scene.box.has_value());
  EXPECT_EQ(scene.contact.inelastic, InelasticMode::kStick);
  const std::vector<WallDesc> walls = allWalls(scene);
  ASSERT_EQ(walls.size(), 5u);
  EXPECT_EQ(walls[4].name, "box top");
  EXPECT_EQ(walls[4].normal, core::Vec2(0.0, -1.0));
}

TEST(SceneFileTest, AFileCanStartFromAPresetAndChangeIt) {
  const SceneDesc scene = parseSceneText(R"(
preset = "pi-blocks"
digits = 4
title = "Four digits"
[view]
theme = "dark"
)",
                                         "pi4.toml");
  EXPECT_EQ(scene.title, "Four digits");
  EXPECT_EQ(scene.name, "pi-blocks") << "the preset's name, which the file did not change";
  EXPECT_EQ(scene.bodies[1].mass_kg, 1e6);
  EXPECT_EQ(scene.view.theme, "dark");
  EXPECT_EQ(scene.parameters.at("digits"), 4.0);
}

TEST(SceneFileTest, LoadSceneReadsFilesAndPresets) {
  const test::ScratchDir scratch("collide_scene_file_test_");
  const std::filesystem::path path = scratch.path() / "collide_scene_file_test.toml";
  {
    std::ofstream out(path);
    out << "[[body]]\nmass = 1\nsize = 1\nposition = 0\n";
  }
  const SceneDesc from_file = loadScene(path.string());
  EXPECT_EQ(from_file.name, "collide_scene_file_test");
  EXPECT_EQ(from_file.bodies.size(), 1u);
  std::filesystem::remove(path);
  EXPECT_EQ(loadScene("worked-example"), loadPreset("worked-example"));
}

TEST(SceneFileTest, WriterOutputReadsBackEqual) {
  SceneDesc scene = parseSceneText(R"(
title = "quote \" and backslash \\ and K\u00F6rper \U0001F600"
dimensions = 2
restitution = 0.1
[[body]]
name = "a"
mass = 0.1
size = 0.3
position = [0.1, 0.7]
velocity = [1e-7, -3.3333333333333335]
[[body]]
name = "b"
mass = 1e16
size = 0.3
position = [2, 0.7]
[[pair]]
bodies = [1, 2]
restitution = 0.3
[restitution_law]
kind = "speed-threshold"
threshold_speed = 0.5
exponent = 0.3
[view]
slow_motion = 3
center_of_mass = true
)",
                                   "w.toml");
  EXPECT_EQ(parseSceneText(sceneToToml(scene), "again.toml"), scene) << sceneToToml(scene);
}

}  // namespace
}  // namespace collide::scene
