// The readout line says the numbers a scene is about (issue 18): the e of each impact where a
// scene's impacts differ in e, and the spin of a stuck pair. Expected values come from the
// definition of e (velocities before and after), the scene's restitution law, and conservation of
// angular momentum, never from the code under test.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

#include "app/animation.hpp"
#include "physics/timeline.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

const std::string kReadoutMinus = "\u2212";

double shownNumber(std::string text) {
  double sign = 1.0;
  if (text.rfind(kReadoutMinus, 0) == 0) {
    sign = -1.0;
    text.erase(0, kReadoutMinus.size());
  } else if (!text.empty() && text[0] == '+') {
    text.erase(0, 1);
  }
  return sign * std::stod(text);
}

// The "last e = …" of an info line; NaN when it has none.
double lastE(const std::string& info) {
  std::smatch m;
  static const std::regex pattern("^collisions: [0-9]+, last e = ([0-9.]+)   ");
  return std::regex_search(info, m, pattern) ? std::stod(m[1]) : std::nan("");
}

// e from its definition: the normal separation speed over the approach speed.
double measuredE(const physics::CollisionEvent& event) {
  const core::Vec2 before = event.velocity_b_before_mps - event.velocity_a_before_mps;
  const core::Vec2 after = event.velocity_b_after_mps - event.velocity_a_after_mps;
  return -after.dot(event.normal) / before.dot(event.normal);
}

TEST(ReadoutsTest, GranularChainShowsTheEOfEachImpact) {
  const scene::SceneDesc scene = scene::loadPreset("granular-chain");
  const app::Animation animation = app::animate(scene, {1280, 720});
  const std::vector<physics::CollisionEvent>& events = animation.frames.timeline().collisions();
  ASSERT_GE(events.size(), 5u);
  EXPECT_TRUE(std::isnan(
      lastE(animation.frames.frameAtSimulated(0.5 * events[0].time_s).panels.front().info)));
  for (std::size_t k = 0; k + 1 < events.size(); ++k) {
    if (events[k + 1].time_s - events[k].time_s < 1e-6) continue;  // no instant between them
    const double t = 0.5 * (events[k].time_s + events[k + 1].time_s);
    const std::string info = animation.frames.frameAtSimulated(t).panels.front().info;
    // Three significant figures of e <= 1: within half a unit in the third decimal.
    EXPECT_NEAR(lastE(info), measuredE(events[k]), 0.0005 + 1e-12) << info;
  }
}

TEST(ReadoutsTest, CarCrashShowsTheEItsSpeedGives) {
  const scene::SceneDesc scene = scene::loadPreset("car-crash");
  const app::Animation animation = app::animate(scene, {1280, 720});
  // Closing at 15 + 10 m/s, above the threshold: e = e0 (threshold / u)^exponent.
  const double u = scene.bodies[0].velocity_mps.x() - scene.bodies[1].velocity_mps.x();
  const scene::RestitutionLawDesc& law = scene.restitution_law;
  ASSERT_EQ(law.kind, scene::RestitutionLawKind::kSpeedThreshold);
  ASSERT_GT(u, law.threshold_speed_mps);
  const double e = scene.restitution * std::pow(law.threshold_speed_mps / u, law.exponent);
  const std::string info = animation.frames.frameAtSimulated(scene.duration_s).panels.front().info;
  EXPECT_NEAR(lastE(info), e, 0.5 * std::pow(10.0, std::floor(std::log10(e)) - 2) + 1e-12) << info;
}

TEST(ReadoutsTest, ScenesWithOneEDoNotRepeatIt) {
  const app::Animation animation = app::animate(scene::loadPreset("worked-example"), {1280, 720});
  const std::string info = animation.frames.frameAtSimulated(3.0).panels.front().info;
  EXPECT_TRUE(std::isnan(lastE(info))) << info;
}

// Two solid disks stick: the pair keeps the angular momentum about its centre of mass,
// L = sum m (r x v), and spins at omega = L / I with I = sum (m R^2 / 2 + m d^2).
TEST(ReadoutsTest, StuckPairShowsItsSpin) {
  const scene::SceneDesc scene = scene::loadPreset("stick-2d");
  ASSERT_EQ(scene.bodies.size(), 2u);
  const scene::BodyDesc &a = scene.bodies[0], &b = scene.bodies[1];
  const double m = a.mass_kg + b.mass_kg;
  const core::Vec2 com = (a.mass_kg * a.position_m + b.mass_kg * b.position_m) / m;
  const auto cross = [](const core::Vec2& r, const core::Vec2& v) {
    return r.x() * v.y() - r.y() * v.x();
  };
  const core::Vec2 v_com = (a.mass_kg * a.velocity_mps + b.mass_kg * b.velocity_mps) / m;
  const double angular_momentum = a.mass_kg * cross(a.position_m - com, a.velocity_mps - v_com) +
                                  b.mass_kg * cross(b.position_m - com, b.velocity_mps - v_com);
  // Joined, their centres are a radius plus a radius apart.
  const double apart = a.size_m + b.size_m;
  const double d_a = apart * b.mass_kg / m, d_b = apart * a.mass_kg / m;
  const double inertia = 0.5 * a.mass_kg * a.size_m * a.size_m +
                         0.5 * b.mass_kg * b.size_m * b.size_m + a.mass_kg * d_a * d_a +
                         b.mass_kg * d_b * d_b;
  const double omega = angular_momentum / inertia;
  ASSERT_GT(std::abs(omega), 0.1);

  const app::Animation animation = app::animate(scene, {1280, 720});
  const std::string before = animation.frames.frameAtSimulated(0.0).panels.front().info;
  const std::string omega_symbol = "\u03c9";
  EXPECT_EQ(before.find(omega_symbol), std::string::npos) << before;
  const std::string info = animation.frames.frameAtSimulated(scene.duration_s).panels.front().info;
  std::smatch match;
  ASSERT_TRUE(
      std::regex_search(info, match, std::regex("   \u03c9 = ((?:\\+|\u2212)[0-9.]+) rad/s   ")))
      << info;
  const double shown = shownNumber(match[1]);
  EXPECT_NEAR(shown, omega,
              0.5 * std::pow(10.0, std::floor(std::log10(std::abs(omega))) - 2) + 1e-12)
      << info;
}

}  // namespace
}  // namespace collide
