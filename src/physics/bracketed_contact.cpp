#include "physics/bracketed_contact.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

namespace collide::physics::detail {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Deepest overlap a forced step past a grazing contact may leave, m (as in
// conservative_advance.hpp: far below anything drawn).
constexpr double kGrazeDepth_m = 1e-10;
constexpr int kMaxSteps = 200000;

}  // namespace

double firstContact_s(const std::function<GapSample(double)>& gap_at, const ContactSearch& search,
                      int* steps) {
  const double curvature = std::max(search.curvature_mps2, 1e-300);
  double t = search.start_s;
  GapSample s = gap_at(t);
  if (steps != nullptr) ++*steps;
  if (s.gap_m <= search.touch_m && s.rate_mps < -search.closing_floor_mps) return t;
  // Floor on a step, doubled each time it binds so that leaving a grazing contact costs a few
  // dozen steps; never more than the graze bound allows.
  const double graze_step = std::sqrt(2.0 * kGrazeDepth_m / curvature);
  double floor_s = 1e-13 * std::max(1.0, std::abs(t));
  for (int k = 0; k < kMaxSteps && t <= search.end_s; ++k) {
    const double g = s.gap_m, r = s.rate_mps;
    if (g > 0.0 && r < -search.closing_floor_mps && r * r >= 2.0 * curvature * g) {
      // The upper bound reaches zero at h_u <= -r / C, where the gap is still falling.
      const double h_u = (-r - std::sqrt(r * r - 2.0 * curvature * g)) / curvature;
      // Past the end of the search the bracket is cut there: the gap still falls monotonically
      // on the shorter interval, so a root before the end is the only one (a bracket that
      // merely reached past the end used to be given up, which lost contacts just before it).
      const double t_hi = std::min(t + h_u, search.end_s);
      const GapSample hi = gap_at(t_hi);
      if (steps != nullptr) ++*steps;
      if (hi.gap_m <= 0.0) {
        std::uintmax_t iterations = 100;
        const auto root = boost::math::tools::toms748_solve(
            [&](double x) { return gap_at(x).gap_m; }, t, t_hi, g, hi.gap_m,
            boost::math::tools::eps_tolerance<double>(52), iterations);
        // The end where the surfaces still part (gap >= 0): the bodies never overlap.
        return gap_at(root.first).gap_m >= 0.0 ? root.first : root.second;
      }
    }
    // The lower bound g + r h - C h^2 / 2 stays >= 0 up to its larger root.
    const double disc = r * r + 2.0 * curvature * g;
    double h = disc > 0.0 ? (r + std::sqrt(disc)) / curvature : 0.0;
    if (!(h >= floor_s)) {
      // A forced step may pass a contact, but by no more than kGrazeDepth_m.
      h = std::min(floor_s, graze_step);
      floor_s *= 2.0;
    } else {
      floor_s = 1e-13 * std::max(1.0, std::abs(t));
    }
    if (t == search.end_s) break;
    t = std::min(t + h, search.end_s);
    s = gap_at(t);
    if (steps != nullptr) ++*steps;
    if (s.gap_m <= search.touch_m && s.rate_mps < -search.closing_floor_mps) return t;
  }
  return kInfinity;
}

}  // namespace collide::physics::detail
