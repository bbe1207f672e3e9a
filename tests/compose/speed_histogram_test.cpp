// The ideal gas and its speed histogram: the bars count every disk, the curve is the 2D
// Maxwell-Boltzmann distribution for the gas's energy (checked against the Rayleigh density's own
// normalisation and peak, computed here), and the simulated speeds do relax towards it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "app/animation.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace {

struct Gas {
  scene::SceneDesc scene = scene::loadPreset("ideal-gas");
  app::Animation animation = app::animate(scene, {640, 360});
  const physics::Timeline& timeline() const { return animation.frames.panelTimeline(0); }
  // kT per disk from equipartition (2 degrees of freedom): the mean kinetic energy.
  double kT_J() const {
    const physics::Snapshot start = timeline().sample(0.0);
    double energy_J = 0.0;
    for (std::size_t i = 0; i < start.bodies.size(); ++i) {
      energy_J += 0.5 * scene.bodies[i].mass_kg * start.bodies[i].velocity_mps.squaredNorm();
    }
    return energy_J / static_cast<double>(start.bodies.size());
  }
};

void expectBarsCountEveryDiskAndTheCurveIsMaxwellBoltzmann(const Gas& gas) {
  const double n = static_cast<double>(gas.scene.bodies.size());
  const double m = gas.scene.bodies[0].mass_kg, kT = gas.kT_J();
  const double sigma_mps = std::sqrt(kT / m);  // the Rayleigh scale; the density peaks there
  for (double t : {0.0, 5.0, 10.0}) {
    SCOPED_TRACE(t);
    const frame::FrameModel frame = gas.animation.frames.frameAtSimulated(t);
    ASSERT_EQ(frame.charts.size(), 1u);
    const frame::ChartModel& chart = frame.charts[0];
    ASSERT_EQ(chart.series.size(), 3u);
    EXPECT_FALSE(chart.cursor_x.has_value());
    // The bars now: points (0,0), then two per bin at its height, then (top, 0).
    const std::vector<core::Vec2>& bars = chart.series[1].points;
    ASSERT_GE(bars.size(), 4u);
    const double bin_mps = bars[2].x() - bars[1].x();
    double disks = 0.0;
    for (std::size_t k = 1; k + 1 < bars.size(); k += 2) disks += bars[k].y();
    EXPECT_EQ(disks, n);
    // The curve is n f(v) dv per bin: its area over one bin width is n times the Rayleigh
    // probability below the axis's end, 1 - exp(-v^2 / 2 sigma^2).
    const std::vector<core::Vec2>& curve = chart.series[2].points;
    double area = 0.0, peak = 0.0;
    for (std::size_t k = 1; k < curve.size(); ++k) {
      area += 0.5 * (curve[k].y() + curve[k - 1].y()) * (curve[k].x() - curve[k - 1].x());
      peak = std::max(peak, curve[k].y());
    }
    const double top_mps = curve.back().x();
    const double below_top = 1.0 - std::exp(-0.5 * top_mps * top_mps / (sigma_mps * sigma_mps));
    EXPECT_NEAR(area / bin_mps, n * below_top, 0.01 * n);
    // Its peak: n dv / sigma * exp(-1/2), at v = sigma.
    EXPECT_NEAR(peak, n * bin_mps / sigma_mps * std::exp(-0.5), 0.01 * peak);
  }
}

void expectSpeedsRelaxTowardsMaxwellBoltzmann(const Gas& gas) {
  const double m = gas.scene.bodies[0].mass_kg;
  const double two_sigma_sq = 2.0 * gas.kT_J() / m;  // 2 sigma^2, (m/s)^2
  // Fractions of disks faster than 2 m/s and slower than 0.4 m/s. The start spreads speeds
  // evenly over [0, 2) m/s: none above, a fifth below. In equilibrium (Rayleigh):
  // exp(-4 / 2 sigma^2) and 1 - exp(-0.16 / 2 sigma^2).
  auto fractions = [&](double t, double& fast, double& slow) {
    const physics::Snapshot s = gas.timeline().sample(t);
    fast = slow = 0.0;
    for (const physics::BodyState& body : s.bodies) {
      const double v = body.velocity_mps.norm();
      fast += v > 2.0 ? 1.0 : 0.0;
      slow += v < 0.4 ? 1.0 : 0.0;
    }
    fast /= static_cast<double>(s.bodies.size());
    slow /= static_cast<double>(s.bodies.size());
  };
  double fast = 0.0, slow = 0.0;
  fractions(0.0, fast, slow);
  EXPECT_EQ(fast, 0.0);
  EXPECT_NEAR(slow, 0.2, 0.05);
  // Averaged over the second half (300 disks: one instant's fraction scatters by about
  // sqrt(p (1 - p) / 300), 1.3 % for the fast ones).
  double fast_mean = 0.0, slow_mean = 0.0;
  const int instants = 6;
  for (int k = 0; k < instants; ++k) {
    fractions(5.0 + k, fast, slow);
    fast_mean += fast / instants;
    slow_mean += slow / instants;
  }
  EXPECT_NEAR(fast_mean, std::exp(-4.0 / two_sigma_sq), 0.025);
  EXPECT_NEAR(slow_mean, 1.0 - std::exp(-0.16 / two_sigma_sq), 0.04);
  // Elastic throughout: nothing lost.
  EXPECT_EQ(gas.timeline().totalEnergyLost(), 0.0);
}

// One test, one simulation: the gas takes a few tenths of a second to set up, and ctest runs each
// test in a process of its own.
TEST(SpeedHistogramTest, CountsEveryDiskDrawsMaxwellBoltzmannAndTheGasRelaxesToIt) {
  const Gas gas;
  expectBarsCountEveryDiskAndTheCurveIsMaxwellBoltzmann(gas);
  expectSpeedsRelaxTowardsMaxwellBoltzmann(gas);
}

}  // namespace
}  // namespace collide
