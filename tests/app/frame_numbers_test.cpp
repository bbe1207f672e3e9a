// Every number on every preset's pictures, read back from the FrameModel and the alt text:
// the energy books add up (to the energy at the start, and as displayed), no segment is negative,
// and every number is legible (at most four significant figures, no exponent, no "-0", nothing
// cut off with an ellipsis).
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "report/alt_text.hpp"
#include "report/narration.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

constexpr int kInstants = 20;
const std::string kMinus = "\u2212";

// A displayed number back to a double: true minus sign, thousands commas ("12,500").
double parseShown(std::string text) {
  const bool negative = text.rfind(kMinus, 0) == 0;
  if (negative) text.erase(0, kMinus.size());
  text.erase(std::remove(text.begin(), text.end(), ','), text.end());
  return negative ? -std::stod(text) : std::stod(text);
}

// The number at the end of an energy label "KE₁ 12.3 mJ", its unit and its decimals.
bool labelValue(const std::string& label, double& value, std::string& unit, int& decimals) {
  static const std::regex pattern(R"(((?:\xE2\x88\x92)?[0-9][0-9,]*(?:\.([0-9]+))?) ([µmkMG]?J)$)");
  std::smatch match;
  if (!std::regex_search(label, match, pattern)) return false;
  value = parseShown(match[1]);
  decimals = match[2].matched ? static_cast<int>(match[2].length()) : 0;
  unit = match[3];
  return true;
}

double unitValue(const std::string& unit) {
  if (unit == "µJ") return 1e-6;
  if (unit == "mJ") return 1e-3;
  if (unit == "kJ") return 1e3;
  if (unit == "MJ") return 1e6;
  if (unit == "GJ") return 1e9;
  return 1.0;
}

// The initial energy of the picture as the test computes it: kinetic energy of the initial
// velocities in the drawing frame, plus the gravity segment the bar shows at t = 0 (its zero is a
// display choice, the lowest level reached).
double initialEnergy(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                     const frame::PanelModel& at_start) {
  const auto& bodies = timeline.world().bodies;
  core::Vec2 frame{0.0, 0.0};
  if (scene.view.center_of_momentum_frame) {
    double mass = 0.0;
    for (const auto& body : bodies) {
      mass += body.mass_kg;
      frame += body.mass_kg * body.velocity_mps;
    }
    frame /= mass;
    if (scene.dimensions == 1) frame.y() = 0.0;
  }
  double energy = 0.0;
  for (const auto& body : bodies) {
    // A rolling ball's spin too: I = 2/5 m r^2 about a horizontal axis (0 elsewhere).
    energy += 0.5 * body.mass_kg * (body.velocity_mps - frame).squaredNorm() +
              0.2 * body.mass_kg * body.size_m * body.size_m * body.spin_radps.squaredNorm();
  }
  for (const frame::EnergySegment& segment : at_start.energy_bar.segments) {
    if (segment.label.rfind("PE", 0) == 0) energy += segment.energy_J;
  }
  return energy;
}

struct Picture {
  std::string preset;
  scene::SceneDesc scene;
  app::Animation animation;
};

std::vector<Picture>& everyPreset() {
  static std::vector<Picture> pictures = [] {
    std::vector<Picture> all;
    for (const scene::PresetInfo& info : scene::presetList()) {
      scene::SceneDesc scene = scene::loadPreset(info.name);
      app::Animation animation = app::animate(scene, {1280, 720});
      all.push_back({info.name, std::move(scene), std::move(animation)});
    }
    return all;
  }();
  return pictures;
}

// The energy released by t: the stated Q of every release due by then (the presets give Q).
double releasedBy(const scene::SceneDesc& scene, double t_s) {
  double released_J = 0.0;
  for (const scene::ReleaseDesc& release : scene.releases) {
    if (release.time_s <= t_s) released_J += release.energy_J.value_or(0.0);
  }
  return released_J;
}

double instant(const scene::SceneDesc& scene, int k) {
  return scene.duration_s * k / (kInstants - 1);
}

