// SPDX-License-Identifier: MIT
// Every preset's energy books read back from the FrameModel: the parts add up (to the energy at
// the start, and as displayed), no segment is negative, and nothing reads a value that is
// round-off of zero.
#include "frame_numbers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

using frame_numbers::everyPreset;
using frame_numbers::instant;
using frame_numbers::kInstants;
using frame_numbers::labelValue;
using frame_numbers::parseShown;
using frame_numbers::Picture;
using frame_numbers::unitValue;

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

// The energy released by t: the stated Q of every release due by then (the presets give Q).
double releasedBy(const scene::SceneDesc& scene, double t_s) {
  double released_J = 0.0;
  for (const scene::ReleaseDesc& release : scene.releases) {
    if (release.time_s <= t_s) released_J += release.energy_J.value_or(0.0);
  }
  return released_J;
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
}  // namespace
}  // namespace collide
