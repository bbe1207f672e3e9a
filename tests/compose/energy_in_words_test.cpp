// SPDX-License-Identifier: MIT
// Energy that comes in or goes inside, in words and on the chart (issue 44): a strobe of a
// release says the bodies start together at rest and are pushed apart (no impact); the energy
// chart of molecules with insides draws the equipartition levels, which follow from the energy at
// the start (all kinetic: the insides start empty) and the degrees of freedom (2 translational per
// disk in a plane, zeta internal): KE relaxes to 2/(2 + zeta) of it, the insides to zeta/(2 +
// zeta); the alt text and the narration name the internal energy, which conservation says is the
// kinetic energy the disks no longer have.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "app/world_from_scene.hpp"
#include "physics/simulate.hpp"
#include "report/alt_text.hpp"
#include "report/narration.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace energy_in_words_test {

TEST(EnergyInWordsTest, StrobeOfAReleaseSaysTheBodiesStartTogetherAndArePushedApart) {
  for (const auto& [preset, words] :
       {std::pair{"spring-carts",
                  "cart 1 and cart 2 start together at rest, pushed apart at "
                  "t = 0.500 s"},
        std::pair{"recoil",
                  "rifle and bullet start together at rest, pushed apart at "
                  "t = 0.250 s"}}) {
    const app::Animation animation = app::animate(scene::loadPreset(preset), {640, 360});
    const std::string caption = animation.frames.strobeFrame(0.0).panels.front().caption;
    EXPECT_NE(caption.find(words), std::string::npos) << caption;
    // The push is no collision, and its image is where they stood from the start.
    EXPECT_EQ(caption.find("collision"), std::string::npos) << caption;
    EXPECT_EQ(caption.find("push"), caption.find("pushed apart")) << caption;
  }
  const app::Animation plain = app::animate(scene::loadPreset("worked-example"), {640, 360});
  EXPECT_EQ(plain.frames.strobeFrame(0.0).panels.front().caption.find("pushed apart"),
            std::string::npos);
}

// A still after the push tells it: Q and the bodies, at the release's time; before, nothing.
TEST(EnergyInWordsTest, AltTextOfAStillAfterAReleaseTellsThePush) {
  const scene::SceneDesc scene = scene::loadPreset("spring-carts");
  ASSERT_EQ(scene.releases.size(), 1u);
  const physics::Timeline timeline = physics::simulate(app::worldFromScene(scene));
  const std::string after = report::describeStill(timeline, "", 1.5);
  EXPECT_NE(after.find(" At t = 0.500 s stored energy of 3.00 J pushed cart 1 and cart 2 apart. "),
            std::string::npos)
      << after;
  EXPECT_EQ(scene.releases[0].energy_J, 3.0);  // the sentence's 3.00 J
  EXPECT_NE(after.find("No collision has happened yet."), std::string::npos) << after;
  EXPECT_EQ(report::describeStill(timeline, "", 0.25).find("pushed"), std::string::npos);
}

// The gas with insides, shortened: its energy at the start is all kinetic.
scene::SceneDesc gasWithInsides(int internal_dof, double duration_s) {
  scene::SceneDesc scene = scene::loadPreset("ideal-gas");
  scene.internal_dof = internal_dof;
  scene.duration_s = duration_s;
  scene.view.chart_quantity = "energy";
  return scene;
}

double kineticAtStart_J(const scene::SceneDesc& scene) {
  double energy_J = 0.0;
  for (const scene::BodyDesc& body : scene.bodies) {
    energy_J += 0.5 * body.mass_kg * body.velocity_mps.squaredNorm();
  }
  return energy_J;
}

std::vector<frame::ChartSeries> equipartitionLines(const frame::ChartModel& chart) {
  std::vector<frame::ChartSeries> lines;
  for (const frame::ChartSeries& series : chart.series) {
    if (series.label == "equipartition") lines.push_back(series);
  }
  return lines;
}

