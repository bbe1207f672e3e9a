// SPDX-License-Identifier: MIT
// Property tests over random cradles (bodies on strings of one length hung in a touching row,
// random masses, e, release angles and lengths): energy is never created (kinetic + potential +
// lost stays the start's energy, lost never falls), no two balls overlap, and the outcome of a
// scene does not depend on how its balls are numbered or on which side of the screen it is
// (its mirror image and its reversed numbering give the same motion, mirrored).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace string_property_test {

using testing::disk;
using testing::numbered;

constexpr double kG = 9.81;
constexpr int kScenes = 16;

struct Ball {
  double mass_kg, angle_rad;
};

struct RandomCradle {
  double length_m, radius_m, restitution, duration_s;
  std::vector<Ball> balls;
};

RandomCradle randomCradle(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  RandomCradle c;
  c.length_m = 0.3 + 0.7 * unit(rng);
  c.radius_m = 0.02 + 0.06 * unit(rng);
  c.restitution = unit(rng) < 0.2 ? 1.0 : 0.3 + 0.69 * unit(rng);
  // A few swings: long enough for groups to form and part at small e, short enough that
  // rounding (the order of a sum) cannot grow past the tolerances below.
  c.duration_s = 2.0 + 2.0 * unit(rng);
  const int n = 2 + static_cast<int>(4 * unit(rng));
  const int left = 1 + static_cast<int>((n - 1) * unit(rng) * 0.5);
  const bool right = unit(rng) < 0.3;
  const double pull = 0.2 + 0.6 * unit(rng);
  for (int k = 0; k < n; ++k) {
    double angle = 0.0;
    if (k < left) angle = -pull;
    if (right && k == n - 1) angle = 0.5 * pull;
    c.balls.push_back({0.1 + unit(rng), angle});
  }
  return c;
}

// The cradle as a world; `mirror` reflects it in x = 0, `reverse` numbers the balls from the
// right. Ball k (from the left of the unmirrored scene) is body bodyOf(k).
WorldDef worldOf(const RandomCradle& c, bool mirror, bool reverse) {
  WorldDef world;
  world.dimensions = 2;
  world.gravity_mps2 = {0.0, -kG};
  world.duration_s = c.duration_s;
  world.restitution = c.restitution;
  const int n = static_cast<int>(c.balls.size());
  const double sign = mirror ? -1.0 : 1.0;
  for (int i = 0; i < n; ++i) {
    const int k = reverse ? n - 1 - i : i;
    const double angle = sign * c.balls[k].angle_rad;
    const core::Vec2 pivot{sign * 2.0 * c.radius_m * (k - 0.5 * (n - 1)), 0.0};
    BodyDef ball =
        disk(numbered("ball ", k + 1), c.balls[k].mass_kg, c.radius_m,
             pivot + c.length_m * core::Vec2(std::sin(angle), -std::cos(angle)), {0.0, 0.0});
    ball.on_string = true;
    ball.pivot_m = pivot;
    world.bodies.push_back(ball);
  }
  return world;
}

void expectEnergyNeverCreatedAndNoOverlap(const RandomCradle& c, const Timeline& timeline,
                                          int scene) {
  const double start_J = timeline.mechanicalEnergy(timeline.sample(0.0));
  // The potential energy is counted from y = 0, the pivots' height, so the energies are
  // negative: the scale is the weight of the balls over the strings' length.
  double scale_J = 0.0;
  for (const Ball& ball : c.balls) scale_J += ball.mass_kg * kG * c.length_m;
  double lost_before = 0.0;
  for (int s = 0; s <= 100; ++s) {
    const Snapshot at = timeline.sample(c.duration_s * s / 100.0);
    EXPECT_NEAR(timeline.mechanicalEnergy(at) + at.energy_lost_J, start_J, 1e-12 * scale_J)
        << "scene " << scene << " sample " << s;
    EXPECT_GE(at.energy_lost_J, lost_before) << "scene " << scene << " sample " << s;
    lost_before = at.energy_lost_J;
    for (std::size_t i = 0; i + 1 < at.bodies.size(); ++i) {
      for (std::size_t j = i + 1; j < at.bodies.size(); ++j) {
        const double gap =
            (at.bodies[j].position_m - at.bodies[i].position_m).norm() - 2.0 * c.radius_m;
        EXPECT_GE(gap, -1e-10) << "scene " << scene << " sample " << s;
      }
    }
  }
}

TEST(StringPropertyTest, RandomCradlesCreateNoEnergyAndIgnoreNumberingAndMirroring) {
  std::mt19937_64 rng(40);
  int joins = 0;  // groups formed: the scenes exercise them
  for (int scene = 0; scene < kScenes; ++scene) {
    const RandomCradle c = randomCradle(rng);
    const Timeline plain = simulate(worldOf(c, false, false));
    ASSERT_EQ(plain.status(), SimulationStatus::kComplete) << "scene " << scene;
    expectEnergyNeverCreatedAndNoOverlap(c, plain, scene);
    for (const CollisionEvent& event : plain.collisions()) joins += event.collapse_rule ? 1 : 0;
    const Timeline mirrored = simulate(worldOf(c, true, false));
    const Timeline reversed = simulate(worldOf(c, false, true));
    const int n = static_cast<int>(c.balls.size());
    for (int s = 0; s <= 20; ++s) {
      const double t = c.duration_s * s / 20.0;
      const Snapshot a = plain.sample(t), m = mirrored.sample(t), r = reversed.sample(t);
      for (int k = 0; k < n; ++k) {
        const core::Vec2 x = a.bodies[k].position_m;
        const core::Vec2 xm = m.bodies[k].position_m, xr = r.bodies[n - 1 - k].position_m;
        EXPECT_NEAR(xm.x(), -x.x(), 1e-9) << "scene " << scene << " t " << t << " ball " << k;
        EXPECT_NEAR(xm.y(), x.y(), 1e-9) << "scene " << scene << " t " << t << " ball " << k;
        EXPECT_NEAR((xr - x).norm(), 0.0, 1e-9) << "scene " << scene << " t " << t << " " << k;
      }
    }
  }
  EXPECT_GT(joins, 0);
}

}  // namespace string_property_test
}  // namespace collide::physics
