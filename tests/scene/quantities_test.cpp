// SPDX-License-Identifier: MIT
// Scene values as textbooks write them (issue 39): quantities with units, arithmetic, speed and
// heading, targets placed by struck_by, width and radius; and the one-line problems each gets
// wrong. Expected numbers come from the units' definitions and plain trigonometry. In-process,
// a few milliseconds.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scene/scene_io.hpp"

namespace collide::scene {
namespace {

constexpr double kPiRad = 3.14159265358979323846;

std::string blockScene(const std::string& keys, const std::string& top = "") {
  return top + "[[body]]\nmass = 1\nwidth = 0.5\nposition = 0\n" + keys;
}

std::string firstProblem(const std::string& text, const std::vector<Override>& overrides = {}) {
  try {
    parseSceneText(text, "s.toml", overrides);
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return "";
}

TEST(QuantitiesTest, UnitsConvertToSi) {
  const SceneDesc scene = parseSceneText(
      "duration = \"1500 ms\"\ngravity = \"-981 cm/s^2\"\n[[body]]\nmass = \"25 g\"\n"
      "width = \"12 cm\"\nposition = \"-2 ft\"\nvelocity = \"60 km/h\"\n[[body]]\n"
      "mass = \"2 lb\"\nwidth = \"1 in\"\nposition = \"1 mi\"\nvelocity = \"-10 mph\"\n",
      "s.toml");
  EXPECT_EQ(scene.duration_s, 1.5);
  EXPECT_DOUBLE_EQ(scene.gravity_mps2.x(), -9.81);
  EXPECT_DOUBLE_EQ(scene.bodies[0].mass_kg, 0.025);
  EXPECT_DOUBLE_EQ(scene.bodies[0].size_m, 0.12);
  EXPECT_DOUBLE_EQ(scene.bodies[0].position_m.x(), -2 * 0.3048);
  EXPECT_DOUBLE_EQ(scene.bodies[0].velocity_mps.x(), 60.0 / 3.6);
  EXPECT_DOUBLE_EQ(scene.bodies[1].mass_kg, 2 * 0.45359237);
  EXPECT_DOUBLE_EQ(scene.bodies[1].size_m, 0.0254);
  EXPECT_DOUBLE_EQ(scene.bodies[1].position_m.x(), 1609.344);
  EXPECT_DOUBLE_EQ(scene.bodies[1].velocity_mps.x(), -10 * 1609.344 / 3600);
}

TEST(QuantitiesTest, ArithmeticIsEvaluatedOnceInDoublePrecision) {
  const SceneDesc scene = parseSceneText(
      blockScene("velocity = \"sqrt(3)/2\"\n", "restitution = \"2/3\"\nduration = \"1e-3\"\n"),
      "s.toml");
  EXPECT_EQ(scene.restitution, 2.0 / 3.0);
  EXPECT_EQ(scene.duration_s, 1e-3);
  EXPECT_EQ(scene.bodies[0].velocity_mps.x(), std::sqrt(3.0) / 2);
  const SceneDesc pendulum = parseSceneText(
      "dimensions = 2\ngravity = [0, -9.81]\n[[body]]\nmass = 1\nradius = 0.1\npivot = [0, 0]\n"
      "length = 1\nangle = \"pi/6 rad\"\n",
      "s.toml");
  EXPECT_NEAR(pendulum.bodies[0].position_m.x(), 0.5, 1e-15);  // sin 30 degrees
}

TEST(QuantitiesTest, AWrongUnitNamesTheKindExpected) {
  EXPECT_EQ(firstProblem(blockScene("velocity = \"25 g\"\n")),
            "s.toml:5:12: body.1.velocity: \"25 g\": a mass, not a velocity; allowed: a velocity "
            "in m/s, km/h, cm/s, mm/s, ft/s, mph");
  EXPECT_EQ(firstProblem(blockScene("", "restitution = \"30 deg\"\n")),
            "s.toml:1:15: restitution: \"30 deg\": an angle, not a number without a unit; "
            "allowed: a number without a unit");
  EXPECT_EQ(firstProblem(blockScene("", "duration = \"3 parsec\"\n")),
            "s.toml:1:12: duration: \"3 parsec\": a length, not a time; allowed: a time in s, "
            "ms, min, h");
  EXPECT_NE(firstProblem(blockScene("velocity = \"3 zorks\"\n")).find("'zorks' is not a unit"),
            std::string::npos);
  EXPECT_NE(firstProblem(blockScene("velocity = \"2*(3\"\n")).find("Missing parenthesis"),
            std::string::npos);
}

TEST(QuantitiesTest, UnquotedArithmeticIsToldToQuote) {
  EXPECT_EQ(firstProblem(blockScene("", "restitution = 2/3  # e\n")),
            "s.toml:1:15: restitution: 2/3: arithmetic and units are written in quotes; allowed: "
            "restitution = \"2/3\"");
  EXPECT_EQ(firstProblem("dimensions = 2\n[[body]]\nmass = 25 g\n"),
            "s.toml:3:8: mass: 25 g: arithmetic and units are written in quotes; allowed: "
            "mass = \"25 g\"");
  EXPECT_EQ(firstProblem("[[body]]\nvelocity = [sqrt(3)/2, 0.5]\n"),
            "s.toml:2:12: velocity: [sqrt(3)/2, 0.5]: arithmetic and units are written in quotes; "
            "allowed: velocity = [\"sqrt(3)/2\", 0.5]");
}

TEST(QuantitiesTest, CommandLineValuesTakeUnitsAndArithmeticAsTyped) {
  const std::string text =
      "dimensions = 2\n[[body]]\nmass = 1\nradius = 0.1\nposition = [0, 0]\nvelocity = [1, 0]\n";
  const SceneDesc scene =
      parseSceneText(text, "s.toml",
                     {parseSetExpression("body.1.mass=25g"),
                      {"restitution", "2/3", "--e 2/3"},
                      {"body.1", "36 km/h", "--v1 36 km/h", Override::Kind::kSpeed},
                      {"body.1", "pi/2 rad", "--theta1 pi/2 rad", Override::Kind::kDirection}});
  EXPECT_DOUBLE_EQ(scene.bodies[0].mass_kg, 0.025);
  EXPECT_EQ(scene.restitution, 2.0 / 3.0);
  EXPECT_EQ(scene.bodies[0].velocity_mps, core::Vec2(0.0, 10.0));  // exactly north
  const SceneDesc vector =
      parseSceneText(text, "s.toml", {parseSetExpression("body.1.velocity=[sqrt(3)/2, 50 cm/s]")});
  EXPECT_EQ(vector.bodies[0].velocity_mps, core::Vec2(std::sqrt(3.0) / 2, 0.5));
  EXPECT_EQ(firstProblem(text, {{"restitution", "2/3 kg", "--e 2/3 kg"}}),
            "--e 2/3 kg: restitution: 2/3 kg: a mass, not a number without a unit; allowed: a "
            "number without a unit");
}

TEST(QuantitiesTest, ADirectionForABodyAtRestIsAnError) {
  const std::string text = "dimensions = 2\n[[body]]\nmass = 1\nradius = 0.1\nposition = [0, 0]\n";
  EXPECT_EQ(firstProblem(text, {{"body.1", "45", "--theta1 45", Override::Kind::kDirection}}),
            "--theta1 45: body.1: 45: the body is at rest, so a direction changes nothing; "
            "allowed: a direction with a speed (--v1/--v2 SPEED, applied first), or a body that "
            "moves");
}

TEST(QuantitiesTest, APendulumInA1DSceneGetsOneProblem) {
  try {
    parseSceneText("[[body]]\nmass = 1\nwidth = 0.1\npivot = [0, 0]\nlength = 1\n", "s.toml");
    FAIL();
  } catch (const SceneError& e) {
    ASSERT_EQ(e.problems().size(), 1u) << e.problems().back();
    EXPECT_NE(e.problems()[0].find("body.1.pivot: [0, 0]: a string hangs in a plane"),
              std::string::npos);
  }
}

TEST(QuantitiesTest, SpeedAndHeadingAsBooksStateThem) {
  const auto velocity = [](const std::string& heading) {
    return parseSceneText(
               "dimensions = 2\n[[body]]\nmass = 1\nradius = 0.1\n"
               "position = [0, 0]\nspeed = \"2 m/s\"\nheading = " +
                   heading + "\n",
               "s.toml")
        .bodies[0]
        .velocity_mps;
  };
  const double c30 = std::cos(kPiRad / 6), s30 = std::sin(kPiRad / 6);
  EXPECT_EQ(velocity("\"N\""), core::Vec2(0.0, 2.0));
  EXPECT_EQ(velocity("\"west\""), core::Vec2(-2.0, 0.0));
  EXPECT_EQ(velocity("\"S\""), core::Vec2(0.0, -2.0));
  EXPECT_NEAR((velocity("\"NE\"") - core::Vec2(std::sqrt(2.0), std::sqrt(2.0))).norm(), 0, 1e-15);
  EXPECT_NEAR((velocity("30") - core::Vec2(2 * c30, 2 * s30)).norm(), 0, 1e-15);
  EXPECT_NEAR((velocity("\"60 deg north of east\"") - core::Vec2(2 * s30, 2 * c30)).norm(), 0,
              1e-15);
  EXPECT_NEAR((velocity("\"30 deg east of north\"") - core::Vec2(2 * s30, 2 * c30)).norm(), 0,
              1e-15);
  EXPECT_NEAR((velocity("\"30 deg south of west\"") - core::Vec2(-2 * c30, -2 * s30)).norm(), 0,
              1e-15);
  EXPECT_NE(firstProblem("dimensions = 2\n[[body]]\nmass = 1\nradius = 0.1\nposition = [0, 0]\n"
                         "speed = 2\nheading = \"30 deg north of south\"\n")
                .find("is no quarter turn"),
            std::string::npos);
  EXPECT_NE(firstProblem(blockScene("speed = 2\nvelocity = 1\n")).find("given with velocity"),
            std::string::npos);
  EXPECT_NE(firstProblem(blockScene("speed = 2\nheading = 90\n")).find("a 1D scene moves along x"),
            std::string::npos);
}

// A puck of radius r at the origin moving along +x; the target, radius R, struck with impact
// parameter b and gap g, sits at (sqrt((r + R)^2 - b^2) + g, -b).
TEST(QuantitiesTest, ATargetIsPlacedAlongTheLineOfApproach) {
  const SceneDesc scene = parseSceneText(
      "dimensions = 2\n[[body]]\nmass = 1\nradius = \"3 cm\"\nposition = [0, 0]\n"
      "speed = 2\n[[body]]\nmass = 1\nradius = \"2 cm\"\nstruck_by = 1\n"
      "impact_parameter = 0.6\ngap = \"10 cm\"\n[[body]]\nmass = 1\nradius = 0.01\n"
      "position = [1, 1]\nvelocity = [0, -1]\n[[body]]\nmass = 1\nradius = 0.01\n"
      "struck_by = 3\nimpact_parameter = \"-5 mm\"\n",
      "s.toml");
  const double b = 0.6 * 0.05;
  EXPECT_NEAR(
      (scene.bodies[1].position_m - core::Vec2(std::sqrt(0.05 * 0.05 - b * b) + 0.1, -b)).norm(), 0,
      1e-15);
  // Moving along -y, the right of the line is -x: b = -5 mm puts it 5 mm towards +x.
  EXPECT_NEAR(
      (scene.bodies[3].position_m - core::Vec2(1.005, 1 - std::sqrt(0.02 * 0.02 - 0.005 * 0.005)))
          .norm(),
      0, 1e-15);
  EXPECT_NE(firstProblem("dimensions = 2\n[[body]]\nmass = 1\nradius = 0.1\nposition = [0, 0]\n"
                         "[[body]]\nmass = 1\nradius = 0.1\nstruck_by = 1\n")
                .find("does not move towards it"),
            std::string::npos);
  EXPECT_NE(firstProblem("dimensions = 2\n[[body]]\nmass = 1\nradius = 0.1\nposition = [0, 0]\n"
                         "speed = 1\n[[body]]\nmass = 1\nradius = 0.1\nstruck_by = 1\n"
                         "impact_parameter = \"30 cm\"\n")
                .find("more than the summed radii (0.2 m)"),
            std::string::npos);
  EXPECT_NE(
      firstProblem("[[body]]\nmass = 1\nwidth = 0.5\nstruck_by = 1\n").find("not another body"),
      std::string::npos);
}

TEST(QuantitiesTest, WidthForBlocksRadiusForDisksSizeStillRead) {
  std::vector<std::string> notes;
  EXPECT_NE(firstProblem("dimensions = 2\n[[body]]\nmass = 1\nwidth = 1\nposition = [0, 0]\n")
                .find("body.1.width: 1: a disk has no width; allowed: radius"),
            std::string::npos);
  EXPECT_NE(firstProblem(blockScene("size = 0.5\n")).find("body.1.size: 0.5: given with width"),
            std::string::npos);
  const SceneDesc old =
      parseSceneText("[[body]]\nshape = \"disk\"\nmass = 1\nsize = 0.1\nposition = 0\n", "s.toml");
  EXPECT_EQ(old.bodies[0].size_m, 0.1);
}

TEST(QuantitiesTest, PresetsShowPendulumsWithLengthAndAngleAndNameTheSchema) {
  const std::string text = presetToml("ballistic-pendulum");
  EXPECT_EQ(text.rfind("#:schema ", 0), 0u);
  EXPECT_NE(text.find("\nlength = 1.0 "), std::string::npos) << text;
  EXPECT_NE(text.find("\nangle = 0.0 "), std::string::npos) << text;
  const SceneDesc shown = parseSceneText(text, "shown.toml");
  EXPECT_EQ(shown.bodies, loadPreset("ballistic-pendulum").bodies);
}

}  // namespace
}  // namespace collide::scene
