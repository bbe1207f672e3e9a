// SPDX-License-Identifier: MIT
// The curvature bound of two swings on strings of one length (physics/swing_pair_bound.hpp)
// against the gap's second derivative measured along the exact pendulum solutions by central
// differences, over random pairs: from far apart to in step within 1e-9 rad. And the certified
// search's bracket cut at the search's end.
#include "physics/swing_pair_bound.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "physics/bracketed_contact.hpp"

namespace collide::physics::detail {
namespace {

constexpr double kG = 9.81;

core::Vec2 at(const core::Vec2& pivot, double length, const PendulumState& s) {
  return pivot + pendulumPosition_m(length, s.angle_rad);
}

TEST(SwingPairBoundTest, BoundsTheGapsCurvatureOverTheHorizon) {
  std::mt19937 rng(40);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const double length = 0.2 + unit(rng);
    const double radius = 0.02 + 0.05 * unit(rng);
    const double w0 = std::sqrt(kG / length);
    // Pivots one diameter apart (a cradle's), or a little more.
    const core::Vec2 pa{0.0, 0.0}, pb{2.0 * radius * (1.0 + 0.2 * unit(rng)), 0.0};
    PendulumState a{(unit(rng) - 0.5) * 2.0, (unit(rng) - 0.5) * 2.0 * w0};
    const double spread = std::pow(10.0, -9.0 * unit(rng));
    PendulumState b{a.angle_rad + spread * (unit(rng) - 0.5),
                    a.angular_velocity_rad_s + spread * w0 * (unit(rng) - 0.5)};
    const PendulumArc arc_a(length, kG, a), arc_b(length, kG, b);
    SwingPair pair;
    pair.length_m = length;
    pair.omega0_rad_s = w0;
    pair.reach_m = 2.0 * radius;
    pair.a = a;
    pair.b = b;
    pair.largest_angle_rad = std::max(arc_a.amplitude_rad(), arc_b.amplitude_rad());
    pair.angular_speed_bound_rad_s =
        2.0 * w0 * std::sqrt(std::max(arc_a.energyParameter(), arc_b.energyParameter()));
    const double horizon = 1.0 / w0;
    const double bound = swingPairCurvature_mps2(pair, horizon);
    const auto gap = [&](double t) {
      return (at(pb, length, arc_b.at(t)) - at(pa, length, arc_a.at(t))).norm() - 2.0 * radius;
    };
    const double h = 1e-3 * horizon;
    for (int k = 1; k < 200; ++k) {
      const double t = horizon * k / 200.0;
      if (gap(t) < 0.0) continue;  // the bound holds while the gap is >= 0
      // Central difference: exact to O(h^2 g''''), plus the pendulum solutions' rounding (a few
      // units in positions of about 1 + L metres) over h^2.
      const double measured = (gap(t + h) - 2.0 * gap(t) + gap(t - h)) / (h * h);
      const double rounding = 64.0 * 1e-16 * (1.0 + length) / (h * h);
      EXPECT_LE(std::abs(measured), bound * 1.01 + rounding)
          << "trial " << trial << " t " << t << " spread " << spread << " bound " << bound
          << " rounding " << rounding << " gap " << gap(t) << " L " << length;
      ++checked;
    }
  }
  EXPECT_GT(checked, 5000);
}

}  // namespace
}  // namespace collide::physics::detail

namespace collide::physics::detail {
namespace {

// A contact just before the end of a search whose certified bracket reaches past the end: the
// gap 1 - t falls at 1 m/s and the bound C = 0.1 m/s^2 puts the bracket's end at 1.056 s,
// beyond the search's end at 1.01 s. The contact at 1 s is found (it used to be given up).
TEST(SwingPairBoundTest, ContactBeforeTheSearchsEndIsFoundWhenItsBracketReachesPast) {
  const auto gap = [](double t) { return GapSample{1.0 - t, -1.0}; };
  ContactSearch search;
  search.start_s = 0.0;
  search.end_s = 1.01;
  search.curvature_mps2 = 0.1;
  search.closing_floor_mps = 1e-12;
  search.touch_m = 1e-12;
  EXPECT_NEAR(firstContact_s(gap, search), 1.0, 1e-15);
  search.end_s = 0.99;  // and none before an earlier end
  EXPECT_EQ(firstContact_s(gap, search), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace collide::physics::detail
