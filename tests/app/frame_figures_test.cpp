// SPDX-License-Identifier: MIT
// The numbers on the pictures true to their figures: velocities and energies to three significant
// figures of their values, in units that fit (air-track, car-crash), and pi-blocks' small block
// beside the big one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "app/animation.hpp"
#include "frame_numbers.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

using frame_numbers::everyPreset;
using frame_numbers::figuresOf;
using frame_numbers::instant;
using frame_numbers::kInstants;
using frame_numbers::labelValue;
using frame_numbers::parseShown;
using frame_numbers::Picture;
using frame_numbers::unitValue;
using frame_numbers::velocityValue;

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
}  // namespace
}  // namespace collide
