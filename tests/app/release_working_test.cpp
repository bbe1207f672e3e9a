// SPDX-License-Identifier: MIT
// collide solve for energy that comes in (issue 44): the working of a release (spring-carts,
// recoil, a pair released while moving) and of a super-elastic impact. Every expected number is
// derived here from conservation: Sum p kept and the kinetic energy grown by Q (from rest:
// v2 = sqrt(2 Q m1 / (m2 (m1 + m2))), v1 = -m2 v2 / m1), or the restitution law with the gain
// 1/2 mu (e^2 - 1) u^2. The LaTeX compiles with pdflatex and the MathML parses.
#include <gtest/gtest.h>
#include <libxml/parser.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "scene/scene_desc.hpp"
#include "support/scratch.hpp"
#include "working_result.hpp"

namespace collide {
namespace release_working_test {

using Shown = test::ShownNumber;

void expectShown(const std::map<std::string, Shown>& shown, const std::string& symbol,
                 double expected, const std::string& what) {
  const auto it = shown.find(symbol);
  ASSERT_NE(it, shown.end()) << what << ": no " << symbol << " in the result";
  EXPECT_NEAR(it->second.value(), expected, it->second.tolerance) << what << ": " << symbol;
}

// Two bodies at rest pushed apart by Q.
struct FromRest {
  double v1, v2;
};
FromRest fromRest(double m1, double m2, double q) {
  const double v2 = std::sqrt(2.0 * q * m1 / (m2 * (m1 + m2)));
  return {-m2 * v2 / m1, v2};
}

void expectReleasePreset(const std::string& preset, const std::string& title) {
  const scene::SceneDesc scene = scene::loadPreset(preset);
  ASSERT_EQ(scene.releases.size(), 1u);
  const double m1 = scene.bodies[0].mass_kg, m2 = scene.bodies[1].mass_kg;
  const double q = scene.releases[0].energy_J.value();
  const FromRest expected = fromRest(m1, m2, q);
  const test::CliResult r = test::run({"solve", preset, "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind(title, 0), 0u) << r.out;
  // The laws as the issue states them: Sum p = 0 before, the kinetic energies add up to Q.
  EXPECT_NE(r.out.find("m₁v₁′ + m₂v₂′ = 0    ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("½m₁v₁′² + ½m₂v₂′² = Q"), std::string::npos) << r.out;
  const std::map<std::string, Shown> shown = test::workingResults(r.out);
  expectShown(shown, "v₁′", expected.v1, preset);
  expectShown(shown, "v₂′", expected.v2, preset);
  expectShown(shown, "Q", q, preset);
  // Equal and opposite momenta, as the shown speeds say within their digits.
  EXPECT_NEAR(m1 * shown.at("v₁′").value() + m2 * shown.at("v₂′").value(), 0.0,
              m1 * shown.at("v₁′").tolerance + m2 * shown.at("v₂′").tolerance);
}

TEST(ReleaseWorkingTest, SpringCartsSpeedsFollowFromZeroMomentumAndQ) {
  expectReleasePreset("spring-carts",
                      "Release 1 of 1: cart 1 and cart 2 pushed apart at t = 0.500 s");
}

TEST(ReleaseWorkingTest, RecoilIsTheReleaseAndTheBulletsImpactComesSecond) {
  expectReleasePreset("recoil", "Release 1 of 1: rifle and bullet pushed apart at t = 0.250 s");
  const test::CliResult wall = test::run({"solve", "recoil", "--impact", "2", "-q"});
  ASSERT_EQ(wall.exit_code, 0) << wall.err;
  EXPECT_EQ(wall.out.rfind("Impact 1 of 1: bullet and wall", 0), 0u) << wall.out;
  // The bullet stops in the wall (e = 0): it loses all it was given, Q m_rifle / (m_rifle + m_b).
  const double m_rifle = 4.0, m_bullet = 0.01, q = 802.0;
  const double v_bullet = fromRest(m_rifle, m_bullet, q).v2;
  expectShown(test::workingResults(wall.out), "ΔKE", 0.5 * m_bullet * v_bullet * v_bullet,
              "recoil impact 2");
}

// Two blocks (1 and 3 kg) moving together at 1 m/s, touching, pushed apart by Q = 1.5 J at t = 0.
const char* const kMovingPair =
    "dimensions = 1\nduration = 1\n"
    "[[body]]\nmass = 1\nwidth = 0.5\nposition = 0\nvelocity = 1\n"
    "[[body]]\nmass = 3\nwidth = 0.5\nposition = 0.5\nvelocity = 1\n"
    "[[release]]\nbodies = [1, 2]\ntime = 0\nenergy = 1.5\n";

// Two blocks closing at 3 m/s with e = 1.5 (super_elastic): 1 kg at +2 m/s, 3 kg at -1 m/s.
const char* const kSuperElastic =
    "dimensions = 1\nduration = 2\nrestitution = 1.5\nsuper_elastic = true\n"
    "[[body]]\nmass = 1\nwidth = 0.5\nposition = -2\nvelocity = 2\n"
    "[[body]]\nmass = 3\nwidth = 0.5\nposition = 2\nvelocity = -1\n";

std::string writeScene(const test::ScratchDir& dir, const std::string& name, const char* text) {
  std::ofstream(dir.file(name)) << text;
  return dir.file(name);
}

TEST(ReleaseWorkingTest, APairReleasedWhileMovingKeepsItsCentreOfMassVelocity) {
  test::ScratchDir dir("collide-release-working");
  const test::CliResult r = test::run({"solve", writeScene(dir, "moving.toml", kMovingPair), "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Sum p = 4 kg m/s kept: v_cm = 1 m/s. 1/2 mu s'^2 = Q with mu = 3/4 kg: s' = 2 m/s, shared in
  // the inverse ratio of the masses: v1' = 1 - 3/4 * 2, v2' = 1 + 1/4 * 2.
  const double m1 = 1.0, m2 = 3.0, q = 1.5, v_cm = (m1 * 1.0 + m2 * 1.0) / (m1 + m2);
  const double mu = m1 * m2 / (m1 + m2), s_after = std::sqrt(2.0 * q / mu);
  const std::map<std::string, Shown> shown = test::workingResults(r.out);
  expectShown(shown, "v₁′", v_cm - m2 / (m1 + m2) * s_after, "moving pair");
  expectShown(shown, "v₂′", v_cm + m1 / (m1 + m2) * s_after, "moving pair");
  expectShown(shown, "Q", q, "moving pair");
  EXPECT_NE(r.out.find("½m₁v₁′² + ½m₂v₂′² = ½m₁v₁² + ½m₂v₂² + Q"), std::string::npos) << r.out;
}

TEST(ReleaseWorkingTest, SuperElasticImpactGainsHalfMuE2Minus1U2) {
  test::ScratchDir dir("collide-release-working");
  const test::CliResult r = test::run({"solve", writeScene(dir, "pop.toml", kSuperElastic), "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double m1 = 1.0, m2 = 3.0, v1 = 2.0, v2 = -1.0, e = 1.5;
  const double u = v1 - v2, p = m1 * v1 + m2 * v2, mu = m1 * m2 / (m1 + m2);
  // Sum p kept and v2' - v1' = e u.
  const double v1_after = (p - m2 * e * u) / (m1 + m2);
  const std::map<std::string, Shown> shown = test::workingResults(r.out);
  expectShown(shown, "v₁′", v1_after, "super-elastic");
  expectShown(shown, "v₂′", v1_after + e * u, "super-elastic");
  expectShown(shown, "Q", 0.5 * mu * (e * e - 1.0) * u * u, "super-elastic");
  EXPECT_EQ(shown.count("ΔKE"), 0u) << r.out;  // nothing is lost
  EXPECT_NE(r.out.find("Q = ½μ(e² − 1)u²"), std::string::npos) << r.out;
}

// Every format of the new workings: the LaTeX as one pdflatex document, the MathML as XML, the
// Markdown with its math between dollars.
TEST(ReleaseWorkingTest, LatexCompilesAndMathmlParses) {
  test::ScratchDir dir("collide-release-working");
  const std::vector<std::string> scenes = {"spring-carts", "recoil",
                                           writeScene(dir, "moving.toml", kMovingPair),
                                           writeScene(dir, "pop.toml", kSuperElastic)};
  std::ofstream tex(dir.file("working.tex"));
  tex << "\\documentclass{article}\n\\usepackage[utf8]{inputenc}\n\\usepackage{amsmath}\n"
         "\\begin{document}\n";
  for (const std::string& scene : scenes) {
    const test::CliResult latex = test::run({"solve", scene, "--format", "latex", "-q"});
    ASSERT_EQ(latex.exit_code, 0) << latex.err;
    tex << latex.out << "\n";
    const test::CliResult mathml = test::run({"solve", scene, "--format", "mathml", "-q"});
    ASSERT_EQ(mathml.exit_code, 0) << mathml.err;
    xmlDoc* doc = xmlReadMemory(mathml.out.data(), int(mathml.out.size()), "working.xml", nullptr,
                                XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
    EXPECT_NE(doc, nullptr) << scene << ":\n" << mathml.out;
    if (doc != nullptr) xmlFreeDoc(doc);
    const test::CliResult markdown = test::run({"solve", scene, "--format", "markdown", "-q"});
    ASSERT_EQ(markdown.exit_code, 0) << markdown.err;
    EXPECT_NE(markdown.out.find("$"), std::string::npos) << scene;
  }
  tex << "\\end{document}\n";
  tex.close();
  if (test::runShellCaptured(dir.path(), "command -v pdflatex").exit_code != 0) {
    GTEST_SKIP() << "pdflatex is not installed (scripts/install-packages installs "
                    "texlive-latex-base)";
  }
  const test::ShellRun run = test::runShellCaptured(
      dir.path(),
      "cd " + dir.shellFile("") + " && pdflatex -interaction=nonstopmode -halt-on-error " +
          "-no-shell-escape working.tex",
      std::chrono::seconds(60));
  EXPECT_EQ(run.exit_code, 0) << run.out.substr(run.out.size() > 3000 ? run.out.size() - 3000 : 0);
}

}  // namespace release_working_test
}  // namespace collide