TEST(FrameNumbersTest, EnergyBooksAddUpAtEveryInstantOfEveryPreset) {
  int sums_checked = 0;
  for (const Picture& picture : everyPreset()) {
    const compose::FrameSource& frames = picture.animation.frames;
    const frame::FrameModel start = frames.frameAtSimulated(0.0);
    for (int k = 0; k < kInstants; ++k) {
      const double t = instant(picture.scene, k);
      const frame::FrameModel frame = frames.frameAtSimulated(t);
      ASSERT_EQ(frame.panels.size(), frames.panelCount());
      for (std::size_t p = 0; p < frame.panels.size(); ++p) {
        SCOPED_TRACE(picture.preset + " panel " + std::to_string(p) +
                     " at t = " + std::to_string(t));
        const frame::PanelModel& panel = frame.panels[p];
        // The parts add up to the energy at the start and what was released by t (spring-carts,
        // recoil), which the strip under them shows.
        const double released = releasedBy(picture.scene, t);
        const double expected =
            initialEnergy(picture.scene, frames.panelTimeline(p), start.panels[p]) + released;
        double sum = 0.0, shown_sum_J = 0.0, strip_J = 0.0;
        bool all_labelled = true;
        // Whether some labelled part could have read the other way: one neither exact at its
        // last figure nor exactly halfway between two steps (such a part never moves, so it
        // reads the same in every picture: docs/numbers.md).
        bool some_part_movable = false;
        for (const frame::EnergySegment& segment : panel.energy_bar.segments) {
          EXPECT_GE(segment.energy_J, 0.0) << segment.label;
          if (segment.strip) {
            strip_J += segment.energy_J;
            continue;
          }
          sum += segment.energy_J;
          double value = 0.0;
          std::string unit;
          int decimals = 0;
          if (labelValue(segment.label, value, unit, decimals)) {
            shown_sum_J += value * unitValue(unit);
            // True to its last figure: within half a step of it (one step where the parts' sum
            // needed a part rounded the other way).
            EXPECT_LE(std::fabs(value * unitValue(unit) - segment.energy_J),
                      std::pow(10.0, -decimals) * unitValue(unit) * (1.0 + 1e-9))
                << segment.label;
            EXPECT_TRUE(value != 0.0 || segment.energy_J == 0.0) << segment.label;
            const double steps = segment.energy_J / unitValue(unit) * std::pow(10.0, decimals);
            const double off = std::fabs(steps - std::floor(steps));
            some_part_movable =
                some_part_movable || (std::fabs(off) > 1e-6 && std::fabs(off - 0.5) > 1e-6 &&
                                      std::fabs(off - 1.0) > 1e-6);
          } else if (segment.energy_J > 0.0) {  // a zero-width segment has no entry and adds 0
            all_labelled = false;
          }
        }
        EXPECT_NEAR(sum, expected, 1e-9 * expected);
        EXPECT_NEAR(strip_J, released, 1e-9 * expected);
        // As displayed: the labels, summed, round to the total the caption states
        // ("... of 1.38 J").
        static const std::regex total_pattern(
            R"((?: of |\(total )((?:\xE2\x88\x92)?[0-9][0-9,]*(?:\.([0-9]+))?) ([µmkMG]?J))");
        std::smatch match;
        ASSERT_TRUE(std::regex_search(panel.caption, match, total_pattern)) << panel.caption;
        const double total_unit = unitValue(match[3]);
        const double shown_total_J = parseShown(match[1]) * total_unit;
        const int total_decimals = match[2].matched ? static_cast<int>(match[2].length()) : 0;
        const double total_step_J = std::pow(10.0, -total_decimals) * total_unit;
        EXPECT_NEAR(shown_total_J, expected, 0.5 * total_step_J + 1e-12 * expected);
        if (all_labelled) {
          // Within half a step of the total's last figure: the sum rounds to it. One step where
          // no part could move (soft-contact at the start: 1.12 J + 0.250 J of 1.38 J).
          const double allowed = (some_part_movable ? 0.5 : 1.0) * total_step_J;
          EXPECT_LE(std::fabs(shown_sum_J - shown_total_J), allowed * (1.0 + 1e-9))
              << panel.caption;
          ++sums_checked;
        }
      }
    }
  }
  EXPECT_GT(sums_checked, 20 * 10);  // most presets label every segment
}

