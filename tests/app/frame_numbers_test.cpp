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

// The number at the end of an energy label "KE₁ 12.3 mJ" and its unit.
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
                     const render::PanelModel& at_start) {
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
  for (const auto& body : bodies)
    energy += 0.5 * body.mass_kg * (body.velocity_mps - frame).squaredNorm();
  for (const render::EnergySegment& segment : at_start.energy_bar.segments) {
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

double instant(const scene::SceneDesc& scene, int k) {
  return scene.duration_s * k / (kInstants - 1);
}

TEST(FrameNumbersTest, EnergyBooksAddUpAtEveryInstantOfEveryPreset) {
  int sums_checked = 0;
  for (const Picture& picture : everyPreset()) {
    const compose::FrameSource& frames = picture.animation.frames;
    const render::FrameModel start = frames.frameAtSimulated(0.0);
    for (int k = 0; k < kInstants; ++k) {
      const double t = instant(picture.scene, k);
      const render::FrameModel frame = frames.frameAtSimulated(t);
      ASSERT_EQ(frame.panels.size(), frames.panelCount());
      for (std::size_t p = 0; p < frame.panels.size(); ++p) {
        SCOPED_TRACE(picture.preset + " panel " + std::to_string(p) +
                     " at t = " + std::to_string(t));
        const render::PanelModel& panel = frame.panels[p];
        const double expected =
            initialEnergy(picture.scene, frames.panelTimeline(p), start.panels[p]);
        double sum = 0.0, shown_sum = 0.0;
        bool all_labelled = true;
        std::string unit;
        int decimals = 0;
        for (const render::EnergySegment& segment : panel.energy_bar.segments) {
          EXPECT_GE(segment.energy_J, 0.0) << segment.label;
          sum += segment.energy_J;
          double value = 0.0;
          if (labelValue(segment.label, value, unit, decimals)) {
            shown_sum += value;
          } else if (segment.energy_J > 0.0) {  // a zero-width segment has no entry and adds 0
            all_labelled = false;
          }
        }
        EXPECT_NEAR(sum, expected, 1e-9 * expected);
        // As displayed: the labels add up to the total the caption states ("... of 1.38 J").
        static const std::regex total_pattern(
            R"( of ((?:\xE2\x88\x92)?[0-9][0-9,]*(?:\.[0-9]+)?) ([µmkMG]?J))");
        std::smatch match;
        ASSERT_TRUE(std::regex_search(panel.caption, match, total_pattern)) << panel.caption;
        const double shown_total = parseShown(match[1]);
        EXPECT_NEAR(shown_total * unitValue(match[2]), expected,
                    0.5 * std::pow(10.0, -decimals) * unitValue(match[2]) + 1e-12 * expected);
        if (all_labelled) {
          EXPECT_EQ(unit, std::string(match[2]));
          EXPECT_NEAR(shown_sum, shown_total, 0.01 * std::pow(10.0, -decimals)) << panel.caption;
          ++sums_checked;
        }
      }
    }
  }
  EXPECT_GT(sums_checked, 20 * 10);  // most presets label every segment
}

// Every number in `text`: fails on more than four significant figures, an exponent, a negative
// zero, or an ellipsis.
void expectLegible(const std::string& text, const std::string& where) {
  SCOPED_TRACE(where + ": " + text);
  const std::string ellipsis = "\u2026";  // U+2026, one character
  EXPECT_EQ(text.find(ellipsis), std::string::npos) << "ellipsis";
  EXPECT_EQ(text.find("..."), std::string::npos) << "ellipsis";
  static const std::regex exponent(R"([0-9]\.?[eE][+\-\xE2]?[0-9])");
  EXPECT_FALSE(std::regex_search(text, exponent)) << "exponent";
  // Numbers: digits with thousands groups and decimals, optionally signed.
  static const std::regex number(
      R"(((?:\xE2\x88\x92|-)?)([0-9]{1,3}(?:,[0-9]{3})+|[0-9]+)(?:\.([0-9]+))?)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number);
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

void expectFrameLegible(const render::FrameModel& frame, const std::string& where) {
  expectLegible(frame.title, where + " title");
  expectLegible(frame.time_readout, where + " time");
  expectLegible(frame.subtitle, where + " subtitle");
  for (const render::PanelModel& panel : frame.panels) {
    expectLegible(panel.heading, where + " heading");
    expectLegible(panel.info, where + " info");
    expectLegible(panel.caption, where + " caption");
    for (const render::BodyModel& body : panel.bodies) {
      expectLegible(body.label, where + " label");
      expectLegible(body.velocity_label, where + " velocity");
    }
    for (const render::EnergySegment& segment : panel.energy_bar.segments) {
      expectLegible(segment.label, where + " bar");
    }
  }
  for (const render::ChartModel& chart : frame.charts) {
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

// The numbers the issue found unreadable ("0.01 J", "185700.00 J") now read in a unit where the
// energy at the start has three significant figures, and every part shares that unit and its
// decimals (so the parts add up as shown): 7.2 mJ beside 14.5 mJ, never 0.01 J beside 0.01 J.
TEST(FrameNumbersTest, AirTrackAndCarCrashReadInUnitsThatFit) {
  int checked = 0;
  for (const auto& [preset, t] :
       {std::pair<std::string, double>{"air-track", 1.5}, {"car-crash", 1.8}}) {
    for (const Picture& picture : everyPreset()) {
      if (picture.preset != preset) continue;
      const render::FrameModel frame = picture.animation.frames.frameAtSimulated(t);
      const render::PanelModel& panel = frame.panels.front();
      SCOPED_TRACE(preset + ": " + panel.caption);
      static const std::regex total_pattern(R"( of ([0-9][0-9,]*)(?:\.([0-9]+))? ([µmkMG]?J))");
      std::smatch total;
      ASSERT_TRUE(std::regex_search(panel.caption, total, total_pattern));
      std::string integer = total[1];
      integer.erase(std::remove(integer.begin(), integer.end(), ','), integer.end());
      const int decimals = total[2].matched ? static_cast<int>(total[2].length()) : 0;
      const int figures = (integer == "0" ? 0 : static_cast<int>(integer.size())) + decimals;
      EXPECT_EQ(figures, 3) << "the total has three significant figures";
      for (const render::EnergySegment& segment : panel.energy_bar.segments) {
        double value = 0.0;
        std::string unit;
        int part_decimals = 0;
        ASSERT_TRUE(labelValue(segment.label, value, unit, part_decimals)) << segment.label;
        EXPECT_EQ(unit, std::string(total[3])) << segment.label;
        if (value != 0.0) {
          EXPECT_EQ(part_decimals, decimals) << segment.label;
        }
        // A part of at least a tenth of the total shows two figures or more.
        if (segment.energy_J >= 0.1 * panel.energy_bar.full_scale_J) {
          EXPECT_GE(value * std::pow(10.0, part_decimals), 10.0) << segment.label;
        }
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 6);
}

}  // namespace
}  // namespace collide
