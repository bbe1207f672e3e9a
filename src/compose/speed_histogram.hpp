#pragma once
// The speed histogram of a gas of disks at one instant, beside the two-dimensional
// Maxwell-Boltzmann distribution for the same kinetic energy (chart "speed", the ideal-gas
// preset). Unlike the charts against time it changes from frame to frame, so it is built for each
// frame. Fixed axes over the whole scene, so a video shows the shape change, not the axes.
//
// The curve: in two dimensions a disk of mass m at temperature T has the speed density
// f(v) = (m v / kT) exp(-m v^2 / 2kT) (a Rayleigh distribution), and equipartition gives kT as the
// mean translational kinetic energy per disk. The expected number of disks in a bin [a, b] is
// sum over disks of exp(-m a^2 / 2kT) - exp(-m b^2 / 2kT).
#include "compose/frame_builder.hpp"
#include "compose/palette.hpp"
#include "frame/frame_model.hpp"
#include "physics/timeline.hpp"

namespace collide::compose {

inline constexpr const char* kSpeedChartQuantity = "speed";

// The histogram at simulated time t_s, with the one at t = 0 dashed for comparison.
frame::ChartModel speedHistogram(const physics::Timeline& timeline, const FramePlan& plan,
                                 const Theme& theme, double t_s);

}  // namespace collide::compose