// Every number in `text`: fails on more than four significant figures, an exponent, a negative
// zero, or an ellipsis. The one ellipsis allowed is a whole last list item (", …"): a caption of a
// scene with many bodies lists its first velocities and says that more follow.
void expectLegible(const std::string& full_text, const std::string& where) {
  SCOPED_TRACE(where + ": " + full_text);
  const std::string ellipsis = "\u2026";  // U+2026, one character
  const std::string more = ", " + ellipsis;
  const std::string text =
      full_text.ends_with(more) ? full_text.substr(0, full_text.size() - more.size()) : full_text;
  EXPECT_EQ(text.find(ellipsis), std::string::npos) << "ellipsis";
  EXPECT_EQ(text.find("..."), std::string::npos) << "ellipsis";
  static const std::regex exponent(R"([0-9]\.?[eE][+\-\xE2]?[0-9])");
  EXPECT_FALSE(std::regex_search(text, exponent)) << "exponent";
  // A count ("collisions: 12797", "12797 collisions": the ideal gas after 3 s) is exact and read
  // whole: not a measurement, so not held to four figures.
  static const std::regex count(R"(collisions: [0-9,]+|[0-9,]+ collisions)");
  const std::string measured = std::regex_replace(text, count, "collisions");
  // Numbers: digits with thousands groups and decimals, optionally signed.
  static const std::regex number(
      R"(((?:\xE2\x88\x92|-)?)([0-9]{1,3}(?:,[0-9]{3})+|[0-9]+)(?:\.([0-9]+))?)");
  for (auto it = std::sregex_iterator(measured.begin(), measured.end(), number);
       it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    std::string digits = std::string(m[2]) + std::string(m[3]);
    digits.erase(std::remove(digits.begin(), digits.end(), ','), digits.end());
    const std::size_t first = digits.find_first_not_of('0');
    if (first == std::string::npos) {
      EXPECT_TRUE(std::string(m[1]).empty()) << "negative zero: " << m.str();
      continue;
    }
    // Trailing zeros of an integer are not significant (12,500); decimals' are.
    std::string significant = digits.substr(first);
    if (!m[3].matched) {
      while (significant.size() > 1 && significant.back() == '0') significant.pop_back();
    }
    EXPECT_LE(significant.size(), 4u) << "too many figures: " << m.str();
  }
}

void expectFrameLegible(const frame::FrameModel& frame, const std::string& where) {
  expectLegible(frame.title, where + " title");
  expectLegible(frame.time_readout, where + " time");
  expectLegible(frame.subtitle, where + " subtitle");
  for (const frame::PanelModel& panel : frame.panels) {
    expectLegible(panel.heading, where + " heading");
    expectLegible(panel.info, where + " info");
    expectLegible(panel.caption, where + " caption");
    for (const frame::BodyModel& body : panel.bodies) {
      expectLegible(body.label, where + " label");
      expectLegible(body.velocity_label, where + " velocity");
    }
    for (const frame::EnergySegment& segment : panel.energy_bar.segments) {
      expectLegible(segment.label, where + " bar");
    }
  }
  for (const frame::ChartModel& chart : frame.charts) {
    expectLegible(chart.title, where + " chart title");
    expectLegible(chart.y_label, where + " chart axis");
  }
}

