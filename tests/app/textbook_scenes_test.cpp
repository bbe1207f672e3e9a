// SPDX-License-Identifier: MIT
// Textbook problems written as books state them (units, arithmetic, speed and heading, targets
// placed by impact parameter) give the same `collide data` numbers as the same scenes written in
// SI, to 1e-12 relative. Every SI number is worked out here by hand or by the test's own
// arithmetic (unit factors from their definitions, trigonometry of the line of approach), never by
// the code under test. Thirteen scenes, a few milliseconds each.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"
#include "scratch.hpp"

namespace collide {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kPound_kg = 0.45359237;  // exact, by definition
constexpr double kFoot_m = 0.3048;        // exact, by definition
constexpr double kMile_m = 1609.344;      // exact, by definition

std::string num(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::string vec(double x, double y) {
  return "[" + num(x) + ", " + num(y) + "]";
}

double cosd(double degrees) {
  return std::cos(degrees * kPi / 180.0);
}
double sind(double degrees) {
  return std::sin(degrees * kPi / 180.0);
}

// Where a target struck by a body at `from` moving along the unit vector (ux, uy) relative to
// it sits: sqrt(R^2 - b^2) + gap ahead, b to the right of the line of approach.
std::string aimed(double from_x, double from_y, double ux, double uy, double reach, double b,
                  double gap) {
  const double ahead = std::sqrt(reach * reach - b * b) + gap;
  return vec(from_x + ahead * ux + b * uy, from_y + ahead * uy - b * ux);
}

struct Case {
  const char* name;
  std::string textbook, si;
  bool collides = true;  // false: a swing with nothing to hit
};

std::vector<Case> cases() {
  std::vector<Case> all;
  // 1. OpenStax-style carts: a 250 g cart at 60 cm/s meets a 500 g cart at rest, 20 cm away.
  all.push_back({"carts in grams and centimetres",
                 "duration = \"1500 ms\"\n[[body]]\nmass = \"250 g\"\nwidth = \"10 cm\"\n"
                 "position = \"-30 cm\"\nvelocity = \"60 cm/s\"\n[[body]]\nmass = \"0.5 kg\"\n"
                 "width = \"10 cm\"\nstruck_by = 1\ngap = \"20 cm\"\n",
                 "duration = 1.5\n[[body]]\nmass = 0.25\nwidth = 0.1\nposition = -0.3\n"
                 "velocity = 0.6\n[[body]]\nmass = 0.5\nwidth = 0.1\nposition = " +
                     num(-0.3 + 0.1 + 0.2) + "\n"});
  // 2. Schaum: a 10 g bullet at 400 m/s lodges in a 2 kg block.
  all.push_back({"bullet into a block",
                 "restitution = \"0\"\nduration = \"0.5 s\"\n[[body]]\nmass = \"10 g\"\n"
                 "width = \"1 cm\"\nposition = \"-1 m\"\nvelocity = \"400 m/s\"\n[[body]]\n"
                 "mass = \"2 kg\"\nwidth = \"20 cm\"\nposition = 0\n",
                 "restitution = 0\nduration = 0.5\n[[body]]\nmass = 0.01\nwidth = 0.01\n"
                 "position = -1\nvelocity = 400\n[[body]]\nmass = 2\nwidth = 0.2\nposition = 0\n"});
  // 3. A 1200 kg car at 90 km/h runs into a 1800 kg truck at 36 km/h; they lock together.
  all.push_back({"car and truck in km/h",
                 "restitution = 0\nduration = \"3 s\"\n[[body]]\nmass = \"1.2 t\"\n"
                 "width = \"4.5 m\"\nposition = \"-30 m\"\nvelocity = \"90 km/h\"\n[[body]]\n"
                 "mass = 1800\nwidth = \"6 m\"\nposition = 0\nvelocity = \"36 km/h\"\n",
                 "restitution = 0\nduration = 3\n[[body]]\nmass = 1200\nwidth = 4.5\n"
                 "position = -30\nvelocity = " +
                     num(90.0 / 3.6) +
                     "\n[[body]]\nmass = 1800\n"
                     "width = 6\nposition = 0\nvelocity = " +
                     num(36.0 / 3.6) + "\n"});
  // 4. A ball dropped 1.2 m onto the floor with e = 2/3 (a 1D line along x, gravity along it).
  all.push_back({"bouncing ball with e = 2/3",
                 "restitution = \"2/3\"\ngravity = \"-9.81 m/s^2\"\nduration = \"2 s\"\n"
                 "[[body]]\nshape = \"disk\"\nmass = \"50 g\"\nradius = \"2 cm\"\n"
                 "position = \"122 cm\"\n[[wall]]\nposition = 0\nnormal = 1\n",
                 "restitution = " + num(2.0 / 3.0) +
                     "\ngravity = -9.81\nduration = 2\n"
                     "[[body]]\nshape = \"disk\"\nmass = 0.05\nradius = 0.02\nposition = 1.22\n"
                     "[[wall]]\nposition = 0\nnormal = 1\n"});
  // 5. OpenStax 2D: a puck at 2 m/s strikes an identical puck at rest, impact parameter half the
  // summed radii, 5 cm before contact.
  const double r5 = 0.03;
  all.push_back({"pucks at half the summed radii",
                 "dimensions = 2\nduration = 1\n[[body]]\nmass = \"170 g\"\nradius = \"3 cm\"\n"
                 "position = [0, 0]\nspeed = \"2 m/s\"\nheading = \"E\"\n[[body]]\n"
                 "mass = \"170 g\"\nradius = \"3 cm\"\nstruck_by = 1\nimpact_parameter = 0.5\n"
                 "gap = \"5 cm\"\n",
                 "dimensions = 2\nduration = 1\n[[body]]\nmass = 0.17\nradius = 0.03\n"
                 "position = [0, 0]\nvelocity = [2, 0]\n[[body]]\nmass = 0.17\nradius = 0.03\n"
                 "position = " +
                     aimed(0, 0, 1, 0, 2 * r5, 0.5 * 2 * r5, 0.05) + "\n"});
  // 6. Two cars at a crossing: 72 km/h heading 60 degrees north of east, 54 km/h heading north;
  // they lock together (e = 0), placed by the line of approach of their relative velocity.
  const double v6a_x = 20 * cosd(60), v6a_y = 20 * sind(60), v6b_y = 15;
  const double rel_x = v6a_x, rel_y = v6a_y - v6b_y, rel = std::hypot(rel_x, rel_y);
  all.push_back({"cars by compass heading",
                 "dimensions = 2\nrestitution = 0\nduration = 2\n[[body]]\nname = \"car\"\n"
                 "mass = \"1500 kg\"\nradius = \"2 m\"\nposition = [\"-10 m\", 0]\n"
                 "speed = \"72 km/h\"\nheading = \"60 deg north of east\"\n[[body]]\n"
                 "name = \"van\"\nmass = \"2.5 t\"\nradius = \"2 m\"\nspeed = \"54 km/h\"\n"
                 "heading = \"N\"\nstruck_by = \"car\"\ngap = \"1 m\"\n",
                 "dimensions = 2\nrestitution = 0\nduration = 2\n[[body]]\nname = \"car\"\n"
                 "mass = 1500\nradius = 2\nposition = [-10, 0]\nvelocity = " +
                     vec(v6a_x, v6a_y) +
                     "\n[[body]]\nname = \"van\"\nmass = 2500\nradius = 2\nvelocity = [0, 15]\n"
                     "position = " +
                     aimed(-10, 0, rel_x / rel, rel_y / rel, 4, 0, 1) + "\n"});
  // 7. Feet and radians: 5 ft/s at pi/4 rad, a target at an impact parameter of 1 cm.
  const double v7 = 5 * kFoot_m;
  all.push_back({"feet per second at pi/4 rad",
                 "dimensions = 2\nduration = 1\n[[body]]\nmass = 1\nradius = \"4 cm\"\n"
                 "position = [0, 0]\nspeed = \"5 ft/s\"\nheading = \"pi/4 rad\"\n[[body]]\n"
                 "mass = 2\nradius = \"6 cm\"\nstruck_by = 1\nimpact_parameter = \"1 cm\"\n",
                 "dimensions = 2\nduration = 1\n[[body]]\nmass = 1\nradius = 0.04\n"
                 "position = [0, 0]\nvelocity = " +
                     vec(v7 * cosd(45), v7 * sind(45)) +
                     "\n[[body]]\nmass = 2\nradius = 0.06\nposition = " +
                     aimed(0, 0, cosd(45), sind(45), 0.1, 0.01, 0) + "\n"});
  // 8. A 200 g bob on an 80 cm string let go 30 degrees to the left.
  const double a8 = -30 * kPi / 180;
  all.push_back({"pendulum in cm and degrees",
                 "dimensions = 2\ngravity = [0, \"-9.81 m/s^2\"]\nduration = \"1.2 s\"\n"
                 "[[body]]\nmass = \"200 g\"\nradius = \"2 cm\"\npivot = [0, 0]\n"
                 "length = \"80 cm\"\nangle = \"-30 deg\"\n",
                 "dimensions = 2\ngravity = [0, -9.81]\nduration = 1.2\n[[body]]\nmass = 0.2\n"
                 "radius = 0.02\npivot = [0, 0]\nposition = " +
                     vec(0.8 * std::sin(a8), -0.8 * std::cos(a8)) + "\n",
                 false});
  // 9. A ball at sqrt(3)/2 and 1/2 m/s in a 2 m by 1 m box, e = 0.8 on the walls.
  all.push_back({"ball in a box, arithmetic components",
                 "dimensions = 2\nduration = 3\nrestitution = \"4/5\"\n[[body]]\nmass = 1\n"
                 "radius = \"10 cm\"\nposition = [\"50 cm\", \"50 cm\"]\n"
                 "velocity = [\"sqrt(3)/2 m/s\", \"1/2\"]\n[box]\nmin = [0, 0]\n"
                 "max = [\"200 cm\", \"1000 mm\"]\n",
                 "dimensions = 2\nduration = 3\nrestitution = 0.8\n[[body]]\nmass = 1\n"
                 "radius = 0.1\nposition = [0.5, 0.5]\nvelocity = " +
                     vec(std::sqrt(3.0) / 2, 0.5) + "\n[box]\nmin = [0, 0]\nmax = [2, 1]\n"});
  // 10. Pounds and miles per hour: a 3 lb ball at 2 mph hits a 6 lb ball at rest, touching.
  all.push_back({"pounds and mph",
                 "duration = 1\n[[body]]\nshape = \"disk\"\nmass = \"3 lb\"\nradius = \"1 in\"\n"
                 "position = 0\nvelocity = \"2 mph\"\n[[body]]\nshape = \"disk\"\n"
                 "mass = \"6 lb\"\nradius = \"1 in\"\nstruck_by = 1\n",
                 "duration = 1\n[[body]]\nshape = \"disk\"\nmass = " + num(3 * kPound_kg) +
                     "\nradius = 0.0254\nposition = 0\nvelocity = " + num(2 * kMile_m / 3600) +
                     "\n[[body]]\nshape = \"disk\"\nmass = " + num(6 * kPound_kg) +
                     "\nradius = 0.0254\nposition = 0.0508\n"});
  // 11. A soft contact lasting 10 ms, a minute and a half of gliders in a 3 m box.
  all.push_back({"soft contact in ms, duration in minutes",
                 "duration = \"0.05 min\"\nrestitution = \"0.5\"\n[[body]]\nmass = \"1 kg\"\n"
                 "width = \"20 cm\"\nposition = \"-50 cm\"\nvelocity = \"1 m/s\"\n[[body]]\n"
                 "mass = \"3 kg\"\nwidth = \"20 cm\"\nposition = \"50 cm\"\n[contact]\n"
                 "model = \"spring-damper\"\nduration = \"10 ms\"\n",
                 "duration = 3\nrestitution = 0.5\n[[body]]\nmass = 1\nwidth = 0.2\n"
                 "position = -0.5\nvelocity = 1\n[[body]]\nmass = 3\nwidth = 0.2\n"
                 "position = 0.5\n[contact]\nmodel = \"spring-damper\"\nduration = 0.01\n"});
  // 12. 4 m/s heading 20 degrees south of west into a puck at rest, impact parameter -0.3.
  const double h12 = 180 + 20;
  all.push_back({"south of west, negative impact parameter",
                 "dimensions = 2\nduration = 1\n[[body]]\nmass = \"0.5 kg\"\nradius = \"5 cm\"\n"
                 "position = [1, 1]\nspeed = \"4 m/s\"\nheading = \"20 deg south of west\"\n"
                 "[[body]]\nmass = \"500 g\"\nradius = \"5 cm\"\nstruck_by = 1\n"
                 "impact_parameter = -0.3\ngap = \"2 cm\"\n",
                 "dimensions = 2\nduration = 1\n[[body]]\nmass = 0.5\nradius = 0.05\n"
                 "position = [1, 1]\nvelocity = " +
                     vec(4 * cosd(h12), 4 * sind(h12)) +
                     "\n[[body]]\nmass = 0.5\nradius = 0.05\nposition = " +
                     aimed(1, 1, cosd(h12), sind(h12), 0.1, -0.03, 0.02) + "\n"});
  // 13. Arithmetic masses and 1e-3 scale: 1/3 kg at 1.5e3 mm/s on 2/3 kg, e = sqrt(2)/2.
  all.push_back({"expressions everywhere",
                 "restitution = \"sqrt(2)/2\"\nduration = \"2*1.5\"\n[[body]]\n"
                 "mass = \"1/3 kg\"\nwidth = \"1e-1\"\nposition = \"-2*0.5\"\n"
                 "velocity = \"1.5e3 mm/s\"\n[[body]]\nmass = \"2/3\"\nwidth = \"100 mm\"\n"
                 "position = \"(1+1)/4 m\"\n",
                 "restitution = " + num(std::sqrt(2.0) / 2) +
                     "\nduration = 3\n[[body]]\n"
                     "mass = " +
                     num(1.0 / 3) +
                     "\nwidth = 0.1\nposition = -1\nvelocity = 1.5\n"
                     "[[body]]\nmass = " +
                     num(2.0 / 3) + "\nwidth = 0.1\nposition = 0.5\n"});
  return all;
}

// Numbers agree to 1e-12 of the largest magnitude among their siblings (a vector's components),
// so a component that is 1e-17 in one and 0 in the other is no failure of a unit; positions to
// 1e-12 of the scene's extent (`extent_m`: a body's x of 0 m reached through centimetres may be
// 1e-17 m).
void expectSame(const nlohmann::json& a, const nlohmann::json& b, const std::string& path,
                double scale, double extent_m) {
  if (a.is_number() && b.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    const double size = std::max({std::abs(x), std::abs(y), scale});
    EXPECT_LE(std::abs(x - y), 1e-12 * size) << path << ": " << num(x) << " vs " << num(y);
    return;
  }
  ASSERT_EQ(a.type(), b.type()) << path;
  if (a.is_array()) {
    ASSERT_EQ(a.size(), b.size()) << path;
    double largest = scale;
    for (const auto& item : b) {
      if (item.is_number()) largest = std::max(largest, std::abs(item.get<double>()));
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
      expectSame(a[i], b[i], path + "[" + std::to_string(i) + "]", largest, extent_m);
    }
  } else if (a.is_object()) {
    for (const auto& [key, value] : b.items()) {
      if (key == "scene") continue;  // the file's name
      ASSERT_TRUE(a.contains(key)) << path << "." << key;
      const bool position = key.size() > 9 && key.compare(key.size() - 9, 9, "_position") == 0;
      expectSame(a[key], value, path + "." + key, position ? extent_m : 0.0, extent_m);
    }
  } else {
    EXPECT_EQ(a, b) << path;
  }
}

// The largest coordinate of any body's position at either end, m.
double extentOf(const nlohmann::json& summary) {
  double extent_m = 0.0;
  for (const auto& body : summary["bodies"]) {
    for (const char* key : {"initial_position", "final_position"}) {
      for (const auto& coordinate : body[key]) {
        extent_m = std::max(extent_m, std::abs(coordinate.get<double>()));
      }
    }
  }
  return extent_m;
}

nlohmann::json dataOf(const test::ScratchDir& dir, const std::string& name,
                      const std::string& text) {
  const std::string file = dir.file(name + ".toml");
  std::ofstream(file) << text;
  const test::CliResult r = test::run({"data", file, "--json", "-"});
  EXPECT_EQ(r.exit_code, 0) << name << ": " << r.err;
  return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

TEST(TextbookScenesTest, UnitsArithmeticAndHeadingsGiveTheSiScenesNumbers) {
  const test::ScratchDir dir("collide-textbook-");
  int index = 0;
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.name);
    const std::string stem = "case" + std::to_string(++index);
    const nlohmann::json book = dataOf(dir, stem + "-book", c.textbook);
    const nlohmann::json si = dataOf(dir, stem + "-si", c.si);
    ASSERT_FALSE(si.is_null());
    if (c.collides) {
      EXPECT_GT(si["collision_count"].get<long long>(), 0);
    }
    expectSame(book, si, c.name, 0.0, extentOf(si));
  }
}

TEST(TextbookScenesTest, ArithmeticOnTheCommandLineIsTheNumberItMeans) {
  const test::CliResult typed = test::run({"data", "worked-example", "--e", "2/3", "--json", "-"});
  const test::CliResult number = test::run(
      {"data", "worked-example", "--set", "restitution=" + num(2.0 / 3.0), "--json", "-"});
  ASSERT_EQ(typed.exit_code, 0) << typed.err;
  ASSERT_EQ(number.exit_code, 0) << number.err;
  EXPECT_EQ(nlohmann::json::parse(typed.out), nlohmann::json::parse(number.out));
  const test::CliResult at_rest =
      test::run({"data", "billiards-break", "--theta2", "45", "--json", "-"});
  EXPECT_EQ(at_rest.exit_code, 2);
  EXPECT_EQ(at_rest.err.rfind("collide: --theta2 45: body.2: 45: the body is at rest", 0), 0u)
      << at_rest.err;
}

TEST(TextbookScenesTest, BobsLetGoAtRestStartAtExactlyZero) {
  const test::CliResult r = test::run({"data", "newtons-cradle", "--json", "-"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Parsed into a named value: a range-for over a member of the temporary would read freed memory.
  const nlohmann::json summary = nlohmann::json::parse(r.out);
  for (const auto& body : summary["bodies"]) {
    for (const auto& component : body["initial_velocity"]) {
      const double v = component.get<double>();
      EXPECT_TRUE(v == 0.0 && !std::signbit(v)) << body["name"] << ": " << num(v);
    }
  }
}

TEST(TextbookScenesTest, CheckSaysWhichKeysSetAStart) {
  const test::ScratchDir dir("collide-textbook-check-");
  const std::string file = dir.file("pucks.toml");
  std::ofstream(file) << cases()[4].textbook;  // the pucks at half the summed radii
  const test::CliResult r = test::run({"check", file});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\n  body.1: velocity [2, 0] m/s from speed 2 m/s and heading 0 degrees"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\n  body.2: position ["), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" m: struck by body 1 ('body 1') after a gap of 0.05 m, impact parameter "
                       "0.03 m\n"),
            std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace collide
