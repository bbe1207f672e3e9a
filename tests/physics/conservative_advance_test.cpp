// Conservative advancement on gaps given in closed form, against roots found here by bisection.
#include "physics/conservative_advance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace collide::physics::detail {
namespace {

// A disk at rest against a wall, pulled off it by a = 0.33 m/s^2 (the x component of a slanted
// gravity): gap = a tau^2 / 2, never closing again. Leaving the contact takes a few dozen steps
// (the step floor doubles from 1e-13 s while the gap is still below the tolerance, then the
// steps grow with tau); it once crept on in 2.5e-5 s steps and gave up after 20,000.
TEST(ConservativeAdvanceTest, LeavingAContactFromRestIsNeverInAFewSteps) {
  const double a = 0.33;
  auto gapAt = [&](double tau) { return GapState{0.5 * a * tau * tau, a * tau, a * tau}; };
  AdvanceBounds bounds;
  bounds.start_s = 1.27;
  bounds.tau_max_s = 2.73;
  bounds.accel_mps2 = a;
  bounds.tolerance_m = 1e-12;
  int steps = 0;
  EXPECT_EQ(conservativeAdvance(gapAt, bounds, &steps), kNever);
  EXPECT_LE(steps, 100);
}

// A contact that grazes at tau = 0, opens and closes again: gap = (1 - cos tau) - 0.1 tau^2 m
// (a centre swinging round at 1 rad/s on a 1 m arm, drifting back at 0.2 m/s^2), with
// |gap''| <= 1 + 0.2 m/s^2. It closes between pi and 2 pi s, where 1 - cos tau = 0.1 tau^2.
TEST(ConservativeAdvanceTest, ContactAfterAGrazeIsFoundAtItsRoot) {
  auto gap = [](double tau) { return (1.0 - std::cos(tau)) - 0.1 * tau * tau; };
  auto rate = [](double tau) { return std::sin(tau) - 0.2 * tau; };
  double lo = std::numbers::pi, hi = 2.0 * std::numbers::pi;  // gap(lo) > 0 > gap(hi)
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (gap(mid) > 0.0 ? lo : hi) = mid;
  }
  const double root = lo;
  auto gapAt = [&](double tau) {
    return GapState{gap(tau), rate(tau), std::abs(std::sin(tau)) + 0.2 * tau};
  };
  AdvanceBounds bounds;
  bounds.tau_max_s = 10.0;
  bounds.accel_mps2 = 1.2;
  bounds.tolerance_m = 1e-12;
  int steps = 0;
  const double found = conservativeAdvance(gapAt, bounds, &steps);
  // Conservative steps stop where the gap first falls to the tolerance: at most
  // tolerance / |rate| before the root, and never past it.
  EXPECT_LE(found, root + 1e-12);
  EXPECT_GE(found, root - 2.0 * bounds.tolerance_m / std::abs(rate(root)) - 1e-12);
  EXPECT_LE(steps, 1000);
}

// Straight approach, no curvature: a 2 m gap closing at 4 m/s touches at 0.5 s. The answer is
// where the gap is down to the tolerance, 1e-12 m: in [0.5 - 2.5e-13, 0.5] s, after a step of
// (gap - tolerance) / speed and a few at the step floor.
TEST(ConservativeAdvanceTest, StraightApproachStopsWithinTheTolerance) {
  auto gapAt = [](double tau) { return GapState{2.0 - 4.0 * tau, -4.0, 4.0}; };
  AdvanceBounds bounds;
  bounds.tau_max_s = 10.0;
  bounds.tolerance_m = 1e-12;
  int steps = 0;
  const double found = conservativeAdvance(gapAt, bounds, &steps);
  EXPECT_GE(found, 0.5 - 2.5e-13 - 1e-16);
  EXPECT_LE(found, 0.5);
  EXPECT_LE(steps, 5);
}

}  // namespace
}  // namespace collide::physics::detail
