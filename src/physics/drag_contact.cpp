// SPDX-License-Identifier: MIT
// Times of impact under air drag. See drag_contact.hpp.
#include "physics/drag_contact.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

namespace collide::physics::detail {
namespace {

constexpr double kNoContact = std::numeric_limits<double>::infinity();
// Deepest overlap a forced step past a grazing contact may leave, m (as bracketed_contact.cpp).
constexpr double kDragGrazeDepth_m = 1e-10;
constexpr int kDragMaxSteps = 100000;

// Where the upper bound gap + rate h + C h^2 / 2 first reaches zero while the gap still falls
// (rate + C h <= 0 there), or infinity when it does not.
double upperBoundZero_s(const DraggedGap& s, double closing_floor_mps) {
  const double g = s.gap_m, r = s.rate_mps, c = s.curvature_mps2;
  if (!(g > 0.0) || !(r < -closing_floor_mps)) return kNoContact;
  const double disc = r * r - 2.0 * c * g;
  if (disc < 0.0) return kNoContact;
  // (-r - sqrt(disc)) / c without its cancellation at small c.
  return 2.0 * g / (-r + std::sqrt(disc));
}

// How far the lower bound gap + rate h - C h^2 / 2 stays >= 0: no contact before.
double safeStep_s(const DraggedGap& s) {
  const double g = s.gap_m, r = s.rate_mps, c = s.curvature_mps2;
  if (c == 0.0) return r < 0.0 ? g / -r : kNoContact;
  const double disc = r * r + 2.0 * c * g;
  if (!(disc > 0.0)) return 0.0;
  // (r + sqrt(disc)) / c, written without its cancellation where r < 0 (then g > 0).
  return r >= 0.0 ? (r + std::sqrt(disc)) / c : 2.0 * g / (std::sqrt(disc) - r);
}

// The root in [lo, hi], where the gap falls from g_lo > 0 to g_hi <= 0: the end where the
// surfaces still part (gap >= 0), so that the bodies never overlap.
double refineRoot(const std::function<DraggedGap(double)>& gap_at, double lo, double hi,
                  double g_lo, double g_hi) {
  std::uintmax_t iterations = 100;
  const auto root = boost::math::tools::toms748_solve(
      [&](double x) { return gap_at(x).gap_m; }, lo, hi, g_lo, g_hi,
      boost::math::tools::eps_tolerance<double>(52), iterations);
  return gap_at(root.first).gap_m >= 0.0 ? root.first : root.second;
}

// Touching and closing, or touching and pushed together while parting by less than the push
// undoes within the rounding of the positions.
bool contactNow(const DraggedGap& s, double closing_floor_mps) {
  if (s.gap_m > s.touch_m) return false;
  if (s.rate_mps < -closing_floor_mps) return true;
  if (!(s.accel_mps2 < 0.0)) return false;
  return s.rate_mps <= 0.0 || s.rate_mps * s.rate_mps <= -2.0 * s.accel_mps2 * s.touch_m;
}

}  // namespace

double firstDraggedContact_s(const std::function<DraggedGap(double)>& gap_at, double start_s,
                             double end_s, double closing_floor_mps,
                             const std::function<double(double, double)>& clear_for) {
  double t = start_s;
  DraggedGap s = gap_at(t);
  if (contactNow(s, closing_floor_mps)) return t;
  double forced_s = 1e-13 * std::max(1.0, std::abs(t));
  double clear_s = 0.0;
  for (int k = 0; k < kDragMaxSteps && t < end_s; ++k) {
    // The rate's floor keeps the gap open to the end: nothing to find.
    if (s.gap_m > 0.0 && s.gap_m + std::min(s.rate_floor_mps, 0.0) * (end_s - t) > 0.0) break;
    clear_s = clear_for ? clear_for(t, clear_s) : 0.0;
    if (clear_s >= end_s - t) break;
    const double h_u = upperBoundZero_s(s, closing_floor_mps);
    if (h_u < kNoContact) {
      const double t_hi = std::min(t + h_u, end_s);
      const DraggedGap hi = gap_at(t_hi);
      if (hi.gap_m <= 0.0) return refineRoot(gap_at, t, t_hi, s.gap_m, hi.gap_m);
    }
    // The least step worth taking; where the safe step is below it (touching, parting slowly)
    // a forced step, doubled each time in a row (so that leaving a grazing contact costs a few
    // dozen steps), which may pass a contact but by no more than kDragGrazeDepth_m.
    const double least_s = 1e-13 * std::max(1.0, std::abs(t));
    double h = std::max(safeStep_s(s), clear_s);
    if (!(h >= least_s)) {
      const double curvature = std::max(s.curvature_mps2, 1e-300);
      h = std::min(forced_s, std::sqrt(2.0 * kDragGrazeDepth_m / curvature));
      forced_s *= 2.0;
    } else {
      forced_s = least_s;
    }
    t = std::min(t + h, end_s);
    s = gap_at(t);
    if (contactNow(s, closing_floor_mps)) return t;
  }
  return kNoContact;
}

}  // namespace collide::physics::detail
