#pragma once
// Internal: the first time a gap between bodies under air drag closes, to round-off. Under drag
// (drag_motion.hpp) every body's velocity runs monotonically from its value now towards its
// terminal velocity, and the magnitude of its acceleration never grows. So from any instant t:
// - the gap's rate never falls below a floor (the partners' velocities bounded by their values
//   at t and their terminal ones): gap + floor (t' - t) > 0 to the end of the search certifies
//   that no contact comes;
// - |gap''| is at most the sum of the partners' accelerations at t, C, so the gap at t + h lies
//   between gap + rate h -+ C h^2 / 2. Below the lower bound's first zero no contact can happen
//   (conservative advancement); once the upper bound reaches zero while still falling, the gap
//   falls monotonically from positive to non-positive, and the bracket goes to TOMS 748
//   (Alefeld, Potra and Shi, ACM TOMS 21, 1995; Boost.Math) to full precision.
// A disk pair adds a certificate of its own (drag_sweep.hpp): a span from t over which the gap
// surely stays above the touching band, which skips stretches of any length, the rest of the run
// included, where the bounds above would creep. A pure function of its input, so predictions
// replay exactly.
#include <functional>

namespace collide::physics::detail {

struct DraggedGap {
  double gap_m = 0.0;           // clearance between the surfaces (negative: overlap)
  double rate_mps = 0.0;        // d gap / dt
  double accel_mps2 = 0.0;      // d^2 gap / dt^2 now (negative: the surfaces are pushed together)
  double curvature_mps2 = 0.0;  // bound on |gap''| from this instant on
  double rate_floor_mps = 0.0;  // bound below the rate from this instant on (may be -inf)
  double touch_m = 0.0;         // a gap this small is touching: the rounding of the positions
};

// The first time in [start_s, end_s] at which the gap reaches zero while closing faster than
// closing_floor_mps, or infinity. Touching (gap <= touch) and closing counts at once, and so does
// touching while pushed together, not closing or parting by less than the push undoes within the
// rounding of the positions (an impact at round-off speed, which the resting rule ends, as
// firstClosingRoot answers 0 for a pressed contact).
// clear_for(t, hint), where given: how long from t the gap surely stays above the touching band
// (0: unknown); hint is what it answered at the search's previous step.
double firstDraggedContact_s(const std::function<DraggedGap(double)>& gap_at, double start_s,
                             double end_s, double closing_floor_mps,
                             const std::function<double(double, double)>& clear_for = {});

}  // namespace collide::physics::detail
