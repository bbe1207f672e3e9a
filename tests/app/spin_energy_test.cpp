// SPDX-License-Identifier: MIT
// A kinetic energy that includes rotation says so (issue 37 item 5): stick-2d's stuck pair turns
// as one rigid body, so each disk also spins about its own centre. The energy bar shows that spin
// apart, as "spin", and each KE as ½·m·v² of its disk's centre, which a reader checks against the
// v the picture writes (KE₁ read 0.367 J where ½·1 kg·(0.827 m/s)² is 0.342 J). The numbers come
// from the conservation laws here, not from compose. Balls rolling on a cloth spin too.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

#include "app/animation.hpp"
#include "physics/timeline.hpp"
#include "scene/scene_desc.hpp"
#include "text/language.hpp"

namespace collide {
namespace {

// A bar label's number and the step of its last figure, in J ("KE₁ 0.342 J", "spin 76.8 mJ").
bool barValue(const std::string& label, double& value_J, double& step_J) {
  static const std::regex pattern(R"(([0-9]+)(?:\.([0-9]+))? ([m]?)J$)");
  std::smatch match;
  if (!std::regex_search(label, match, pattern)) return false;
  const double unit = match[3] == "m" ? 1e-3 : 1.0;
  const std::string decimals = match[2].matched ? std::string(match[2]) : "";
  value_J = std::stod(std::string(match[1]) + "." + decimals + "0") * unit;
  step_J = std::pow(10.0, -static_cast<double>(decimals.size())) * unit;
  return true;
}

// The bar's part named `name` ("KE₁ ", "spin ") is labelled with expected_J, true to its last
// figure (one step where the parts' sum moved it).
void expectBarPart(const frame::PanelModel& panel, const std::string& name, double expected_J) {
  bool found = false;
  for (const frame::EnergySegment& segment : panel.energy_bar.segments) {
    if (segment.label.rfind(name, 0) != 0) continue;
    found = true;
    double value_J = 0.0, step_J = 0.0;
    ASSERT_TRUE(barValue(segment.label, value_J, step_J)) << segment.label;
    EXPECT_LE(std::fabs(value_J - expected_J), step_J * (1.0 + 1e-9))
        << segment.label << " against " << expected_J << " J";
  }
  EXPECT_TRUE(found) << "no bar label " << name;
}

double cross(const core::Vec2& a, const core::Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// The stuck pair after the impact, from momentum and angular momentum about the centre of mass.
struct StuckPair {
  double m1, m2, radius;
  core::Vec2 v_cm, r1;  // centre-of-mass velocity; disk 1's centre from the centre of mass at t_hit
  double omega, t_hit;
  // Disk 1's velocity at t: the centre of mass's plus ω × its offset, turned by ω (t − t_hit).
  core::Vec2 v1(double t) const {
    const double angle = omega * (t - t_hit);
    const core::Vec2 r{std::cos(angle) * r1.x() - std::sin(angle) * r1.y(),
                       std::sin(angle) * r1.x() + std::cos(angle) * r1.y()};
    return v_cm + omega * core::Vec2{-r.y(), r.x()};
  }
  // Disk 2 stays opposite disk 1 across the centre of mass: r2 = −(m1/m2)·r1.
  core::Vec2 v2(double t) const { return v_cm - (m1 / m2) * (v1(t) - v_cm); }
  double spin_J() const { return 0.5 * (0.5 * (m1 + m2) * radius * radius) * omega * omega; }
};

// stick-2d: disk 1 (1 kg, radius 0.2 m) from (−1.2, 0.2) at +2 m/s along x, disk 2 (2 kg, the
// same radius) at rest at the origin. They touch with centres 0.4 m apart, disk 1 at
// x = −√(0.4² − 0.2²).
StuckPair stick2d() {
  const double m1 = 1.0, m2 = 2.0, radius = 0.2, speed = 2.0;
  const core::Vec2 hit1{-std::sqrt(0.16 - 0.04), 0.2}, hit2{0.0, 0.0};
  const double t_hit = (hit1.x() + 1.2) / speed;
  const core::Vec2 cm = (m1 * hit1 + m2 * hit2) / (m1 + m2);
  const core::Vec2 v_cm = core::Vec2{m1 * speed, 0.0} / (m1 + m2);
  const core::Vec2 r1 = hit1 - cm, r2 = hit2 - cm;
  const double angular_momentum =
      m1 * cross(r1, core::Vec2{speed, 0.0} - v_cm) + m2 * cross(r2, -v_cm);
  const double inertia = m1 * r1.squaredNorm() + m2 * r2.squaredNorm() +
                         0.5 * m1 * radius * radius + 0.5 * m2 * radius * radius;
  return {m1, m2, radius, v_cm, r1, angular_momentum / inertia, t_hit};
}

TEST(SpinEnergyTest, TheBarShowsTheStuckPairsSpinApartFromEachKE) {
  const text::ScopedLanguage english("en");
  const StuckPair pair = stick2d();
  const scene::SceneDesc scene = scene::loadPreset("stick-2d");
  const app::Animation animation = app::animate(scene, {1280, 720});
  for (const double t : {2.0, 3.5}) {
    SCOPED_TRACE("t = " + std::to_string(t));
    const frame::PanelModel panel = animation.frames.frameAtSimulated(t).panels.front();
    const double expected[] = {0.5 * pair.m1 * pair.v1(t).squaredNorm(),
                               0.5 * pair.m2 * pair.v2(t).squaredNorm(), pair.spin_J()};
    const std::string names[] = {"KE\u2081 ", "KE\u2082 ", "spin "};
    for (int k = 0; k < 3; ++k) expectBarPart(panel, names[k], expected[k]);
  }
  // Before the impact nothing spins: the spin has no label, KE₁ is the whole ½·m·v².
  const frame::PanelModel before = animation.frames.frameAtSimulated(0.1).panels.front();
  for (const frame::EnergySegment& segment : before.energy_bar.segments) {
    EXPECT_NE(segment.label.rfind("spin", 0), 0u) << segment.label;
  }
}

// A ball rolling without slipping turns at ω = v/R; a solid ball's moment of inertia is
// (2/5)·m·R², so its spin holds ½·(2/5)·m·R²·(v/R)² = (1/5)·m·v² beside its ½·m·v².
// billiards-follow's cue ball rolls from the start; at the end both balls roll.
TEST(SpinEnergyTest, RollingBallsShowTheirSpinApartFromEachKE) {
  const text::ScopedLanguage english("en");
  const scene::SceneDesc scene = scene::loadPreset("billiards-follow");
  const app::Animation animation = app::animate(scene, {1280, 720});
  const physics::Timeline& timeline = animation.frames.panelTimeline(0);
  // The bar stands for the energy at the start, the cue ball's spin included: ½·m·v₀² +
  // (1/5)·m·v₀².
  const double start_J = 0.7 * scene.bodies[0].mass_kg * scene.bodies[0].velocity_mps.squaredNorm();
  EXPECT_NEAR(animation.frames.frameAtSimulated(0.0).panels.front().energy_bar.full_scale_J,
              start_J, 1e-12 * start_J);
  for (const double t : {0.1, scene.duration_s}) {
    SCOPED_TRACE("t = " + std::to_string(t));
    const physics::Snapshot snapshot = timeline.sample(t);
    double spin_J = 0.0;
    double kinetic_J[2] = {0.0, 0.0};
    for (int i = 0; i < 2; ++i) {
      const double mass_kg = scene.bodies[i].mass_kg;
      const double speed_squared = snapshot.bodies[i].velocity_mps.squaredNorm();
      kinetic_J[i] = 0.5 * mass_kg * speed_squared;
      spin_J += 0.2 * mass_kg * speed_squared;
    }
    ASSERT_GT(spin_J, 0.0);
    const frame::PanelModel panel = animation.frames.frameAtSimulated(t).panels.front();
    const std::string names[] = {"KE\u2081 ", "KE\u2082 ", "spin "};
    const double expected[] = {kinetic_J[0], kinetic_J[1], spin_J};
    for (int k = 0; k < 3; ++k) {
      if (expected[k] == 0.0) continue;  // the object ball at rest before the impact
      expectBarPart(panel, names[k], expected[k]);
    }
  }
}

}  // namespace
}  // namespace collide