TEST(EnergyInWordsTest, GasChartDrawsTheEquipartitionLevelsDashed) {
  for (int zeta : {0, 1, 2}) {
    SCOPED_TRACE(zeta);
    const scene::SceneDesc scene = gasWithInsides(zeta, 1.0);
    const app::Animation animation = app::animate(scene, {640, 360});
    const frame::ChartModel chart = animation.frames.chartFrame().charts.at(0);
    ASSERT_EQ(chart.y_label, "energy (J)");
    const std::vector<frame::ChartSeries> lines = equipartitionLines(chart);
    const double total_J = kineticAtStart_J(scene);
    // Each degree of freedom holds total / (2 + zeta) per disk's share: one level where the
    // translational and internal levels meet (zeta = 2), none without insides.
    std::vector<double> levels;
    if (zeta > 0) levels.push_back(total_J * 2.0 / (2.0 + zeta));
    if (zeta == 1) levels.push_back(total_J * zeta / (2.0 + zeta));
    ASSERT_EQ(lines.size(), levels.size());
    for (std::size_t k = 0; k < lines.size(); ++k) {
      EXPECT_TRUE(lines[k].dashed);
      ASSERT_EQ(lines[k].points.size(), 2u);
      EXPECT_EQ(lines[k].points[0].x(), 0.0);
      EXPECT_EQ(lines[k].points[1].x(), scene.duration_s);
      for (const core::Vec2& point : lines[k].points) {
        EXPECT_NEAR(point.y(), levels[k], 1e-9 * total_J);
      }
    }
  }
}

// The energy written just before `words` ("0.650 J held inside ..."), in J; -1 where absent.
double energyBefore(const std::string& text, const std::string& words) {
  const std::size_t at = text.find(words);
  if (at == std::string::npos) return -1.0;
  std::istringstream before(text.substr(0, at));
  std::vector<std::string> tokens;
  for (std::string token; before >> token;) tokens.push_back(token);
  if (tokens.size() < 2) return -1.0;
  const double value = std::stod(tokens[tokens.size() - 2]);
  return tokens.back() == "mJ" ? value * 1e-3 : value;
}

TEST(EnergyInWordsTest, AltTextAndNarrationNameTheInternalEnergy) {
  const scene::SceneDesc scene = gasWithInsides(1, 1.0);
  const physics::Timeline timeline = physics::simulate(app::worldFromScene(scene));
  const double start_J = kineticAtStart_J(scene);
  // What the disks no longer have as kinetic energy is inside them (nothing is lost).
  const double t_s = 1.0;
  const double inside_J = start_J - timeline.kineticEnergy(timeline.sample(t_s));
  ASSERT_GT(inside_J, 0.1 * start_J);
  const std::string alt = report::describeStill(timeline, "", t_s);
  // Three figures, the parts rounded together: within a unit of the last figure.
  EXPECT_NEAR(energyBefore(alt, " held inside the molecules as internal energy"), inside_J,
              0.01 * inside_J)
      << alt;
  const std::vector<report::Cue> cues = report::narrate(timeline, {"", t_s});
  const std::string& closing = cues.back().text;
  EXPECT_NEAR(energyBefore(closing, " is held inside the molecules as internal energy"), inside_J,
              0.01 * inside_J)
      << closing;
  EXPECT_NE(closing.find("kinetic and internal energy add up to"), std::string::npos) << closing;
  // The first pair's cue says which way its kinetic energy went: into the insides or out.
  const physics::CollisionEvent* pair = nullptr;
  for (const physics::CollisionEvent& event : timeline.collisions()) {
    if (!event.hitsWall()) {
      pair = &event;
      break;
    }
  }
  ASSERT_NE(pair, nullptr);
  const auto kinetic_J = [&](const core::Vec2& va, const core::Vec2& vb) {
    return 0.5 * scene.bodies[std::size_t(pair->body_a)].mass_kg * va.squaredNorm() +
           0.5 * scene.bodies[std::size_t(pair->body_b)].mass_kg * vb.squaredNorm();
  };
  const bool gained = kinetic_J(pair->velocity_a_after_mps, pair->velocity_b_after_mps) >
                      kinetic_J(pair->velocity_a_before_mps, pair->velocity_b_before_mps);
  const auto cue = std::find_if(cues.begin(), cues.end(), [](const report::Cue& c) {
    return c.text.find(" hits disk ") != std::string::npos;
  });
  ASSERT_NE(cue, cues.end());
  EXPECT_NE(cue->text.find(gained ? "of internal energy turns into kinetic energy."
                                  : "of kinetic energy goes inside the molecules."),
            std::string::npos)
      << cue->text;
}

}  // namespace energy_in_words_test
}  // namespace collide
