// SPDX-License-Identifier: MIT
// collide solve (issue 41), in-process: for every preset the working's result equals what
// conservation of momentum and the definition of e give for the impact's numbers (masses and
// velocities before, from `collide data --json --events`), within the digits it shows (the
// ballistic pendulum and the accident reconstruction read their speeds back from the rise and the
// skids: the speeds the scene started with); the LaTeX of every preset compiles with pdflatex
// (one document) and the MathML parses as XML.
#include <gtest/gtest.h>
#include <libxml/parser.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "scene/scene_desc.hpp"
#include "support/scratch.hpp"
#include "working_result.hpp"

namespace collide {
namespace {

using Shown = test::ShownNumber;

using Vec = std::array<double, 2>;
Vec vecOf(const nlohmann::json& json) {
  return {json[0].get<double>(), json[1].get<double>()};
}
double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1];
}

std::string subscript(int index) {
  static const char* const kDigits[] = {"₀", "₁", "₂", "₃", "₄", "₅", "₆", "₇", "₈", "₉"};
  std::string out;
  for (char c : std::to_string(index)) out += kDigits[c - '0'];
  return out;
}

void expectShown(const std::map<std::string, Shown>& shown, const std::string& symbol,
                 const std::vector<double>& expected, const std::string& preset) {
  const auto it = shown.find(symbol);
  ASSERT_NE(it, shown.end()) << preset << ": no " << symbol << " in the result";
  ASSERT_EQ(it->second.values.size(), expected.size()) << preset << " " << symbol;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_NEAR(it->second.values[k], expected[k], it->second.tolerance)
        << preset << ": " << symbol << " component " << k;
  }
}

std::vector<double> shownVector(const Vec& v, int dimensions) {
  return dimensions == 1 ? std::vector<double>{v[0]} : std::vector<double>{v[0], v[1]};
}

// A preset whose first event is a release (stored energy pushing bodies apart): its working,
// the release's, is checked in release_working_test.cpp.
bool startsWithRelease(const std::string& preset) {
  return preset == "spring-carts" || preset == "recoil";
}

struct FirstImpact {
  nlohmann::json summary, event;
  int dimensions = 1;
};

FirstImpact firstImpact(const std::string& preset) {
  const test::CliResult data = test::run({"data", preset, "--json", "-", "--events", "-q"});
  EXPECT_EQ(data.exit_code, 0) << data.err;
  FirstImpact impact;
  impact.summary = nlohmann::json::parse(data.out);
  // The first impact: a release (stored energy pushing bodies apart), a string event or the end of
  // a soft contact is no impact and has no working.
  static const std::set<std::string> kImpacts = {"impact", "wall", "rest", "contact_start"};
  for (const nlohmann::json& event : impact.summary.at("events")) {
    if (kImpacts.count(event.at("kind").get<std::string>()) > 0) {
      impact.event = event;
      break;
    }
  }
  impact.dimensions = impact.summary.at("dimensions").get<int>();
  return impact;
}

// Two bodies: the normal components from momentum and e, the tangential ones kept; a wall: the
// normal component reversed and scaled by e.
void expectImpulseResult(const std::string& preset, const FirstImpact& impact,
                         const std::map<std::string, Shown>& shown) {
  const nlohmann::json& event = impact.event;
  const Vec n = vecOf(event.at("normal"));
  const double e = event.at("restitution").get<double>();
  const int a = event.at("a").get<int>() - 1;  // bodies are numbered from 1
  const double m_a = impact.summary.at("bodies")[a].at("mass").get<double>();
  const Vec va = vecOf(event.at("velocities_before")[0]);
  const std::string v = "v", prime = "\u2032";
  if (!event.at("b").is_number()) {  // a wall
    const double un = dot(va, n);
    const Vec after = {va[0] - (1 + e) * un * n[0], va[1] - (1 + e) * un * n[1]};
    expectShown(shown, v + subscript(a + 1) + prime, shownVector(after, impact.dimensions), preset);
    expectShown(shown, "ΔKE", {0.5 * m_a * (1 - e * e) * un * un}, preset);
    return;
  }
  const int b = event.at("b").get<int>() - 1;
  const double m_b = impact.summary.at("bodies")[b].at("mass").get<double>();
  const Vec vb = vecOf(event.at("velocities_before")[1]);
  const double ua = dot(va, n), ub = dot(vb, n);
  const double common = (m_a * ua + m_b * ub) / (m_a + m_b);  // the centre of mass, along n
  const double wa = common - e * m_b * (ua - ub) / (m_a + m_b);
  const double wb = common + e * m_a * (ua - ub) / (m_a + m_b);
  const Vec after_a = {va[0] + (wa - ua) * n[0], va[1] + (wa - ua) * n[1]};
  const Vec after_b = {vb[0] + (wb - ub) * n[0], vb[1] + (wb - ub) * n[1]};
  expectShown(shown, v + subscript(a + 1) + prime, shownVector(after_a, impact.dimensions), preset);
  expectShown(shown, v + subscript(b + 1) + prime, shownVector(after_b, impact.dimensions), preset);
  const double mu = m_a * m_b / (m_a + m_b);
  expectShown(shown, "ΔKE", {0.5 * mu * (1 - e * e) * (ua - ub) * (ua - ub)}, preset);
}