TEST(FrameNumbersTest, EveryTextOfEveryPresetIsLegible) {
  for (const Picture& picture : everyPreset()) {
    const compose::FrameSource& frames = picture.animation.frames;
    std::vector<report::PanelDescription> panels;
    for (std::size_t p = 0; p < frames.panelCount(); ++p) {
      panels.push_back({frames.panelHeading(p), &frames.panelTimeline(p)});
    }
    for (int k = 0; k < kInstants; k += 3) {
      const double t = instant(picture.scene, k);
      const std::string where = picture.preset + " at " + std::to_string(t);
      expectFrameLegible(frames.frameAtSimulated(t), where);
      expectLegible(report::describePanels(panels, picture.scene.title, t), where + " alt text");
    }
    expectFrameLegible(frames.strobeFrame(5.0), picture.preset + " strobe");
    expectFrameLegible(frames.chartFrame(), picture.preset + " chart");
    report::NarrationOptions options;
    options.title = picture.scene.title;
    for (const report::Cue& cue : report::narrate(frames.timeline(), options)) {
      expectLegible(cue.text, picture.preset + " caption cue");
    }
  }
}

// Significant figures of a shown number with `decimals` decimals: "7.22" -> 3, "0.680" -> 3.
int figuresOf(double value, int decimals) {
  if (value == 0.0) return 0;
  return static_cast<int>(std::floor(std::log10(std::fabs(value)))) + decimals + 1;
}

// The numbers the issue found unreadable ("0.01 J", "185700.00 J") read with three significant
// figures each, in the unit of the energy at the start (a part below a tenth of that unit in its
// own prefix), and true to their last figure. Expected energies: ½·m·v² of the velocities at that
// instant, and for car-crash the closed form of its one impact.
TEST(FrameNumbersTest, AirTrackAndCarCrashReadInUnitsThatFit) {
  int checked = 0;
  for (const auto& [preset, t] :
       {std::pair<std::string, double>{"air-track", 1.5}, {"car-crash", 1.8}}) {
    for (const Picture& picture : everyPreset()) {
      if (picture.preset != preset) continue;
      const frame::FrameModel frame = picture.animation.frames.frameAtSimulated(t);
      const frame::PanelModel& panel = frame.panels.front();
      SCOPED_TRACE(preset + ": " + panel.caption);
      const physics::Timeline& timeline = picture.animation.frames.panelTimeline(0);
      const physics::Snapshot now = timeline.sample(t);
      ASSERT_EQ(now.collision_count, 1);
      ASSERT_TRUE(timeline.softContacts().empty() || now.time_s > timeline.softContacts()[0].end_s);
      double start_J = 0.0;
      std::vector<double> expected;
      for (std::size_t i = 0; i < picture.scene.bodies.size(); ++i) {
        const scene::BodyDesc& body = picture.scene.bodies[i];
        start_J += 0.5 * body.mass_kg * body.velocity_mps.squaredNorm();
        expected.push_back(0.5 * body.mass_kg * now.bodies[i].velocity_mps.squaredNorm());
      }
      double kinetic_J = 0.0;
      for (double part : expected) kinetic_J += part;
      expected.push_back(start_J - kinetic_J);  // lost
      if (preset == "car-crash") {
        // Closing at u = 15 + 10 m/s above the threshold: e = e₀·(threshold/u)^exponent; lost
        // ½·μ·(1 − e²)·u², μ = m₁m₂/(m₁ + m₂).
        const scene::BodyDesc &a = picture.scene.bodies[0], &b = picture.scene.bodies[1];
        const double u = a.velocity_mps.x() - b.velocity_mps.x();
        const scene::RestitutionLawDesc& law = picture.scene.restitution_law;
        const double e =
            picture.scene.restitution * std::pow(law.threshold_speed_mps / u, law.exponent);
        const double mu = a.mass_kg * b.mass_kg / (a.mass_kg + b.mass_kg);
        EXPECT_NEAR(expected.back(), 0.5 * mu * (1.0 - e * e) * u * u, 1e-9 * start_J);
      }

      static const std::regex total_pattern(
          R"((?: of |\(total )([0-9][0-9,]*(?:\.([0-9]+))?) ([µmkMG]?J))");
      std::smatch total;
      ASSERT_TRUE(std::regex_search(panel.caption, total, total_pattern));
      const double total_value = parseShown(total[1]);
      const int total_decimals = total[2].matched ? static_cast<int>(total[2].length()) : 0;
      EXPECT_EQ(figuresOf(total_value, total_decimals), 3) << "the total has three figures";
      EXPECT_NEAR(total_value * unitValue(total[3]), start_J,
                  0.5 * std::pow(10.0, -total_decimals) * unitValue(total[3]));
      // The parts labelled now: a part the bar keeps through the run holds nothing between
      // its contacts (air-track's spring) and has no label then.
      std::vector<const frame::EnergySegment*> labelled;
      for (const frame::EnergySegment& segment : panel.energy_bar.segments) {
        if (segment.label.empty()) {
          EXPECT_EQ(segment.energy_J, 0.0) << "a part with energy but no label";
          continue;
        }
        labelled.push_back(&segment);
      }
      ASSERT_EQ(labelled.size(), expected.size());
      for (std::size_t k = 0; k < expected.size(); ++k) {
        const frame::EnergySegment& segment = *labelled[k];
        double value = 0.0;
        std::string unit;
        int decimals = 0;
        ASSERT_TRUE(labelValue(segment.label, value, unit, decimals)) << segment.label;
        EXPECT_EQ(figuresOf(value, decimals), 3) << segment.label;
        // In the total's unit down to a tenth of it, so the parts compare at a glance.
        if (expected[k] >= 0.1 * unitValue(total[3])) {
          EXPECT_EQ(unit, std::string(total[3])) << segment.label;
        }
        // True to its last figure (one step where the sum needed it rounded the other way).
        EXPECT_LE(std::fabs(value * unitValue(unit) - expected[k]),
                  std::pow(10.0, -decimals) * unitValue(unit))
            << segment.label;
        ++checked;
      }
      // The share lost, with three figures too: "(9.75%)".
      std::smatch percent;
      ASSERT_TRUE(std::regex_search(panel.caption, percent, std::regex(R"(\(([0-9.]+)%\))")));
      const std::string digits = percent[1];
      const std::size_t dot = digits.find('.');
      const int percent_decimals =
          dot == std::string::npos ? 0 : static_cast<int>(digits.size() - dot - 1);
      EXPECT_EQ(figuresOf(std::stod(digits), percent_decimals), 3);
      EXPECT_NEAR(std::stod(digits), 100.0 * expected.back() / start_J,
                  0.5 * std::pow(10.0, -percent_decimals) + 1e-9);
    }
  }
  EXPECT_EQ(checked, 6);
}

