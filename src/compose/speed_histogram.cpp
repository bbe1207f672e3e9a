#include "compose/speed_histogram.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "compose/frame_text.hpp"
#include "text/translate.hpp"
#include "text/wording.hpp"

namespace collide::compose {
namespace {

// About the square root of the number of disks, within these bounds.
constexpr int kMinBins = 5, kMaxBins = 24;
// The x axis reaches where the equilibrium density has fallen to this fraction of its tail.
constexpr double kTailFraction = 1e-3;
constexpr int kCurvePoints = 120;

// Disks per bin of width bin_mps over [0, top_mps]; speeds beyond the top count in the last bin.
std::vector<int> countSpeeds(const physics::Snapshot& snapshot, double top_mps, int bins) {
  std::vector<int> counts(static_cast<std::size_t>(bins), 0);
  for (const physics::BodyState& body : snapshot.bodies) {
    const double v = body.velocity_mps.norm();
    const int k = std::clamp(static_cast<int>(v / top_mps * bins), 0, bins - 1);
    ++counts[static_cast<std::size_t>(k)];
  }
  return counts;
}

// The outline of the bars, each value capped at y_max (a bar beyond the axis ends at its top).
std::vector<core::Vec2> staircase(const std::vector<int>& counts, double top_mps, double y_max) {
  std::vector<core::Vec2> points{{0.0, 0.0}};
  const int bins = static_cast<int>(counts.size());
  for (int k = 0; k < bins; ++k) {
    const double y = std::min(static_cast<double>(counts[static_cast<std::size_t>(k)]), y_max);
    points.push_back({top_mps * k / bins, y});
    points.push_back({top_mps * (k + 1) / bins, y});
  }
  points.push_back({top_mps, 0.0});
  return points;
}

double translationalEnergy(const physics::Snapshot& snapshot,
                           const std::vector<physics::BodyDef>& bodies) {
  double energy_J = 0.0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    energy_J += 0.5 * bodies[i].mass_kg * snapshot.bodies[i].velocity_mps.squaredNorm();
  }
  return energy_J;
}

// The disks' masses with how many disks have each: the equilibrium curve sums one term per mass,
// not per disk (a gas of hundreds of disks has one or two masses).
std::vector<std::pair<double, int>> massesCounted(const std::vector<physics::BodyDef>& bodies) {
  std::vector<std::pair<double, int>> counted;
  for (const physics::BodyDef& body : bodies) {
    const auto same = std::find_if(counted.begin(), counted.end(),
                                   [&](const auto& entry) { return entry.first == body.mass_kg; });
    if (same != counted.end()) {
      ++same->second;
    } else {
      counted.emplace_back(body.mass_kg, 1);
    }
  }
  return counted;
}

}  // namespace

frame::ChartModel speedHistogram(const physics::Timeline& timeline, const FramePlan& plan,
                                 const Theme& theme, double t_s) {
  const std::vector<physics::BodyDef>& bodies = timeline.world().bodies;
  const int n = static_cast<int>(bodies.size());
  const physics::Snapshot start = timeline.sample(0.0), now = timeline.sample(t_s);
  // kT per disk now (2 degrees of freedom each; e < 1 cools the gas, so not the start's).
  const double kT_J = n > 0 ? translationalEnergy(now, bodies) / n : 0.0;
  const double start_kT_J = n > 0 ? translationalEnergy(start, bodies) / n : 0.0;
  double lightest_kg = n > 0 ? bodies[0].mass_kg : 1.0, fastest_mps = 0.0;
  for (int i = 0; i < n; ++i) {
    lightest_kg = std::min(lightest_kg, bodies[static_cast<std::size_t>(i)].mass_kg);
    fastest_mps =
        std::max(fastest_mps, start.bodies[static_cast<std::size_t>(i)].velocity_mps.norm());
  }
  // Fixed for the scene: the start's fastest disk, or the equilibrium tail at the start's energy.
  const double tail_mps = std::sqrt(2.0 * start_kT_J / lightest_kg * std::log(1.0 / kTailFraction));
  double top_mps = std::max(fastest_mps, tail_mps);
  if (!(top_mps > 0.0)) top_mps = 1.0;
  // About sqrt(n) bins of a round width (1, 2 or 5 times a power of ten m/s), reaching the top.
  const int wanted =
      std::clamp(static_cast<int>(std::lround(std::sqrt(double(n)))), kMinBins, kMaxBins);
  const double decade = std::pow(10.0, std::floor(std::log10(top_mps / wanted)));
  double bin_mps = decade;
  for (double step : {1.0, 2.0, 5.0, 10.0}) {
    bin_mps = step * decade;
    if (top_mps / bin_mps <= wanted) break;
  }
  const int bins = std::max(1, static_cast<int>(std::ceil(top_mps / bin_mps - 1e-9)));
  top_mps = bins * bin_mps;

  // The equilibrium count per bin width at speed v: sum of f_i(v) dv.
  const std::vector<std::pair<double, int>> masses = massesCounted(bodies);
  auto expected = [&](double v, double kT) {
    if (!(kT > 0.0)) return 0.0;
    double sum = 0.0;
    for (const auto& [mass_kg, disks] : masses) {
      const double a = mass_kg / kT;
      sum += disks * a * v * std::exp(-0.5 * a * v * v);
    }
    return sum * bin_mps;
  };
  const std::vector<int> at_start = countSpeeds(start, top_mps, bins);
  const std::vector<int> at_now = countSpeeds(now, top_mps, bins);
  // The y axis: the start's tallest bar or the curve's peak (at v = sqrt(kT / m) for one mass).
  double peak = 0.0;
  for (int k = 0; k <= kCurvePoints; ++k) {
    peak = std::max(peak, expected(top_mps * k / kCurvePoints, start_kT_J));
  }
  const double y_max =
      1.25 *
      std::max(peak, static_cast<double>(*std::max_element(at_start.begin(), at_start.end())));

  frame::ChartModel chart;
  // TRANSLATORS: the speed histogram's title; {time} is "t = 1.25 s".
  chart.title = text::fill(text::tr("Speeds at {time}"), {{"time", timeText(t_s, plan.formats)}});
  // What the curve's short label stands for, on a line under the title.
  // TRANSLATORS: under the speed histogram's title: "M-B", the curve's label, spelled out.
  chart.notes = {text::tr("M-B: the Maxwell-Boltzmann distribution")};
  chart.x_label = text::tr("speed (m/s)");
  // TRANSLATORS: the histogram's vertical axis; {width} is a bin's width, "0.1 m/s".
  chart.y_label =
      text::fill(text::tr("disks per {width}"), {{"width", text::formatValue(bin_mps, "m/s")}});
  frame::ChartSeries initial{text::equation(text::symbol(text::Symbol::kTime), "0"),
                             theme.style.muted_text, staircase(at_start, top_mps, y_max), true};
  frame::ChartSeries current{text::trc("histogram series", "now"), theme.bodies[0],
                             staircase(at_now, top_mps, y_max), false};
  frame::ChartSeries curve{
      text::trc("histogram series: Maxwell-Boltzmann", "M-B"), theme.total, {}, false};
  for (int k = 0; k <= kCurvePoints; ++k) {
    const double v = top_mps * k / kCurvePoints;
    curve.points.push_back({v, std::min(expected(v, kT_J), y_max)});
  }
  chart.series = {initial, current, curve};
  chart.min = {0.0, 0.0};
  chart.max = {top_mps, y_max > 0.0 ? y_max : 1.0};
  return chart;
}

}  // namespace collide::compose
