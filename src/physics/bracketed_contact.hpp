#pragma once
// Internal: the first time a gap that is no polynomial closes (a swinging body against another
// body or a wall), certified and never stepped past. From a bound C on |gap''| the gap at t + h
// lies between gap + rate h - C h^2 / 2 and gap + rate h + C h^2 / 2:
// - below the lower bound's first zero no contact can happen, so the search moves there
//   (conservative advancement, which never passes a contact);
// - once the upper bound reaches zero at h_u with rate + C h_u <= 0, the gap falls monotonically
//   on [t, t + h_u] from positive to non-positive: exactly one root lies inside, and the bracket
//   goes to TOMS 748 (Alefeld, Potra and Shi, ACM TOMS 21, 1995; Boost.Math) to full precision.
// A pure function of its input, so predictions replay exactly.
#include <functional>

namespace collide::physics::detail {

struct GapSample {
  double gap_m = 0.0;     // clearance between the surfaces (negative: overlap)
  double rate_mps = 0.0;  // d gap / dt
};

struct ContactSearch {
  double start_s = 0.0;          // search from here
  double end_s = 0.0;            // to here (inclusive)
  double curvature_mps2 = 0.0;   // bound on |gap''| over [start, end] while the gap is >= 0
  double closing_floor_mps = 0;  // closing speeds at or below this are rounding, not approach
  double touch_m = 0.0;          // a gap this small counts as touching
};

// The first time in [start, end] at which the gap reaches zero while closing faster than the
// floor, or infinity. At the start, touching (gap <= touch) and closing counts at once.
// `steps`, when given, counts the gap evaluations (for tests).
double firstContact_s(const std::function<GapSample(double)>& gap_at, const ContactSearch& search,
                      int* steps = nullptr);

}  // namespace collide::physics::detail