// The signed number and its decimals in a velocity label "v₁′ = +0.170 m/s" (1D) or the speed in
// "v₁ = 4.26 m/s, −82°" (2D).
bool velocityValue(const std::string& label, double& value, int& decimals) {
  static const std::regex pattern(R"(= ((?:\+|\xE2\x88\x92)?)([0-9][0-9,]*(?:\.([0-9]+))?) m/s)");
  std::smatch match;
  if (!std::regex_search(label, match, pattern)) return false;
  value = parseShown(match[2]) * (match[1] == kMinus ? -1.0 : 1.0);
  decimals = match[3].matched ? static_cast<int>(match[3].length()) : 0;
  return true;
}

// No number on a picture reads 0 unless its value is zero up to round-off, and every velocity
// and energy shown is its value to three significant figures: the body's velocity in the frame
// model, the segment's energy.
TEST(FrameNumbersTest, EveryVelocityAndEnergyIsTrueToThreeFigures) {
  int velocities = 0, energies = 0;
  for (const Picture& picture : everyPreset()) {
    const compose::FrameSource& frames = picture.animation.frames;
    for (int k = 0; k < kInstants; k += 2) {
      const double t = instant(picture.scene, k);
      const frame::FrameModel frame = frames.frameAtSimulated(t);
      for (const frame::PanelModel& panel : frame.panels) {
        SCOPED_TRACE(picture.preset + " at " + std::to_string(t));
        double fastest = 0.0;
        for (const frame::BodyModel& body : panel.bodies) {
          fastest = std::max(fastest, body.velocity_mps.norm());
        }
        for (const frame::BodyModel& body : panel.bodies) {
          double shown = 0.0;
          int decimals = 0;
          if (!velocityValue(body.velocity_label, shown, decimals)) continue;
          const double truth = panel.two_d ? body.velocity_mps.norm() : body.velocity_mps.x();
          if (shown == 0.0) {
            EXPECT_LE(std::fabs(truth), 1e-9 * fastest) << body.velocity_label;
          } else {
            EXPECT_EQ(figuresOf(shown, decimals), 3) << body.velocity_label;
            EXPECT_LE(std::fabs(shown - truth), 0.5 * std::pow(10.0, -decimals) * (1.0 + 1e-9))
                << body.velocity_label;
          }
          ++velocities;
        }
        for (const frame::EnergySegment& segment : panel.energy_bar.segments) {
          double shown = 0.0;
          std::string unit;
          int decimals = 0;
          if (!labelValue(segment.label, shown, unit, decimals)) continue;
          if (shown == 0.0) {
            EXPECT_LE(segment.energy_J, 1e-9 * panel.energy_bar.full_scale_J) << segment.label;
          } else {
            const int figures = figuresOf(shown, decimals);
            EXPECT_TRUE(figures == 3 || figures == 4) << segment.label;
          }
          ++energies;
        }
      }
    }
  }
  EXPECT_GT(velocities, 200);
  EXPECT_GT(energies, 200);
}

