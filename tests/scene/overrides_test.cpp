// --set KEY=VALUE and the two-body shortcuts: applied to presets and files, validated like the
// file, and reported by how the user wrote them.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/scene_io.hpp"

namespace collide::scene {
namespace {

Override set(const std::string& text) {
  return parseSetExpression(text);
}

std::string problemWith(const std::string& scene, const std::vector<Override>& overrides) {
  try {
    loadScene(scene, overrides);
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted";
  return "";
}

TEST(OverridesTest, ParsesKeyEqualsValue) {
  const Override o = set("body.2.mass = 3");
  EXPECT_EQ(o.key, "body.2.mass");
  EXPECT_EQ(o.value, "3");
  EXPECT_EQ(o.origin, "--set body.2.mass = 3");
  for (const char* bad : {"restitution", "=3", "restitution=", ""}) {
    EXPECT_THROW(set(bad), SceneError) << bad;
  }
  try {
    set("mass");
    FAIL() << "'mass' accepted as KEY=VALUE";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()).substr(0, 33), "--set: 'mass': not KEY=VALUE; all");
  }
}

TEST(OverridesTest, ChangesTopLevelBodyAndViewValues) {
  const SceneDesc scene = loadScene(
      "worked-example", {set("restitution=0.3"), set("body.2.mass=3"), set("view.theme=dark"),
                         set("body.1.velocity=2.5"), set("title=\"New title\""),
                         set("view.panels={parameter=\"body.1.mass\", values=[1, 2]}")});
  EXPECT_EQ(scene.restitution, 0.3);
  EXPECT_EQ(scene.bodies[1].mass_kg, 3.0);
  EXPECT_EQ(scene.bodies[0].velocity_mps.x(), 2.5);
  EXPECT_EQ(scene.view.theme, "dark");
  EXPECT_EQ(scene.title, "New title");
  EXPECT_EQ(scene.view.panel_values, (std::vector<double>{1.0, 2.0}));
}

TEST(OverridesTest, PresetParametersRebuildThePreset) {
  const SceneDesc scene = loadScene("pi-blocks", {set("digits=6")});
  EXPECT_EQ(scene.bodies[1].mass_kg, 1e10);
  EXPECT_EQ(scene.parameters.at("digits"), 6.0);
  const SceneDesc two = loadScene("newtons-cradle", {set("moving=2")});
  EXPECT_LT(two.bodies[1].position_m.x(), two.bodies[1].pivot_m->x());  // pulled aside
  EXPECT_EQ(two.bodies[2].position_m.x(), two.bodies[2].pivot_m->x());  // hanging down
  EXPECT_EQ(problemWith("pi-blocks", {set("digits=12")}),
            "--set digits=12: digits: 12: allowed: digits of pi to count (mass ratio "
            "100^(digits-1)), a whole number from 1 to 9");
  EXPECT_NE(problemWith("pi-blocks", {set("digits=2.5")}).find("digits: 2.5: "), std::string::npos);
  EXPECT_EQ(problemWith("worked-example", {set("digits=6")}),
            "--set digits=6: digits: 6: not a parameter of this scene; allowed: with preset "
            "'pi-blocks' (e.g. collide render pi-blocks --set digits=6)");
}

TEST(OverridesTest, BadValuesAreReportedByTheOverride) {
  EXPECT_EQ(problemWith("worked-example", {set("body.2.mass=-3")}),
            "--set body.2.mass=-3: body.2.mass: -3: out of range; allowed: a mass in kg, more "
            "than 0 and at most 1e+18");
  EXPECT_EQ(problemWith("worked-example", {set("body.2.mas=3")}).substr(0, 70),
            "--set body.2.mas=3: body.2.mas: 3: unknown key; did you mean 'mass'? a");
  // The value is echoed as typed, not as TOML renders the number it parsed ("1e+06", "0.5").
  EXPECT_EQ(problemWith("worked-example", {set("m1=1e6")}).substr(0, 35),
            "--set m1=1e6: m1: 1e6: unknown key;");
  EXPECT_EQ(problemWith("worked-example", {set("body.1.mass=-5e-1")}).substr(0, 51),
            "--set body.1.mass=-5e-1: body.1.mass: -5e-1: out of");
  EXPECT_EQ(problemWith("worked-example", {set("body.9.mass=3")}),
            "--set body.9.mass=3: body.9.mass: 3: no body.9 in this scene; allowed: an index from "
            "1 to 2");
  EXPECT_NE(problemWith("worked-example", {set("restitution=[1,")}).find("not a TOML value"),
            std::string::npos);
  EXPECT_NE(problemWith("worked-example", {set("restitution=nan")})
                .find("--set restitution=nan: restitution: nan: not a finite number"),
            std::string::npos);
  EXPECT_NE(problemWith("worked-example", {set("wall.1.restitution=0.5")})
                .find("the scene has no wall entries"),
            std::string::npos);
  // A change that makes bodies overlap is found by the same checks as in a file.
  EXPECT_NE(problemWith("worked-example", {set("body.2.position=-1.8")})
                .find("--set body.2.position=-1.8: body.2.position: -1.8: overlaps body 1 ("),
            std::string::npos);
}

TEST(OverridesTest, ShortcutsSetMassSpeedAndDirection) {
  using Kind = Override::Kind;
  const SceneDesc line = loadScene("worked-example", {{"body.1.mass", "2", "--m1 2"},
                                                      {"body.2", "-3", "--v2 -3", Kind::kSpeed}});
  EXPECT_EQ(line.bodies[0].mass_kg, 2.0);
  EXPECT_EQ(line.bodies[1].velocity_mps, core::Vec2(-3.0, 0.0));
  EXPECT_NE(problemWith("worked-example", {{"body.1", "30", "--theta1 30", Kind::kDirection}})
                .find("--theta1 30: body.1: 30: this is a 1D scene"),
            std::string::npos);

  // The glancing-billiards cue ball moves at 1.5 m/s along +x.
  const SceneDesc plane = loadScene(
      "billiards-glancing",
      {{"body.1", "2", "--v1 2", Kind::kSpeed}, {"body.1", "90", "--theta1 90", Kind::kDirection}});
  EXPECT_NEAR(plane.bodies[0].velocity_mps.x(), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(plane.bodies[0].velocity_mps.y(), 2.0);
  EXPECT_NE(problemWith("billiards-glancing", {{"body.1", "-1", "--v1 -1", Kind::kSpeed}})
                .find("negative"),
            std::string::npos);
}

TEST(OverridesTest, TitlePlaceholdersTakeTheChangedValues) {
  EXPECT_EQ(loadPreset("worked-example").title, "Inelastic collision, e = 0.5");
  EXPECT_EQ(loadPreset("worked-example").title_template, "Inelastic collision, e = {restitution}");
  EXPECT_EQ(loadScene("worked-example", {set("restitution=0.25")}).title,
            "Inelastic collision, e = 0.25");
  EXPECT_EQ(loadScene("heavy-light", {set("body.2.mass=0.5")}).title,
            "Heavy meets light: 10 kg and 0.5 kg, e = 1");
  const SceneDesc scene = parseSceneText(
      "title = \"{{m}} = {body.1.mass} kg, x = {body.1.position}, g = {gravity}, {duration} s\"\n"
      "[[body]]\nmass = 2\nsize = 1\nposition = 3\n",
      "t.toml");
  EXPECT_EQ(scene.title, "{m} = 2 kg, x = 3, g = 0, 4 s");
  try {
    parseSceneText("title = \"e = {restitutoin}\"\n[[body]]\nmass = 2\nsize = 1\nposition = 3\n",
                   "t.toml");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()).substr(0, 57),
              "t.toml:1:9: title: \"e = {restitutoin}\": {restitutoin} nam");
  }
}

TEST(OverridesTest, WithOverridesChangesALoadedScene) {
  const SceneDesc base = loadPreset("worked-example");
  const SceneDesc changed = withOverrides(base, {set("restitution=0")});
  EXPECT_EQ(changed.restitution, 0.0);
  EXPECT_EQ(changed.bodies, base.bodies);
  try {
    withOverrides(base, {set("restitution=2")});
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()).substr(0, 40), "--set restitution=2: restitution: 2: out");
  }
}

}  // namespace
}  // namespace collide::scene