// The bullet's speed from the block's rise: the preset fires it at its initial speed.
void expectPendulumResult(const FirstImpact& impact, const std::map<std::string, Shown>& shown) {
  const nlohmann::json& bodies = impact.summary.at("bodies");
  const double m_block = bodies[0].at("mass").get<double>();
  const double m_bullet = bodies[1].at("mass").get<double>();
  const double v_bullet = vecOf(bodies[1].at("initial_velocity"))[0];
  expectShown(shown, "v₂", {v_bullet}, "ballistic-pendulum");
  expectShown(shown, "v′", {m_bullet * v_bullet / (m_block + m_bullet)}, "ballistic-pendulum");
}

// Accident reconstruction, read back from the skids: the speed at the impact (the event's), the
// pair's after it by momentum, and the speed the striker started its skid at (the scene's).
void expectSkidResult(const FirstImpact& impact, const std::map<std::string, Shown>& shown) {
  const nlohmann::json& bodies = impact.summary.at("bodies");
  const double m1 = bodies[0].at("mass").get<double>(), m2 = bodies[1].at("mass").get<double>();
  const double v1 = vecOf(impact.event.at("velocities_before")[0])[0];
  EXPECT_EQ(vecOf(impact.event.at("velocities_before")[1])[0], 0.0);
  expectShown(shown, "v₀", {vecOf(bodies[0].at("initial_velocity"))[0]}, "accident-reconstruction");
  expectShown(shown, "v₁", {v1}, "accident-reconstruction");
  expectShown(shown, "v′", {m1 * v1 / (m1 + m2)}, "accident-reconstruction");
  expectShown(shown, "ΔKE", {0.5 * m1 * m2 / (m1 + m2) * v1 * v1}, "accident-reconstruction");
}

void expectClusterResult(const FirstImpact& impact, const std::map<std::string, Shown>& shown) {
  const nlohmann::json& bodies = impact.summary.at("bodies");
  double mass = 0.0;
  Vec momentum = {0.0, 0.0};
  for (const nlohmann::json& body : bodies) {
    const double m = body.at("mass").get<double>();
    const Vec v = vecOf(body.at("initial_velocity"));
    mass += m;
    momentum = {momentum[0] + m * v[0], momentum[1] + m * v[1]};
  }
  expectShown(shown, "v_cm′", {momentum[0] / mass, momentum[1] / mass}, "stick-2d");
  const double lost = impact.summary.at("kinetic_energy_initial").get<double>() -
                      impact.summary.at("kinetic_energy_final").get<double>();
  expectShown(shown, "ΔKE", {lost}, "stick-2d");
}

TEST(SolveCliTest, EveryPresetsResultIsWhatTheLawsGive) {
  for (const scene::PresetInfo& preset : scene::presetList()) {
    const test::CliResult solved = test::run({"solve", preset.name, "-q"});
    if (startsWithRelease(preset.name)) continue;
    ASSERT_EQ(solved.exit_code, 0) << preset.name << ": " << solved.err;
    const std::map<std::string, Shown> shown = test::workingResults(solved.out);
    ASSERT_FALSE(shown.empty()) << preset.name << ":\n" << solved.out;
    const FirstImpact impact = firstImpact(preset.name);
    if (preset.name == "ballistic-pendulum") {
      expectPendulumResult(impact, shown);
    } else if (preset.name == "stick-2d") {
      expectClusterResult(impact, shown);
    } else if (preset.name == "accident-reconstruction") {
      expectSkidResult(impact, shown);
    } else {
      expectImpulseResult(preset.name, impact, shown);
    }
  }
}

