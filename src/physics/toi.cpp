#include "physics/toi.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace collide::physics::detail {

double firstClosingRootGeneral(double c0, double c1, double c2) {
  if (c0 <= 0.0) {
    if (c1 < 0.0 || (c1 == 0.0 && c2 < 0.0)) return 0.0;  // touching and approaching
    // Separating now: only a parabola bending back (c2 < 0) closes again, at its larger root,
    // or at its vertex if rounding left it overlapping so that it never clears.
    if (c2 >= 0.0) return kNever;
    const double disc = c1 * c1 - 4.0 * c2 * c0;
    if (disc <= 0.0) return -c1 / (2.0 * c2);
  }
  if (c2 == 0.0) return c1 < 0.0 ? -c0 / c1 : kNever;
  const double disc = c1 * c1 - 4.0 * c2 * c0;
  if (disc <= 0.0) return kNever;  // no crossing, or a tangential graze
  const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
  double r1 = q / c2, r2 = c0 / q;
  if (r1 > r2) std::swap(r1, r2);
  // g falls through r1 when it opens upwards, through r2 when it opens downwards.
  const double root = c2 > 0.0 ? r1 : r2;
  if (root < 0.0) return c0 <= 0.0 ? 0.0 : kNever;
  return root;
}

namespace {

double evalPoly(const double* c, int degree, double x) {
  double value = c[degree];
  for (int k = degree - 1; k >= 0; --k) value = value * x + c[k];
  return value;
}

// Bisection to the last representable point: g(lo) and g(hi) have opposite signs.
double bisect(const double* c, int degree, double lo, double hi) {
  const bool lo_positive = evalPoly(c, degree, lo) > 0.0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    if ((evalPoly(c, degree, mid) > 0.0) == lo_positive) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return hi;
}

// Sorted real roots of the polynomial in (lo, hi): between consecutive critical points the
// polynomial is monotonic, so each sign change brackets exactly one root.
void realRoots(const double* c, int degree, double lo, double hi, std::vector<double>& roots) {
  while (degree > 0 && c[degree] == 0.0) --degree;
  if (degree <= 0) return;
  if (degree == 1) {
    const double x = -c[0] / c[1];
    if (x > lo && x < hi) roots.push_back(x);
    return;
  }
  double derivative[4];
  for (int k = 1; k <= degree; ++k) derivative[k - 1] = k * c[k];
  std::vector<double> points{lo};
  realRoots(derivative, degree - 1, lo, hi, points);
  points.push_back(hi);
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const double a = points[k], b = points[k + 1];
    const double ga = evalPoly(c, degree, a), gb = evalPoly(c, degree, b);
    if ((ga > 0.0) != (gb > 0.0)) {
      const double x = bisect(c, degree, a, b);
      if (x > lo && x < hi) roots.push_back(x);
    }
  }
}

}  // namespace

double firstClosingRootPoly(const double* c, int degree, double tau_max) {
  const double g0 = c[0];
  const double d1 = degree >= 1 ? c[1] : 0.0;
  const double d2 = degree >= 2 ? c[2] : 0.0;
  if (g0 <= 0.0 && (d1 < 0.0 || (d1 == 0.0 && d2 < 0.0))) return 0.0;
  if (!(tau_max > 0.0)) return kNever;
  std::vector<double> critical{0.0};
  double derivative[4];
  for (int k = 1; k <= degree; ++k) derivative[k - 1] = k * c[k];
  realRoots(derivative, degree - 1, 0.0, tau_max, critical);
  critical.push_back(tau_max);
  // Walk the monotonic pieces in order. On a falling piece the surfaces approach: if they are
  // already in contact at its start (an opening overlap that never cleared, lost in rounding),
  // the contact is there; otherwise it is where the piece crosses zero.
  for (std::size_t k = 0; k + 1 < critical.size(); ++k) {
    const double a = critical[k], b = critical[k + 1];
    const double ga = evalPoly(c, degree, a), gb = evalPoly(c, degree, b);
    if (!(gb < ga)) continue;  // rising or flat
    if (ga <= 0.0) return a;
    if (gb <= 0.0) return bisect(c, degree, a, b);
  }
  return kNever;
}

}  // namespace collide::physics::detail
