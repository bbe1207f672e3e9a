#pragma once
// Times of impact: pure functions from gap polynomials to the first time the gap closes.
// A gap g(tau) >= 0 is the clearance between two surfaces, tau the time from a reference instant.
#include <limits>

namespace collide::physics::detail {

inline constexpr double kNever = std::numeric_limits<double>::infinity();

// First tau >= 0 at which g(tau) = c0 + c1 tau + c2 tau^2 reaches zero while decreasing (an
// approach, never a graze), or kNever. If the surfaces already touch or overlap (c0 <= 0) and are
// approaching (c1 < 0, or at rest with c2 < 0) the answer is 0, so nothing can tunnel. Roots come
// from the cancellation-free form q = -(c1 + sign(c1) sqrt(D)) / 2, roots q / c2 and c0 / q.
double firstClosingRootGeneral(double c0, double c1, double c2);
inline double firstClosingRoot(double c0, double c1, double c2) {
  // The common case, no relative acceleration and a positive gap, inline: c0 / (-c1).
  if (c2 == 0.0 && c0 > 0.0) return c1 < 0.0 ? -c0 / c1 : kNever;
  return firstClosingRootGeneral(c0, c1, c2);
}

// Same for a polynomial g(tau) = sum c[k] tau^k of degree <= 4 on [0, tau_max]: real roots are
// isolated between the roots of the derivative (recursively) and refined by bisection.
double firstClosingRootPoly(const double* c, int degree, double tau_max);

}  // namespace collide::physics::detail
