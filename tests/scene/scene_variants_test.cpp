// SPDX-License-Identifier: MIT
// Comparison panels' scenes come from scene::panelVariants by value: each panel is the scene with
// its parameter set to exactly that double (no printing and reading back), the rest unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "scene/scene_io.hpp"

namespace collide::scene {
namespace {

SceneDesc withPanels(const std::string& parameter, const std::vector<double>& values) {
  SceneDesc scene = loadScene("worked-example");
  scene.view.panel_parameter = parameter;
  scene.view.panel_values = values;
  return scene;
}

TEST(SceneVariantsTest, ASceneWithoutPanelsIsItsOwnOnlyVariant) {
  const SceneDesc scene = loadScene("worked-example");
  const std::vector<SceneVariant> variants = panelVariants(scene);
  ASSERT_EQ(variants.size(), 1u);
  EXPECT_EQ(variants[0].scene, scene);
}

TEST(SceneVariantsTest, EachPanelHoldsItsValueExactlyAndNothingElseChanges) {
  // Values whose shortest decimal forms differ from every 6- or 15-digit printing: a value that
  // went through text at too few digits would come back as a neighbouring double.
  const double third = 1.0 / 3.0;
  const double next_after_half = std::nextafter(0.5, 1.0);
  const std::vector<double> values{1.0, third, next_after_half, 0.0};
  const SceneDesc scene = withPanels("restitution", values);
  const std::vector<SceneVariant> variants = panelVariants(scene);
  ASSERT_EQ(variants.size(), values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    EXPECT_EQ(variants[i].value, values[i]);
    EXPECT_EQ(variants[i].scene.restitution, values[i]) << "panel " << i;
    // Everything but the restitution is the base scene's, the panels included; the title is
    // filled again from the same template (it may quote e).
    SceneDesc expected = scene;
    expected.restitution = values[i];
    EXPECT_EQ(variants[i].scene.title_template, scene.title_template);
    expected.title = variants[i].scene.title;
    EXPECT_EQ(variants[i].scene.bodies, expected.bodies) << "panel " << i;
    EXPECT_EQ(variants[i].scene.view, expected.view) << "panel " << i;
    EXPECT_EQ(variants[i].scene, expected) << "panel " << i;
  }
}

TEST(SceneVariantsTest, ABodyKeySetsThatBodysValue) {
  const SceneDesc scene = withPanels("body.2.mass", {0.25, 4.0});
  const std::vector<SceneVariant> variants = panelVariants(scene);
  ASSERT_EQ(variants.size(), 2u);
  EXPECT_EQ(variants[0].scene.bodies.at(1).mass_kg, 0.25);
  EXPECT_EQ(variants[1].scene.bodies.at(1).mass_kg, 4.0);
  EXPECT_EQ(variants[1].scene.bodies.at(0), scene.bodies.at(0));
}

TEST(SceneVariantsTest, AValueTheSceneRefusesNamesThePanelAndTheRule) {
  const SceneDesc scene = withPanels("restitution", {1.0, 2.0});
  try {
    panelVariants(scene);
    FAIL() << "a restitution of 2 accepted";
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("view.panel_values (restitution)"), std::string::npos) << message;
    EXPECT_NE(message.find("out of range"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace collide::scene
