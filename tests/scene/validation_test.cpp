// Every class of scene validation error, each reported as "file:line:column: key: value: what is
// allowed", and every problem of a file collected rather than only the first.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_io.hpp"

namespace collide::scene {
namespace {

// Two valid 1D bodies, lines 1 to 9; tests put top-level keys before and tables after.
const std::string kTwoBodies = R"([[body]]
mass = 1
size = 0.5
position = -2
velocity = 1
[[body]]
mass = 1
size = 0.5
position = 2
)";

// The first problem for `text` read as "s.toml".
std::string problemIn(const std::string& text) {
  try {
    parseSceneText(text, "s.toml");
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    return message;
  }
  ADD_FAILURE() << "accepted:\n" << text;
  return "";
}

// The first problem for `text` contains `needle`.
void expectProblem(const std::string& text, const std::string& needle) {
  const std::string message = problemIn(text);
  EXPECT_NE(message.find(needle), std::string::npos) << message;
}

TEST(ValidationTest, ZeroOrNegativeMass) {
  EXPECT_EQ(problemIn("[[body]]\nsize = 1\nposition = 0\nmass = 0\n"),
            "s.toml:4:8: body.1.mass: 0: out of range; allowed: a mass in kg, more than 0 and "
            "at most 1e+18");
  expectProblem("[[body]]\nsize = 1\nposition = 0\nmass = -2.5\n",
                "s.toml:4:8: "
                "body.1.mass: -2.5");
}

TEST(ValidationTest, SubnormalNumbersAreRefused) {
  // 1e-310 is below the smallest normal double (2^-1022, about 2.2e-308): "more than 0" alone
  // would let it through, and then 1 / m overflows and the bodies pass through each other.
  EXPECT_EQ(problemIn("[[body]]\nsize = 1\nposition = 0\nmass = 1e-310\n"),
            "s.toml:4:8: body.1.mass: 1e-310: a subnormal number (below 2.2e-308, where doubles "
            "lose precision); allowed: a mass in kg, more than 0 and at most 1e+18");
  expectProblem("[[body]]\nsize = 1\nmass = 1\nposition = 0\nvelocity = -4e-320\n",
                "body.1.velocity: -4e-320: a subnormal number");
  expectProblem("[[body]]\nmass = 1\nposition = 0\nsize = 2e-309\n",
                "body.1.size: 2e-309: a subnormal number");
}

TEST(ValidationTest, RestitutionOutsideZeroToOne) {
  EXPECT_EQ(problemIn("restitution = 1.5\n" + kTwoBodies),
            "s.toml:1:15: restitution: 1.5: out of range; allowed: a coefficient of restitution "
            "from 0 to 1 (above 1, to 10, with super_elastic = true: impacts that release energy)");
  expectProblem(kTwoBodies + "[[wall]]\nposition = -5\nrestitution = -0.1\n",
                "s.toml:12:15: wall.1.restitution: -0.1: out of range");
  expectProblem(kTwoBodies + "[[pair]]\nbodies = [1, 2]\nrestitution = 2\n",
                "pair.1.restitution: 2: out of range");
}

TEST(ValidationTest, NanAndInfiniteNumbersAnywhere) {
  EXPECT_EQ(problemIn("duration = nan\n" + kTwoBodies).substr(0, 40),
            "s.toml:1:12: duration: nan: not a finite");
  expectProblem("[[body]]\nmass = inf\nsize = 1\nposition = 0\n",
                "s.toml:2:8: body.1.mass: inf: not a finite number");
  expectProblem("dimensions = 2\n[[body]]\nmass = 1\nsize = 1\nposition = [0, -inf]\n",
                "s.toml:5:12: body.1.position: [0, -inf]: not a finite number");
  expectProblem(kTwoBodies + "[view]\ntrail = nan\n", "view.trail: nan");
}

// view.best_still names an instant of the run (the still shown where a strobe cannot teach).
TEST(ValidationTest, ABestStillIsAnInstantNotBeforeTheStart) {
  expectProblem(kTwoBodies + "[view]\nbest_still = -1\n", "view.best_still: -1: out of range");
  const SceneDesc scene = parseSceneText(kTwoBodies + "[view]\nbest_still = 1.5\n", "s.toml");
  ASSERT_TRUE(scene.view.best_still_s.has_value());
  EXPECT_EQ(*scene.view.best_still_s, 1.5);
  EXPECT_FALSE(parseSceneText(kTwoBodies, "s.toml").view.best_still_s.has_value());
}

TEST(ValidationTest, BodiesOverlappingAtTimeZero) {
  const std::string message = problemIn(
      "[[body]]\nmass = 1\nsize = 1\nposition = 0\n[[body]]\nmass = 1\nsize = 1\nposition = "
      "0.75\n");
  EXPECT_EQ(message,
            "s.toml:8:12: body.2.position: 0.75: overlaps body 1 ('body 1') at t = 0 by 0.25 m; "
            "allowed: bodies apart or touching (centres at least 1 m apart)");
  // Touching is fine; 2D disks overlap by distance between centres.
  EXPECT_NO_THROW(parseSceneText(
      "[[body]]\nmass = 1\nsize = 1\nposition = 0\n[[body]]\nmass = 1\nsize = 1\nposition = 1\n",
      "s.toml"));
  expectProblem(
      "dimensions = 2\n[[body]]\nmass = 1\nsize = 0.5\nposition = [0, 0]\n"
      "[[body]]\nmass = 1\nsize = 0.5\nposition = [0.6, 0.6]\n",
      "body.2.position: [0.6, 0.6]: overlaps body 1");
  expectProblem(kTwoBodies + "[[wall]]\nposition = [-2.1, 0]\nnormal = 1\n",
                "body.1.position: -2: behind or inside wall 1");
  expectProblem(kTwoBodies + "[box]\nmin = -1\nmax = 5\n", "not inside the box");
}

TEST(ValidationTest, UnknownKeysSuggestTheNearestOne) {
  EXPECT_EQ(problemIn(kTwoBodies + "mas = 3\n"),
            "s.toml:10:1: body.2.mas: 3: unknown key; did you mean 'mass'? allowed keys: name, "
            "shape, mass, width, radius, size, position, velocity, speed, heading, color, "
            "friction, static_friction, drag_linear, drag_quadratic, rolling_mu, spin, pivot, "
            "length, angle, struck_by, impact_parameter, gap");
  expectProblem("restitusion = 0.5\n" + kTwoBodies,
                "s.toml:1:1: restitusion: 0.5: unknown key; did you mean 'restitution'?");
  expectProblem(kTwoBodies + "[view]\nthem = \"dark\"\n", "did you mean 'theme'?");
  expectProblem(kTwoBodies + "[view]\ntheme = \"drak\"\n",
                "view.theme: \"drak\": not one of the choices; allowed: 'light', 'dark' or "
                "'high-contrast'; did you mean 'dark'?");
  expectProblem("digits = 4\n" + kTwoBodies, "digits: 4: unknown key");
}

TEST(ValidationTest, WrongTypes) {
  EXPECT_EQ(
      problemIn("duration = \"long\"\n" + kTwoBodies),
      "s.toml:1:12: duration: \"long\": not a number, arithmetic or a quantity with a unit "
      "(Unexpected token \"long\" found at position 0); allowed: a number in s, arithmetic such "
      "as 2/3, either followed by a unit: s, ms, min, h");
  expectProblem("duration = [2]\n" + kTwoBodies,
                "s.toml:1:12: duration: [2]: wrong type (an array); allowed: a duration in s, more "
                "than 0 and at most 3600");
  expectProblem("body = 3\n",
                "s.toml:1:8: body: 3: wrong type; allowed: [[body]] "
                "tables");
  expectProblem(kTwoBodies + "[view]\nchart = 3\n", "view.chart: 3: wrong type");
  expectProblem("dimensions = 2\n[[body]]\nmass = 1\nsize = 1\nposition = 3\n",
                "body.1.position: 3: wrong type (an integer); allowed: a position in m as "
                "[x, y]");
  expectProblem("dimensions = 1.5\n" + kTwoBodies, "dimensions: 1.5: not a whole number");
  expectProblem(kTwoBodies + "color = \"red\"\n", "body.2.color: \"red\": not a colour");
}

TEST(ValidationTest, LimitsOnDurationBodyCountAndSizes) {
  expectProblem("duration = 1e5\n" + kTwoBodies,
                "duration: 1e+05: out of range; allowed: a duration in s, more than 0 "
                "and at most 3600");
  expectProblem("duration = 0\n" + kTwoBodies, "duration: 0: out of range");
  std::string many;
  for (int i = 0; i <= kMaxBodies; ++i) {
    many += "[[body]]\nmass = 1\nsize = 0.5\nposition = " + std::to_string(i) + "\n";
  }
  expectProblem(many, "s.toml:1:1: body: [1001 tables]: 1001 bodies; allowed: at most 1000");
  expectProblem("[[body]]\nmass = 1\nsize = 1\nposition = 1e7\n", "out of range");
  expectProblem(kTwoBodies +
                    "[view]\npanels = { parameter = \"restitution\", values = "
                    "[1, 0.9, 0.8, 0.7, 0.6, 0.5, 0.4] }\n",
                "view.panels");
}

TEST(ValidationTest, MissingAndStructuralProblems) {
  EXPECT_EQ(problemIn("duration = 2\n"),
            "s.toml:1:1: body: (missing): required; allowed: at least one [[body]] table");
  expectProblem("[[body]]\nmass = 1\nposition = 0\n",
                "s.toml:1:1: body.1.width: (missing): required; allowed: a width in m");
  expectProblem("dimensions = 2\n[[body]]\nmass = 1\nposition = [0, 0]\n",
                "s.toml:2:1: body.1.radius: (missing): required; allowed: a radius in m");
  expectProblem(kTwoBodies + "[[pair]]\nbodies = [1, 3]\nrestitution = 0.5\n",
                "pair.1.bodies: [1, 3]: not two different bodies of this scene");
  expectProblem(kTwoBodies + "[[wall]]\nposition = 0\n",
                "wall.1.normal: (missing): bodies on both sides of wall 1");
  expectProblem(
      kTwoBodies + "[restitution_law]\nkind = \"table\"\ntable = [[1, 0.5], [0.5, 0.6]]\n",
      "restitution_law.table");
  expectProblem(kTwoBodies + "[restitution_law]\nkind = \"constant\"\nexponent = 2\n",
                "restitution_law.exponent: 2: only with kind = 'speed-threshold'");
  expectProblem(kTwoBodies + "[view]\npanels = { parameter = \"restitution\", values = [1, 2] }\n",
                "view.panels value 2: restitution: 2.0: out of range");
  expectProblem("name = \"../evil\"\n" + kTwoBodies, "s.toml:1:8: name: \"../evil\"");
}

TEST(ValidationTest, MalformedTomlNamesTheLineAndColumn) {
  EXPECT_EQ(problemIn("duration = [1,\n").substr(0, 30), "s.toml:1:16: malformed TOML: E");
  expectProblem("a = 1\na = 2\n", "s.toml:2:");
  // A number beyond a double's range is TOML; the problem is its size, and the message says so.
  EXPECT_EQ(problemIn("duration = 1e999\n"),
            "s.toml:1:12: 1e999: out of range of a number; allowed: numbers up to about 1.8e308 "
            "in size, within each key's own range (see docs/scene-format.md)");
}

TEST(ValidationTest, EveryProblemIsCollected) {
  try {
    parseSceneText("restitution = 3\n[[body]]\nmass = -1\nsize = 1\nposition = 0\nsped = 2\n",
                   "s.toml");
    FAIL();
  } catch (const SceneError& e) {
    ASSERT_EQ(e.problems().size(), 3u);
    EXPECT_NE(std::string(e.what()).find("(and 2 more problems; 'collide check' lists them)"),
              std::string::npos);
    EXPECT_EQ(e.problems()[0].substr(0, 25), "s.toml:1:15: restitution:");
    EXPECT_EQ(e.problems()[1].substr(0, 16), "s.toml:6:1: body");
    EXPECT_EQ(e.problems()[2].substr(0, 23), "s.toml:3:8: body.1.mass");
  }
}

TEST(ValidationTest, MissingOrUnreadableFiles) {
  try {
    loadScene("/nonexistent/scene.toml");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "scene: '/nonexistent/scene.toml': cannot read: No such file or directory; allowed: "
              "a preset name (see 'collide presets') or a readable .toml scene file");
  }
  EXPECT_THROW(loadScene("/tmp"), SceneError);
  try {
    loadScene("worked-exampel");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'worked-example'"), std::string::npos);
  }
}

}  // namespace
}  // namespace collide::scene