TEST(SolveCliTest, SpecialResultsFollowTheirLaws) {
  // Galperin: with masses 1 and 100^(d-1) the count is the first d digits of pi.
  const std::map<std::string, Shown> pi =
      test::workingResults(test::run({"solve", "pi-blocks", "-q"}).out);
  const double digits = 3;  // the preset's default
  expectShown(pi, "N", {std::floor(std::numbers::pi * std::pow(10.0, digits - 1))}, "pi-blocks");
  // The bouncing ball: e = sqrt(h2/h1) is the e it was given, and h2 = (e u)^2 / 2g.
  const FirstImpact ball = firstImpact("bouncing-ball");
  const std::map<std::string, Shown> bounce =
      test::workingResults(test::run({"solve", "bouncing-ball", "-q"}).out);
  const double e = ball.event.at("restitution").get<double>();
  const double u = -vecOf(ball.event.at("velocities_before")[0])[1];
  expectShown(bounce, "e", {e}, "bouncing-ball");
  expectShown(bounce, "h₂", {(e * u) * (e * u) / (2 * 9.81)}, "bouncing-ball");
  // A soft contact's impulse is the momentum cart 2 gains.
  const FirstImpact soft = firstImpact("soft-contact");
  const std::map<std::string, Shown> contact =
      test::workingResults(test::run({"solve", "soft-contact", "-q"}).out);
  const double m1 = 1.0, m2 = 2.0, v1 = 1.5, v2 = -0.5, e_soft = 0.7;
  const double v2_after = ((1 + e_soft) * m1 * v1 + (m2 - e_soft * m1) * v2) / (m1 + m2);
  EXPECT_EQ(soft.summary.at("bodies")[1].at("mass").get<double>(), m2);
  expectShown(contact, "J", {m2 * (v2_after - v2)}, "soft-contact");
}

TEST(SolveCliTest, ImpactPicksTheImpactAndBadInputIsOneLine) {
  const test::CliResult second = test::run({"solve", "billiards-break", "--impact", "2", "-q"});
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_EQ(second.out.rfind("Impact 2 of 38: ball 1 and ball 2", 0), 0u) << second.out;
  for (const char* typed : {"0", "2", "x", "-1", "1.5", ""}) {
    const test::CliResult r = test::run({"solve", "worked-example", "--impact", typed});
    EXPECT_EQ(r.exit_code, 2) << typed;
    EXPECT_EQ(r.err, "collide: --impact: '" + std::string(typed) +
                         "': no such impact in 'worked-example'; allowed: 1\n");
    EXPECT_TRUE(r.out.empty());
  }
  const test::CliResult format = test::run({"solve", "worked-example", "--format", "pdf"});
  EXPECT_EQ(format.exit_code, 2);
  EXPECT_EQ(format.err,
            "collide: --format: 'pdf': unknown format; allowed: text, latex, markdown, mathml\n");
  const test::CliResult none = test::run({"solve", "worked-example", "--duration", "0.5"});
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_EQ(none.err.rfind("collide: solve: 'worked-example': no impact", 0), 0u) << none.err;
}

// Arabic-Indic zero is a dot ("٠"), so numbers multiplied are joined by "×" there: with a middle
// dot, 2 · 9.81 · 0.200 would read as one long number. Other scripts keep the middle dot.
TEST(SolveCliTest, NumbersMultipliedInArabicAreJoinedByATimesSign) {
  const test::CliResult arabic = test::run({"solve", "ballistic-pendulum", "--lang", "ar", "-q"});
  ASSERT_EQ(arabic.exit_code, 0) << arabic.err;
  EXPECT_NE(arabic.out.find("\u0662 \u00D7 \u0669\u066B\u0668\u0661 \u00D7 \u0660\u066B"),
            std::string::npos)
      << arabic.out;
  const test::CliResult english = test::run({"solve", "ballistic-pendulum", "-q"});
  ASSERT_EQ(english.exit_code, 0) << english.err;
  EXPECT_NE(english.out.find("√(2 \u00B7 9.81 \u00B7 0.200)"), std::string::npos) << english.out;
  EXPECT_EQ(english.out.find("×"), std::string::npos) << english.out;
}

