// The preset library: every preset issue 6 asks for exists, is valid, and `presets show` prints a
// scene file that loads back to the same scene.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "scene/scene_io.hpp"

namespace collide::scene {
namespace {

TEST(PresetsTest, TheLibraryHasEveryPresetOnce) {
  const std::vector<std::string> wanted = {"worked-example",
                                           "elastic",
                                           "perfectly-inelastic",
                                           "compare-restitution",
                                           "heavy-light",
                                           "car-crash",
                                           "accident-reconstruction",
                                           "air-drag",
                                           "clay",
                                           "bullet-block",
                                           "ballistic-pendulum",
                                           "air-track",
                                           "bouncing-ball",
                                           "air-drag-throw",
                                           "newtons-cradle",
                                           "billiards-glancing",
                                           "billiards-break",
                                           "billiards-follow",
                                           "billiards-draw",
                                           "stick-2d",
                                           "granular-chain",
                                           "soft-contact",
                                           "pi-blocks",
                                           "ideal-gas",
                                           "spring-carts",
                                           "recoil"};
  std::set<std::string> names;
  for (const PresetInfo& info : presetList()) EXPECT_TRUE(names.insert(info.name).second);
  for (const std::string& name : wanted) EXPECT_TRUE(names.count(name)) << name;
  EXPECT_EQ(names.size(), wanted.size());
}

TEST(PresetsTest, EveryPresetShowsAsAFileThatLoadsBackEqual) {
  for (const PresetInfo& info : presetList()) {
    SCOPED_TRACE(info.name);
    const SceneDesc preset = loadPreset(info.name);
    EXPECT_EQ(preset.name, info.name);
    const std::string text = presetToml(info.name);
    SceneDesc loaded;
    ASSERT_NO_THROW(loaded = parseSceneText(text, info.name + ".toml")) << text;
    EXPECT_EQ(loaded, preset) << text;
  }
}

TEST(PresetsTest, EveryPresetLoadsThroughTheValidatingReader) {
  for (const PresetInfo& info : presetList()) {
    SCOPED_TRACE(info.name);
    EXPECT_EQ(loadScene(info.name), loadPreset(info.name));
  }
}

TEST(PresetsTest, PhysicallySensibleNumbers) {
  const SceneDesc ball = loadPreset("bouncing-ball");
  EXPECT_EQ(ball.dimensions, 2);
  EXPECT_EQ(ball.restitution, 0.8);
  EXPECT_EQ(ball.gravity_mps2, core::Vec2(0.0, -9.81));
  EXPECT_EQ(ball.view.strobe_rate_hz, 0.0);  // the strobe chooses its rate
  ASSERT_EQ(ball.walls.size(), 1u);
  EXPECT_EQ(wallRestitution(ball, ball.walls[0]), 0.8);

  const SceneDesc cradle = loadPreset("newtons-cradle");
  ASSERT_EQ(cradle.bodies.size(), 5u);
  EXPECT_EQ(cradle.restitution, 1.0);
  // Ball 1 pulled 30 degrees to the left on its string, the others hanging straight down.
  for (const BodyDesc& ball : cradle.bodies) ASSERT_TRUE(ball.pivot_m.has_value());
  EXPECT_LT(cradle.bodies[0].position_m.x(), cradle.bodies[0].pivot_m->x());
  EXPECT_EQ(cradle.bodies[1].position_m.x(), cradle.bodies[1].pivot_m->x());
  for (std::size_t i = 2; i < 5; ++i) {  // resting balls touch exactly
    EXPECT_EQ(cradle.bodies[i].position_m.x() - cradle.bodies[i - 1].position_m.x(),
              2.0 * cradle.bodies[i].size_m);
    EXPECT_EQ(cradle.bodies[i].mass_kg, cradle.bodies[0].mass_kg);
  }

  for (int digits = 1; digits <= 9; ++digits) {
    const SceneDesc pi = makePreset("pi-blocks", {{"digits", digits}});
    EXPECT_EQ(pi.bodies[1].mass_kg / pi.bodies[0].mass_kg, std::pow(100.0, digits - 1));
  }
  EXPECT_EQ(loadPreset("billiards-break").bodies.size(), 16u);
  EXPECT_EQ(makePreset("billiards-break", {{"rows", 2}}).bodies.size(), 4u);
  EXPECT_EQ(loadPreset("compare-restitution").view.panel_values,
            (std::vector<double>{1.0, 0.5, 0.0}));
  EXPECT_EQ(loadPreset("stick-2d").contact.inelastic, InelasticMode::kStick);
  EXPECT_EQ(loadPreset("soft-contact").contact.model, ContactModelKind::kSpringDamper);
  EXPECT_EQ(loadPreset("granular-chain").pairs.size(), 5u);
}

TEST(PresetsTest, ParametricPresetsShowTheirParameters) {
  const std::string text = presetToml("pi-blocks");
  EXPECT_NE(text.find("preset = \"pi-blocks\""), std::string::npos) << text;
  EXPECT_NE(text.find("\ndigits = 3 "), std::string::npos) << text;
  EXPECT_THROW(presetToml("no-such-preset"), SceneError);
}

// The pictures number a scene's bodies by their place in it (m₁, v₂′, the tag "3"), and the alt
// text, narration and data files call them by name: a name that ends in a number must be that
// number, or a reader holding both reads the wrong body (granular-chain called its second body
// "block 1"). Scenes of more than 8 bodies are left out: their pictures list no body's values and
// billiards-break's rack keeps the balls' own numbers, 1 to 15 after the unnumbered cue ball.
TEST(PresetsTest, ABodyNamedWithANumberIsThePictureNumberOfThatBody) {
  constexpr std::size_t kMostNamedBodies = 8;
  for (const PresetInfo& info : presetList()) {
    const SceneDesc scene = loadPreset(info.name);
    if (scene.bodies.size() > kMostNamedBodies) continue;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
      const std::string& name = scene.bodies[i].name;
      const std::size_t space = name.rfind(' ');
      if (space == std::string::npos) continue;
      const std::string last = name.substr(space + 1);
      if (last.empty() || last.find_first_not_of("0123456789") != std::string::npos) continue;
      EXPECT_EQ(std::stoul(last), i + 1)
          << info.name << ": body " << i + 1 << " is \"" << name << "\"";
    }
  }
}

}  // namespace
}  // namespace collide::scene
