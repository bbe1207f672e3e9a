#pragma once
// Internal: where two disks under linear air drag (or on parabolas) can be relative to each other
// over a stretch of time, bounded from below: the certificate that a pair stays apart that lets
// the disk-pair search of plane_drag.cpp skip whole stretches, or the rest of the run, at once.
//
// Over [t, t + H] each disk's velocity moves along a segment: under linear drag and gravity
// v = v_T + (v(t) - v_T) e^(-a tau) runs straight from v(t) towards the terminal v_T, on a
// parabola v(t) + g tau runs straight along g. So for tau <= h <= H it lies between v(t) and
// v(t + H), and the displacement over h, h times the mean velocity, is h times a point of that
// segment. The separation d = x_b - x_a therefore has d(t + h) - d(t) = h p for some p in the
// parallelogram P of differences (a point of b's segment less one of a's): d(t + h) lies in the
// convex hull of d(t) and the four points d(t) + H p, p a corner of P. The hull's distance from
// the origin is a floor under the distance between the centres over the whole stretch.
#include <array>

#include "core/vec.hpp"

namespace collide::physics::detail {

// The distance from the origin to the convex hull of the points (exact up to rounding; zero when
// the origin lies inside).
double hullDistanceFromOrigin_m(std::array<core::Vec2, 5> points);

// The velocities of the two disks at both ends of a stretch of span_s seconds.
struct SweptVelocities {
  core::Vec2 a_start_mps, a_end_mps;
  core::Vec2 b_start_mps, b_end_mps;
};

// A floor under |d| over the stretch, d = x_b - x_a (separation_m at its start).
double sweptDistanceFloor_m(const core::Vec2& separation_m, const SweptVelocities& v,
                            double span_s);

}  // namespace collide::physics::detail