// pi-blocks: the small block's speed and energy read true next to the big block's. Worked out
// here collision by collision (e = 1, wall on the left): blocks closing (v₂ < v₁) exchange
// momentum by the 1D law, a small block moving left (v₁ < 0) bounces off the wall; after the
// first hit v₁′ = 2·m₂·v₂/(m₁ + m₂).
TEST(FrameNumbersTest, PiBlocksSmallBlockReadsTrueBesideTheBigOne) {
  for (const Picture& picture : everyPreset()) {
    if (picture.preset != "pi-blocks") continue;
    const double m1 = picture.scene.bodies[0].mass_kg, m2 = picture.scene.bodies[1].mass_kg;
    double v1 = picture.scene.bodies[0].velocity_mps.x(),
           v2 = picture.scene.bodies[1].velocity_mps.x();
    const double first_v1 = ((m1 - m2) * v1 + 2.0 * m2 * v2) / (m1 + m2);
    int hits = 0;
    for (;;) {
      if (v2 < v1) {
        const double a = ((m1 - m2) * v1 + 2.0 * m2 * v2) / (m1 + m2);
        const double b = ((m2 - m1) * v2 + 2.0 * m1 * v1) / (m1 + m2);
        v1 = a, v2 = b;
      } else if (v1 < 0.0) {
        v1 = -v1;
      } else {
        break;
      }
      ++hits;
    }
    const compose::FrameSource& frames = picture.animation.frames;
    const frame::FrameModel end = frames.frameAtSimulated(picture.scene.duration_s);
    ASSERT_EQ(end.panels.front().info.rfind("collisions: " + std::to_string(hits) + " ", 0), 0u)
        << end.panels.front().info;
    const frame::PanelModel& panel = end.panels.front();
    SCOPED_TRACE(panel.caption);
    double shown = 0.0;
    int decimals = 0;
    // The caption carries every velocity (a label may give way to the body's number).
    const std::size_t small_block = panel.caption.find("; v\u2081\u2032 = ");
    ASSERT_NE(small_block, std::string::npos);
    ASSERT_TRUE(velocityValue(panel.caption.substr(small_block), shown, decimals));
    EXPECT_GT(v1, 0.0);
    EXPECT_EQ(figuresOf(shown, decimals), 3);
    EXPECT_NEAR(shown, v1, 0.5 * std::pow(10.0, -decimals));
    double energy = 0.0;
    std::string unit;
    ASSERT_TRUE(labelValue(panel.energy_bar.segments[0].label, energy, unit, decimals))
        << panel.energy_bar.segments[0].label;
    EXPECT_EQ(figuresOf(energy, decimals), 3);
    EXPECT_NEAR(energy * unitValue(unit), 0.5 * m1 * v1 * v1,
                0.5 * std::pow(10.0, -decimals) * unitValue(unit));
    // Just after the first hit: 2.00 J beside 5.00 kJ, not "0 kJ".
    const double after_first_s = 1.4;
    const frame::PanelModel early = frames.frameAtSimulated(after_first_s).panels.front();
    ASSERT_EQ(early.info.rfind("collisions: 1 ", 0), 0u) << early.info;
    ASSERT_TRUE(labelValue(early.energy_bar.segments[0].label, energy, unit, decimals))
        << early.energy_bar.segments[0].label;
    EXPECT_EQ(figuresOf(energy, decimals), 3);
    EXPECT_NEAR(energy * unitValue(unit), 0.5 * m1 * first_v1 * first_v1,
                0.5 * std::pow(10.0, -decimals) * unitValue(unit));
  }
}

