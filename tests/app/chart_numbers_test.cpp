// The numbers behind the charts, point by point, against closed forms worked out from the scene's
// inputs: momentum in 1D (signed) and 2D (magnitudes), the energy chart's potential energy under
// gravity, and the contact force of a soft collision, whose area is the impulse (1 + e) μ u.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <regex>
#include <string>

#include "app/animation.hpp"
#include "closed_forms.hpp"
#include "scene/scene_io.hpp"

namespace collide {
namespace {

using test::PanelTruth;

frame::ChartModel chartOf(const std::string& preset, const std::string& quantity) {
  const scene::SceneDesc scene =
      scene::loadScene(preset, {scene::parseSetExpression("view.chart=\"" + quantity + "\"")});
  const frame::FrameModel frame = app::animate(scene, {1280, 720}).frames.chartFrame();
  EXPECT_EQ(frame.charts.size(), 1u);
  EXPECT_TRUE(frame.panels.empty());
  return frame.charts.empty() ? frame::ChartModel{} : frame.charts.front();
}

std::map<std::string, const frame::ChartSeries*> seriesByLabel(const frame::ChartModel& chart) {
  std::map<std::string, const frame::ChartSeries*> found;
  for (const frame::ChartSeries& s : chart.series) found[s.label] = &s;
  return found;
}

// Every point of `series` against `expected(t)`, skipping points within a microsecond of a
// collision (where the chart draws its vertical step); returns how many were compared.
int comparePoints(const frame::ChartSeries& series, const std::function<double(double)>& expected,
                  const std::function<bool(double)>& near_step, double tolerance) {
  int compared = 0;
  for (const core::Vec2& point : series.points) {
    if (near_step(point.x())) continue;
    EXPECT_NEAR(point.y(), expected(point.x()), tolerance)
        << series.label << " at t = " << point.x();
    ++compared;
  }
  return compared;
}

// Both bodies' momentum series (p₁, p₂) against `truth(t)`, the closed form of the panel at t:
// m vₓ in 1D (signed) or m |v| in 2D, at more than 500 points away from the collision steps.
void expectBodyMomenta(const std::map<std::string, const frame::ChartSeries*>& series,
                       const std::function<PanelTruth(double)>& truth, bool magnitude) {
  const auto near_step = [&](double t) {
    return truth(t - 1e-6).collisions != truth(t + 1e-6).collisions;
  };
  for (int b = 0; b < 2; ++b) {
    const std::string label = b == 0 ? "p\u2081" : "p\u2082";
    ASSERT_TRUE(series.count(label)) << label;
    const auto p = [&, b](double t) {
      const test::BodyTruth body = truth(t).bodies[b];
      return body.mass_kg * (magnitude ? body.velocity_mps.norm() : body.velocity_mps.x());
    };
    EXPECT_GT(comparePoints(*series.at(label), p, near_step, 1e-12), 500);
  }
}

// The axes hold every point.
void expectAxesHoldEveryPoint(const frame::ChartModel& chart) {
  for (const frame::ChartSeries& s : chart.series) {
    for (const core::Vec2& p : s.points) {
      EXPECT_GE(p.y(), chart.min.y()) << s.label;
      EXPECT_LE(p.y(), chart.max.y()) << s.label;
      EXPECT_GE(p.x(), chart.min.x()) << s.label;
      EXPECT_LE(p.x(), chart.max.x()) << s.label;
    }
  }
}

TEST(ChartNumbersTest, MomentumIn1DIsSignedAndItsSumConstant) {
  const scene::SceneDesc scene = scene::loadPreset("worked-example");
  const frame::ChartModel chart = chartOf("worked-example", "momentum");
  EXPECT_EQ(chart.y_label, "p (kg\u00b7m/s)");
  EXPECT_EQ(chart.x_label, "t (s)");
  const auto series = seriesByLabel(chart);
  ASSERT_EQ(series.size(), 3u);
  expectBodyMomenta(
      series, [&](double t) { return test::twoBlocks(scene, scene.restitution, t); }, false);
  ASSERT_TRUE(series.count("\u03a3p"));
  // 1 kg × 2 m/s + 1 kg × (−1 m/s), before and after.
  EXPECT_GT(
      comparePoints(
          *series.at("\u03a3p"), [](double) { return 1.0; }, [](double) { return false; }, 1e-12),
      500);
  // p₁ goes negative after the collision (−0.25 kg·m/s): the axis goes below zero.
  EXPECT_LT(chart.min.y(), -0.25);
  expectAxesHoldEveryPoint(chart);
}

TEST(ChartNumbersTest, MomentumIn2DShowsMagnitudes) {
  const scene::SceneDesc scene = scene::loadPreset("billiards-glancing");
  const frame::ChartModel chart = chartOf("billiards-glancing", "momentum");
  EXPECT_EQ(chart.y_label, "|p| (kg\u00b7m/s)");
  const auto series = seriesByLabel(chart);
  expectBodyMomenta(
      series, [&](double t) { return test::twoDisks(scene, scene.restitution, t); }, true);
  // The total's magnitude stays m v₀ = 0.17 kg × 1.5 m/s.
  ASSERT_TRUE(series.count("\u03a3p"));
  EXPECT_GT(comparePoints(
                *series.at("\u03a3p"), [](double) { return 0.17 * 1.5; },
                [](double) { return false; }, 1e-12),
            500);
  expectAxesHoldEveryPoint(chart);
}

// Under gravity the energy chart carries potential energy, counted from the lowest point reached
// (the ball's centre one radius above the floor), and kinetic plus potential plus lost stays the
// energy at the start.
TEST(ChartNumbersTest, EnergyChartWithPotentialEnergyUnderGravity) {
  const scene::SceneDesc scene = scene::loadPreset("bouncing-ball");
  const frame::ChartModel chart = chartOf("bouncing-ball", "energy");
  const auto series = seriesByLabel(chart);
  for (const char* label : {"KE\u2081", "PE", "lost", "KE total"}) {
    ASSERT_TRUE(series.count(label)) << label;
  }
  // Closed form up to the second landing.
  const double g = 9.81, e = scene.restitution, r = scene.bodies[0].size_m;
  const double second_landing_s =
      std::sqrt(2.0 * (scene.bodies[0].position_m.y() - r) / g) * (1.0 + 2.0 * e);
  const auto truth = [&](double t) { return test::bouncingBall(scene, t); };
  const auto skip = [&](double t) {
    return t > second_landing_s - 1e-3 || truth(t - 1e-6).collisions != truth(t + 1e-6).collisions;
  };
  // The chart is drawn in the unit its axis names (0.1 J of energy reads in mJ).
  const double unit_J = chart.y_label == "energy (mJ)" ? 1e-3 : 1.0;
  EXPECT_TRUE(chart.y_label == "energy (mJ)" || chart.y_label == "energy (J)") << chart.y_label;
  const double tolerance = 1e-9;
  EXPECT_GT(comparePoints(
                *series.at("PE"), [&](double t) { return *truth(t).potential_J / unit_J; }, skip,
                tolerance),
            150);
  EXPECT_GT(comparePoints(
                *series.at("KE\u2081"),
                [&](double t) { return test::kinetic(truth(t).bodies) / unit_J; }, skip, tolerance),
            150);
  EXPECT_GT(
      comparePoints(
          *series.at("lost"), [&](double t) { return truth(t).lost_J / unit_J; }, skip, tolerance),
      150);
  const PanelTruth start = truth(0.0);
  EXPECT_NEAR(chart.max.y(), 1.05 * start.energy_start_J / unit_J, 1e-9);
  expectAxesHoldEveryPoint(chart);
}

// The soft-contact preset: cart 1 (1 kg, 1.5 m/s) meets cart 2 (2 kg, −0.5 m/s) when the 1.95 m
// between their faces has closed at 2 m/s, t = 0.975 s; the contact passes the impulse
// (1 + e) μ u = 1.7 × 2/3 kg × 2 m/s to cart 2.
TEST(ChartNumbersTest, ForceChartAreaIsTheImpulseAndItsNotesSaySo) {
  const frame::ChartModel chart = chartOf("soft-contact", "force");
  EXPECT_EQ(chart.y_label, "F (N)");
  ASSERT_EQ(chart.series.size(), 1u);
  const std::vector<core::Vec2>& points = chart.series[0].points;
  ASSERT_GT(points.size(), 20u);
  double area_Ns = 0.0;
  for (std::size_t k = 1; k < points.size(); ++k) {
    EXPECT_GE(points[k].x(), points[k - 1].x()) << "time runs forward";
    area_Ns += 0.5 * (points[k].y() + points[k - 1].y()) * (points[k].x() - points[k - 1].x());
  }
  const double impulse_Ns = 1.7 * (2.0 / 3.0) * 2.0;
  // The trapezoids over the recorded samples are off by about 5e-6 of the impulse.
  EXPECT_NEAR(area_Ns, impulse_Ns, 1e-4 * impulse_Ns);
  // The title says what is drawn; its notes, the impulse first, then when the contact began.
  EXPECT_EQ(chart.title, "Contact force against time");
  ASSERT_EQ(chart.notes.size(), 2u);
  std::smatch m;
  ASSERT_TRUE(
      std::regex_match(chart.notes[0], m, std::regex("total impulse ([0-9]+\\.([0-9]+)) N\u00b7s")))
      << chart.notes[0];
  // Three significant figures: 2.27 N·s, within half a unit of its last digit.
  EXPECT_EQ(m[2].length(), 2) << chart.notes[0];
  EXPECT_NEAR(std::stod(m[1]), impulse_Ns, 0.005 + 1e-12) << chart.notes[0];
  ASSERT_TRUE(
      std::regex_match(chart.notes[1], m, std::regex("contact from t = ([0-9]+\\.[0-9]{3}) s")))
      << chart.notes[1];
  EXPECT_NEAR(std::stod(m[1]), 1.95 / 2.0, 0.0005 + 1e-12) << chart.notes[1];
  // The chart zooms onto the contact, which lasts the scene's 0.2 s.
  EXPECT_NEAR(chart.min.x(), 0.975 - 0.1, 1e-6);
  EXPECT_NEAR(chart.max.x(), 0.975 + 0.2 + 0.1, 1e-6);
  expectAxesHoldEveryPoint(chart);
}

// A line at 0 (worked-example's "lost" before its collision at 7/6 s, the force before and after
// a contact) runs above the x axis, which sits at the chart's lowest value: the line neither hides
// the axis nor hides under it.
TEST(ChartNumbersTest, ZeroLinesRunClearOfTheXAxis) {
  for (const auto& [preset, quantity] :
       {std::pair<std::string, std::string>{"worked-example", "energy"},
        {"soft-contact", "force"}}) {
    SCOPED_TRACE(preset + " " + quantity);
    const frame::ChartModel chart = chartOf(preset, quantity);
    const double range = chart.max.y() - chart.min.y();
    ASSERT_GT(range, 0.0);
    double lowest = INFINITY;
    for (const frame::ChartSeries& s : chart.series) {
      for (const core::Vec2& p : s.points) lowest = std::min(lowest, p.y());
    }
    EXPECT_EQ(lowest, 0.0);
    EXPECT_LE(chart.min.y(), -0.03 * range);  // a few pixels at least on any picture
  }
  const frame::ChartModel energy = chartOf("worked-example", "energy");
  const auto series = seriesByLabel(energy);
  ASSERT_TRUE(series.count("lost"));
  EXPECT_EQ(series.at("lost")->points.front().y(), 0.0);
}

}  // namespace
}  // namespace collide