TEST(SolveCliTest, MathmlOfEveryPresetIsWellFormedXml) {
  for (const scene::PresetInfo& preset : scene::presetList()) {
    const test::CliResult r = test::run({"solve", preset.name, "--format", "mathml", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    xmlDoc* doc = xmlReadMemory(r.out.data(), int(r.out.size()), "working.xml", nullptr,
                                XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
    EXPECT_NE(doc, nullptr) << preset.name << ":\n" << r.out;
    if (doc != nullptr) xmlFreeDoc(doc);
  }
}

TEST(SolveCliTest, LatexOfEveryPresetCompilesWithPdflatex) {
  test::ScratchDir dir("collide-solve-latex");
  if (test::runShellCaptured(dir.path(), "command -v pdflatex").exit_code != 0) {
    GTEST_SKIP() << "pdflatex is not installed (scripts/install-packages installs "
                    "texlive-latex-base)";
  }
  std::ofstream tex(dir.file("working.tex"));
  tex << "\\documentclass{article}\n\\usepackage[utf8]{inputenc}\n\\usepackage{amsmath}\n"
         "\\begin{document}\n";
  for (const scene::PresetInfo& preset : scene::presetList()) {
    const test::CliResult r = test::run({"solve", preset.name, "--format", "latex", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    tex << r.out << "\n";
  }
  tex << "\\end{document}\n";
  tex.close();
  const test::ShellRun run = test::runShellCaptured(
      dir.path(),
      "cd " + dir.shellFile("") + " && pdflatex -interaction=nonstopmode -halt-on-error " +
          "-no-shell-escape working.tex",
      std::chrono::seconds(60));
  EXPECT_EQ(run.exit_code, 0) << run.out.substr(run.out.size() > 3000 ? run.out.size() - 3000 : 0);
  EXPECT_TRUE(std::filesystem::exists(dir / "working.pdf"));
}

}  // namespace
}  // namespace collide

namespace collide {
namespace {

bool overlap(const nlohmann::json& a, const nlohmann::json& b) {
  return a[0].get<double>() < b[2].get<double>() && b[0].get<double>() < a[2].get<double>() &&
         a[1].get<double>() < b[3].get<double>() && b[1].get<double>() < a[3].get<double>();
}

// `--working` puts the working in a place of its own: no other item of the frame (bodies,
// labels, arrows, readouts, the energy bar) reaches into it, as `collide layout` records what
// the painters draw.
TEST(SolveCliTest, TheWorkingPanelCoversNothingOfTheScene) {
  for (const char* preset : {"worked-example", "ballistic-pendulum", "billiards-glancing"}) {
    const test::CliResult r =
        test::run({"layout", preset, "--working", "--at", "1", "--json", "-", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json items = nlohmann::json::parse(r.out).at("frames").at(0).at("items");
    const auto working = std::find_if(items.begin(), items.end(), [](const nlohmann::json& item) {
      return item.at("kind") == "working";
    });
    ASSERT_NE(working, items.end()) << preset;
    const nlohmann::json& box = working->at("box");
    EXPECT_GT(box[2].get<double>() - box[0].get<double>(), 300.0) << preset;  // of 1280 px
    for (const nlohmann::json& item : items) {
      if (item.at("kind") == "working") continue;
      EXPECT_FALSE(overlap(item.at("box"), box)) << preset << ": " << item.at("id");
    }
  }
}

}  // namespace
}  // namespace collide

namespace collide {
namespace {

// The lines of text `collide layout` records in the working's place at t: its title and the
// headings of the steps shown.
int workingLinesAt(const std::string& preset, const std::string& t) {
  const test::CliResult r =
      test::run({"layout", preset, "--working", "--at", t, "--json", "-", "-q"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json layout = nlohmann::json::parse(r.out);
  for (const nlohmann::json& item : layout.at("frames").at(0).at("items")) {
    if (item.at("kind") == "working") return item.at("lines").get<int>();
  }
  ADD_FAILURE() << "no working in the layout of " << preset << " at " << t;
  return -1;
}

// The worked example's impact is at 3.5 m / 3 m/s = 1.167 s: before it the panel shows the given
// values only; the laws and the numbers follow at 0.2 s steps and stay. The result is not repeated
// under a heading of its own: each line of the numbers ends in it (v₁′ = … = −0.250 m/s).
TEST(SolveCliTest, TheWorkingAppearsStepByStepFromTheImpact) {
  const int before = workingLinesAt("worked-example", "1");
  const int at_impact = workingLinesAt("worked-example", "1.2");
  const int all = workingLinesAt("worked-example", "3");
  // The title (one line, or two where it wraps) and "Given"; each step then adds its heading.
  EXPECT_GE(before, 2);
  EXPECT_LE(before, 3);
  EXPECT_EQ(at_impact, before + 1);  // the laws
  EXPECT_EQ(all, before + 2);        // the numbers
}

}  // namespace
}  // namespace collide
