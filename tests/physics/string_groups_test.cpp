// SPDX-License-Identifier: MIT
// Contacts that persist between bodies on strings (docs/physics.md, "Swinging together"): a
// cradle whose balls come into step goes on as one group, and a group struck parts. Expected
// numbers come from conservation of momentum and energy, the definition of e and the floor the
// document states (4 units of rounding of a pair's energy at the scene's speed scale).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "physics/simulate.hpp"
#include "worlds.hpp"

namespace collide::physics {
namespace string_groups_test {

using testing::disk;
using testing::numbered;

constexpr double kG = 9.81;
constexpr double kPi = std::numbers::pi;
// The newtons-cradle preset's numbers: 0.2 kg balls of radius 1/16 m on 0.5 m strings from
// pivots one diameter apart, the first pulled 30 degrees aside.
constexpr double kMass_kg = 0.2, kRadius_m = 0.0625, kLength_m = 0.5;
constexpr double kRelease_rad = kPi / 6.0;

BodyDef hanging(int k, double angle_rad, double angular_velocity_rad_s = 0.0) {
  const core::Vec2 pivot{2.0 * kRadius_m * (k - 2), 0.0};
  const core::Vec2 out{std::sin(angle_rad), -std::cos(angle_rad)};
  const core::Vec2 along{std::cos(angle_rad), std::sin(angle_rad)};
  BodyDef ball = disk(numbered("ball ", k + 1), kMass_kg, kRadius_m, pivot + kLength_m * out,
                      kLength_m * angular_velocity_rad_s * along);
  ball.on_string = true;
  ball.pivot_m = pivot;
  return ball;
}

WorldDef cradle(double restitution, double duration_s) {
  WorldDef world;
  world.dimensions = 2;
  world.gravity_mps2 = {0.0, -kG};
  world.duration_s = duration_s;
  world.restitution = restitution;
  for (int k = 0; k < 5; ++k) world.bodies.push_back(hanging(k, k == 0 ? -kRelease_rad : 0.0));
  return world;
}

// The speed the first ball reaches the row with: energy, m g L (1 - cos 30 degrees).
double arrivalSpeed_mps() {
  return std::sqrt(2.0 * kG * kLength_m * (1.0 - std::cos(kRelease_rad)));
}

// The floor of docs/physics.md for two balls: 4 epsilon of 1/2 (m + m) V^2, V the scene's speed
// scale: gravity's speed over twice the scene's extent (the farthest ball's distance from the
// origin and its radius; the balls start at rest).
double relativeEnergyFloor_J(const WorldDef& world) {
  double extent = 0.0;
  for (const BodyDef& b : world.bodies) extent = std::max(extent, b.position_m.norm() + b.size_m);
  const double v2 = 2.0 * kG * 2.0 * extent;
  return 4.0 * std::numeric_limits<double>::epsilon() * 0.5 * (2.0 * kMass_kg) * v2;
}

TEST(StringGroupsTest, ClayCradleSwingsAsOneAndNeverStrikesAgain) {
  const Timeline timeline = simulate(cradle(0.0, 20.0));
  EXPECT_EQ(timeline.status(), SimulationStatus::kComplete);
  // The first ball takes the four others with it, all at the first instant: momentum m v shared
  // by five, v / 5; nothing strikes afterwards (the five swing as one pendulum).
  const double v = arrivalSpeed_mps();
  const double t_hit = timeline.collisions().front().time_s;
  ASSERT_EQ(timeline.collisionCount(), 4);
  for (const CollisionEvent& event : timeline.collisions()) EXPECT_EQ(event.time_s, t_hit);
  const Snapshot after = timeline.sample(t_hit);
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(after.bodies[i].velocity_mps.x(), v / 5.0, 1e-12) << i;
  EXPECT_NEAR(after.energy_lost_J, 0.5 * kMass_kg * v * v * (1.0 - 1.0 / 5.0), 1e-15);
  // They rise together to h = (v / 5)^2 / (2 g), swing after swing, to the end.
  const double h = (v / 5.0) * (v / 5.0) / (2.0 * kG);
  double highest = -kLength_m;
  const double step_s = 0.01;
  for (double t = t_hit; t <= 20.0; t += step_s) {
    const Snapshot s = timeline.sample(t);
    for (int i = 1; i < 5; ++i) {
      EXPECT_NEAR(s.bodies[i].position_m.y(), s.bodies[0].position_m.y(), 1e-12) << t;
    }
    highest = std::max(highest, s.bodies[0].position_m.y());
  }
  // Sampled every step_s: within step_s / 2 of the top, below it by at most 1/2 a (step_s / 2)^2
  // with a = g sin^2(amplitude) the vertical acceleration there.
  const double sin2 = 1.0 - (1.0 - h / kLength_m) * (1.0 - h / kLength_m);
  EXPECT_LE(highest, -kLength_m + h + 1e-12);
  EXPECT_GE(highest, -kLength_m + h - 0.5 * kG * sin2 * 0.25 * step_s * step_s);
}

// The books at instants spread over a run: kinetic + potential + lost = the start's energy.
void expectBooksAddUp(const Timeline& timeline) {
  const double start = timeline.mechanicalEnergy(timeline.sample(0.0));
  const double duration_s = timeline.world().duration_s;
  for (double t = 0.0; t <= duration_s; t += duration_s / 397.0) {
    const Snapshot s = timeline.sample(t);
    EXPECT_NEAR(timeline.mechanicalEnergy(s) + s.energy_lost_J, start, 1e-12) << t;
  }
}

TEST(StringGroupsTest, InelasticCradleComesIntoStepAfterFinitelyManyImpactsAboveTheFloor) {
  const double e = 0.8;
  const double duration_s = 25.0;
  const WorldDef world = cradle(e, duration_s);
  const Timeline timeline = simulate(world);
  EXPECT_EQ(timeline.status(), SimulationStatus::kComplete);
  const double floor_J = relativeEnergyFloor_J(world);
  int rebounds = 0, joins = 0;
  double last_s = 0.0;
  for (const CollisionEvent& event : timeline.collisions()) {
    const double relative_J =
        0.5 * (0.5 * kMass_kg) *
        (event.velocity_a_before_mps - event.velocity_b_before_mps).squaredNorm();
    if (event.collapse_rule) {
      // A join of a group of M_a and one of M_b (balls already together: up to 4 m and m): its
      // relative energy 1/2 mu |dv|^2, mu = M_a M_b / (M_a + M_b), was below the floor of the
      // pair, 4 eps 1/2 (M_a + M_b) V^2, so |dv|^2 <= 4 eps V^2 (M_a + M_b)^2 / (M_a M_b), at
      // most 25/4 of that for two single balls; what it books is what it held along the swing
      // (a string slack for a moment books its radial part as its jerk), at most 1/2 (4/5 m)
      // |dv|^2, 8/5 of relative_J.
      ++joins;
      EXPECT_EQ(event.restitution, 0.0);
      EXPECT_EQ(event.restitution_requested, e);
      EXPECT_LE(relative_J, floor_J * 25.0 / 16.0 * (1.0 + 1e-9)) << event.index;
      EXPECT_GE(event.energy_lost_J, 0.0) << event.index;
      EXPECT_LE(event.energy_lost_J, relative_J * 1.6 * (1.0 + 1e-9)) << event.index;
    } else {
      // A rebound (of two single balls: a group struck has parted): above the floor, as
      // (M_a + M_b)^2 / (M_a M_b) >= 4 for any groups they were in, losing at least
      // (1 - e^2) cos^2(30 degrees) of it (no string swings wider than the first ball's release).
      ++rebounds;
      EXPECT_GT(relative_J, floor_J) << event.index;
      const double c = std::cos(kRelease_rad);
      EXPECT_GE(event.energy_lost_J, (1.0 - e * e) * c * c * floor_J) << event.index;
    }
    last_s = event.time_s;
  }
  EXPECT_GT(joins, 0);
  EXPECT_GT(rebounds, 40);
  // The impacts end well before the run: after the last the five swing in step, one height and
  // one diameter apart, to the end.
  EXPECT_LT(last_s, duration_s - 2.0);
  for (double t = last_s; t <= duration_s; t += 0.01) {
    const Snapshot s = timeline.sample(t);
    for (int i = 1; i < 5; ++i) {
      EXPECT_NEAR(s.bodies[i].position_m.y(), s.bodies[0].position_m.y(), 1e-9) << t << " " << i;
      EXPECT_NEAR(s.bodies[i].position_m.x() - s.bodies[i - 1].position_m.x(), 2.0 * kRadius_m,
                  1e-9)
          << t << " " << i;
    }
  }
  expectBooksAddUp(timeline);
  EXPECT_NEAR(timeline.energyLostMeasured(), timeline.totalEnergyLost(), 1e-12);
}

// Two balls hanging at one angle, the first closing on the second at 1e-8 m/s (far below the
// floor): they join at once. Swinging down as one they strike a third at rest: the group parts
// and the impact is resolved ball by ball, the hardest first (as in a cradle's first cascade),
// not as one body of twice the mass (which would send the third off at (1 + e) 2/3 v and leave
// the two together).
TEST(StringGroupsTest, AGroupStruckPartsAndPassesTheImpulseOnBallByBall) {
  const double e = 0.8, start = -0.4;
  const double nudge_rad_s = 1e-8 / kLength_m;
  WorldDef world;
  world.dimensions = 2;
  world.gravity_mps2 = {0.0, -kG};
  world.duration_s = 1.0;
  world.restitution = e;
  world.bodies.push_back(hanging(0, start, nudge_rad_s));
  world.bodies.push_back(hanging(1, start));
  world.bodies.push_back(hanging(2, 0.0));
  const Timeline timeline = simulate(world);
  ASSERT_GE(timeline.collisions().size(), 3u);
  const CollisionEvent& join = timeline.collisions().front();
  EXPECT_EQ(join.time_s, 0.0);
  EXPECT_TRUE(join.collapse_rule);
  // The pair arrives at the speed energy gives (the nudge adds 1e-8 m/s shared by two).
  const double v = std::sqrt(2.0 * kG * kLength_m * (1.0 - std::cos(start)));
  std::vector<double> u{v, v, 0.0};
  for (;;) {
    int hardest = -1;
    for (int i = 0; i + 1 < 3; ++i) {
      if (u[i] - u[i + 1] > 1e-12 && (hardest < 0 || u[i] - u[i + 1] > u[hardest] - u[hardest + 1]))
        hardest = i;
    }
    if (hardest < 0) break;
    const double a = u[hardest], b = u[hardest + 1];
    u[hardest] = 0.5 * ((1.0 - e) * a + (1.0 + e) * b);
    u[hardest + 1] = 0.5 * ((1.0 + e) * a + (1.0 - e) * b);
  }
  const double t_hit = timeline.collisions()[1].time_s;
  const Snapshot after = timeline.sample(t_hit);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(after.bodies[i].velocity_mps.x(), u[i], 1e-7) << i;
  EXPECT_GT(std::abs(after.bodies[2].velocity_mps.x() - (1.0 + e) * 2.0 / 3.0 * v), 0.1);
  expectBooksAddUp(timeline);
}

}  // namespace string_groups_test
}  // namespace collide::physics