// Nothing reads a value that is round-off of zero. The ballistic pendulum starts with the block
// hanging at rest at the bottom of its swing and the bullet level with it: at t = 0 the bar holds
// the bullet's ½·(0.01 kg)·(200 m/s)² = 200 J alone, and PE, counted from the start, is 0 (the
// bullet riding in the block later dips micrometres below where it came in: no "PE 1.01 µJ").
TEST(FrameNumbersTest, AtTheStartNoEnergyIsRoundOffOfZero) {
  const scene::SceneDesc scene = scene::loadPreset("ballistic-pendulum");
  const app::Animation animation = app::animate(scene, {1280, 720});
  const frame::PanelModel start = animation.frames.frameAtSimulated(0.0).panels.front();
  const physics::BodyDef& bullet = animation.frames.timeline().world().bodies[1];
  ASSERT_LT(bullet.mass_kg, 0.1) << "body 2 is the bullet";
  const double bullet_J = 0.5 * bullet.mass_kg * scene.bodies[1].velocity_mps.squaredNorm();
  ASSERT_FALSE(start.energy_bar.segments.empty());
  for (const frame::EnergySegment& segment : start.energy_bar.segments) {
    double value = 0.0;
    std::string unit;
    int decimals = 0;
    if (segment.label.empty()) {  // a part with nothing to show is drawn without its label
      EXPECT_EQ(segment.energy_J, 0.0);
      continue;
    }
    if (segment.label.rfind("KE\u2082", 0) == 0) {
      ASSERT_TRUE(labelValue(segment.label, value, unit, decimals)) << segment.label;
      EXPECT_NEAR(value * unitValue(unit), bullet_J, 0.5 * std::pow(10.0, -decimals))
          << segment.label;
    } else {  // reads 0: no figure but zeros (subscripts are not ASCII digits)
      EXPECT_EQ(segment.label.find_first_of("123456789"), std::string::npos)
          << segment.label << " at t = 0";
    }
  }
}

// A label that gives way (to the body's number, in a crowd) leaves nothing behind: no place and so
// no leader line pointing from empty space at its body; every label still shown has its place.
TEST(FrameNumbersTest, ALabelThatGivesWayLeavesNoLeader) {
  int dropped = 0, placed = 0;
  for (const Picture& picture : everyPreset()) {
    const compose::FrameSource& frames = picture.animation.frames;
    for (int k = 0; k < kInstants; ++k) {
      const double t = instant(picture.scene, k);
      for (const frame::PanelModel& panel : frames.frameAtSimulated(t).panels) {
        for (const frame::BodyModel& body : panel.bodies) {
          SCOPED_TRACE(picture.preset + " at " + std::to_string(t));
          for (const auto& [text, at] :
               {std::pair{&body.label, &body.label_at},
                std::pair{&body.velocity_label, &body.velocity_label_at}}) {
            EXPECT_EQ(text->empty(), !at->has_value()) << *text;
            dropped += text->empty() && !body.tag.empty() ? 1 : 0;
            placed += at->has_value() ? 1 : 0;
          }
        }
      }
    }
  }
  EXPECT_GT(dropped, 0);  // pi-blocks' small block gives way beside the big one
  EXPECT_GT(placed, 100);
}

}  // namespace
}  // namespace collide
