// Times of impact from gap polynomials, checked against roots worked out by hand.
#include "physics/toi.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace collide::physics::detail {
namespace {

TEST(ToiTest, LinearApproachMeetsAtGapOverSpeed) {
  // gap 3 m closing at 2 m/s.
  EXPECT_DOUBLE_EQ(firstClosingRoot(3.0, -2.0, 0.0), 1.5);
  EXPECT_EQ(firstClosingRoot(3.0, 2.0, 0.0), kNever);
}

TEST(ToiTest, TouchingAndApproachingIsImmediate) {
  EXPECT_EQ(firstClosingRoot(0.0, -1.0, 0.0), 0.0);
  EXPECT_EQ(firstClosingRoot(-1e-12, -1.0, 0.0), 0.0);  // rounding overlap: no tunnelling
  EXPECT_EQ(firstClosingRoot(0.0, 0.0, -4.9), 0.0);     // at rest, pushed in by gravity
  EXPECT_EQ(firstClosingRoot(0.0, 0.0, 0.0), kNever);   // resting, nothing pushing
}

TEST(ToiTest, ParabolicFlightLandsAtTheLargerRoot) {
  // A ball leaving the floor at 3 m/s under g = 9.81: back after 2 v / g.
  const double g = 9.81, v = 3.0;
  EXPECT_NEAR(firstClosingRoot(0.0, v, -0.5 * g), 2.0 * v / g, 1e-15);
  // Dropped from h = 2 m: lands after sqrt(2 h / g).
  EXPECT_NEAR(firstClosingRoot(2.0, 0.0, -0.5 * g), std::sqrt(2.0 * 2.0 / g), 1e-15);
}

TEST(ToiTest, GrazeAndMissAreNotImpacts) {
  // g(tau) = (tau - 1)^2 touches zero at tau = 1 without crossing.
  EXPECT_EQ(firstClosingRoot(1.0, -2.0, 1.0), kNever);
  // Decelerating approach that stops short: 1 - tau + tau^2 has no real root.
  EXPECT_EQ(firstClosingRoot(1.0, -1.0, 1.0), kNever);
}

TEST(ToiTest, StableRootsForTinyAndHugeCoefficients) {
  // (tau - 1e-9)(tau - 1e9): the small root must keep full relative precision.
  const double r1 = 1e-9, r2 = 1e9;
  const double t = firstClosingRoot(r1 * r2, -(r1 + r2), 1.0);
  EXPECT_NEAR(t, r1, 1e-24);
}

TEST(ToiTest, QuarticFirstCrossing) {
  // g = (tau - 1)(tau - 2)(tau - 3)(tau - 4) = tau^4 - 10 tau^3 + 35 tau^2 - 50 tau + 24:
  // positive at 0, first falls through zero at tau = 1.
  const double c[5] = {24.0, -50.0, 35.0, -10.0, 1.0};
  EXPECT_NEAR(firstClosingRootPoly(c, 4, 10.0), 1.0, 1e-12);
  EXPECT_EQ(firstClosingRootPoly(c, 4, 0.5), kNever);
  // Degree 2 agrees with the closed form.
  const double q[3] = {2.0, 0.0, -0.5 * 9.81};
  EXPECT_NEAR(firstClosingRootPoly(q, 2, 10.0), std::sqrt(4.0 / 9.81), 1e-12);
}

}  // namespace
}  // namespace collide::physics::detail
