#include "compose/chart_builder.hpp"

#include <algorithm>
#include <cmath>

#include "compose/frame_text.hpp"
#include "compose/readouts.hpp"
#include "compose/speed_histogram.hpp"
#include "text/translate.hpp"
#include "text/wording.hpp"

namespace collide::compose {

using text::Symbol;
namespace {

constexpr int kSamples = 600;                 // uniform samples over the duration
constexpr std::size_t kMaxStepEvents = 2000;  // collisions drawn as sharp steps, at most
constexpr std::size_t kMaxBodySeries = 4;     // more bodies: totals only
constexpr int kSamplesPerContact = 60;        // energy chart samples inside a soft contact
// Room under the lowest value, of the value range: a line at 0 ("lost" before the first impact, the
// force between contacts) runs just above the x axis instead of on it, where it would hide the
// axis or be hidden by it.
constexpr double kFloorMargin = 0.04;

// Sample times: uniform, plus just before and at each collision so steps stay vertical.
std::vector<double> sampleTimes(const physics::Timeline& timeline) {
  const double duration = timeline.duration_s();
  std::vector<double> times;
  for (int i = 0; i <= kSamples; ++i) times.push_back(duration * i / kSamples);
  const auto& events = timeline.collisions();
  for (std::size_t k = 0; k < events.size() && k < kMaxStepEvents; ++k) {
    times.push_back(std::max(0.0, events[k].time_s - 1e-9 * duration));
    times.push_back(events[k].time_s);
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

// An axis title: the quantity's symbol and its unit, "t (s)".
std::string axisLabel(const std::string& symbol, const std::string& unit) {
  return symbol + " (" + unit + ")";
}

// Molecules with insides: where the translational and the internal energy relax to, each degree
// of freedom holding the same share of the total (2 translational ones per disk in a plane, ζ
// internal ones): KE total 2/(2 + ζ) of it, internal ζ/(2 + ζ). One dashed line for each level
// (one where they meet, ζ = 2), across the whole run.
std::vector<frame::ChartSeries> equipartitionLines(const physics::Timeline& timeline,
                                                   const FramePlan& plan, const Theme& theme,
                                                   int internal_dof) {
  const physics::EnergyBooks start = panelBooks(timeline, plan, 0.0);
  const double total = (start.kineticTotal_J() + start.internal_J) / plan.formats.energy.unit_value;
  const double zeta = internal_dof, translational = 2.0;
  std::vector<double> levels = {total * translational / (translational + zeta)};
  if (zeta != translational) levels.push_back(total * zeta / (translational + zeta));
  std::vector<frame::ChartSeries> lines;
  for (double level : levels) {
    // TRANSLATORS: the energy chart's dashed line where a gas's translational and internal
    // energy settle when every degree of freedom holds the same share.
    lines.push_back({text::tr("equipartition"),
                     theme.equipartition,
                     {{0.0, level}, {timeline.duration_s(), level}},
                     true});
  }
  return lines;
}

// Each body's kinetic energy at the books' time, as a point of its series (per_body), the disks'
// spin taken out and added to `spin`'s series, as the bar shows them (readouts.hpp). Returns
// whether the scene's bodies can spin.
bool addKineticPoints(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                      const FramePlan& plan, const physics::EnergyBooks& books, bool per_body,
                      std::vector<frame::ChartSeries>& bodies, frame::ChartSeries& spin) {
  const text::QuantityFormat& unit = plan.formats.energy;
  const double t = books.time_s;
  const std::vector<double> spin_J = spinEnergies_J(scene, timeline, plan, books);
  double spin_total_J = 0.0;
  for (std::size_t i = 0; i < books.kinetic_J.size(); ++i) {
    const double own_spin_J = i < spin_J.size() ? spin_J[i] : 0.0;
    spin_total_J += own_spin_J;
    if (per_body && i < bodies.size())
      bodies[i].points.push_back({t, (books.kinetic_J[i] - own_spin_J) / unit.unit_value});
  }
  if (spin_J.empty()) return false;
  spin.points.push_back({t, spin_total_J / unit.unit_value});
  return true;
}

frame::ChartModel energyChart(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                              const FramePlan& plan, const Theme& theme) {
  frame::ChartModel chart;
  const text::QuantityFormat& unit = plan.formats.energy;
  chart.title = text::tr("Energy against time");
  chart.x_label = axisLabel(text::symbol(Symbol::kTime), "s");
  // TRANSLATORS: the energy chart's vertical axis; {unit} is "J", "mJ", "kJ".
  chart.y_label = text::fill(text::tr("energy ({unit})"), {{"unit", unit.unit}});
  const std::size_t n = scene.bodies.size();
  const bool per_body = n <= kMaxBodySeries;
  std::vector<frame::ChartSeries> bodies(per_body ? n : 0);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    bodies[i] = {text::symbol(Symbol::kKineticEnergy) + subscript(int(i) + 1),
                 bodyColor(theme, i, scene.bodies[i]),
                 {},
                 false};
  }
  // TRANSLATORS: the energy chart's line of the total kinetic energy; {symbol} is "KE".
  frame::ChartSeries total{
      text::fill(text::tr("{symbol} total"), {{"symbol", text::symbol(Symbol::kKineticEnergy)}}),
      theme.total,
      {},
      true};
  frame::ChartSeries potential{text::symbol(Symbol::kPotentialEnergy), theme.potential, {}, false};
  frame::ChartSeries spring{springWord(), theme.spring, {}, false};
  frame::ChartSeries lost{lostWord(), theme.lost, {}, false};
  frame::ChartSeries released{releasedWord(), theme.released, {}, false};
  frame::ChartSeries surface{surfaceWord(plan.cloth), theme.surface, {}, false};
  frame::ChartSeries air{airWord(), theme.air, {}, false};
  frame::ChartSeries internal{internalWord(), theme.spring, {}, false};
  // The disks' spin apart from each body's KE, as the bar shows it (readouts.hpp).
  frame::ChartSeries spin{spinWord(), theme.total, {}, false};
  bool spins = false;
  const bool insides = scene.internal_dof > 0;
  const bool springs = !timeline.softContacts().empty();
  std::vector<double> times = sampleTimes(timeline);
  // Soft contacts: enough samples inside each to draw the spring's store and the loss growing.
  for (const physics::SoftContact& contact : timeline.softContacts()) {
    for (int k = 0; k <= kSamplesPerContact; ++k) {
      times.push_back(contact.start_s + (contact.end_s - contact.start_s) * k / kSamplesPerContact);
    }
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  for (double t : times) {
    const physics::EnergyBooks books = panelBooks(timeline, plan, t);
    spins = addKineticPoints(scene, timeline, plan, books, per_body, bodies, spin) || spins;
    total.points.push_back({t, books.kineticTotal_J() / unit.unit_value});
    if (plan.potential) potential.points.push_back({t, books.gravity_J / unit.unit_value});
    if (springs) spring.points.push_back({t, books.springTotal_J() / unit.unit_value});
    if (insides) internal.points.push_back({t, books.internal_J / unit.unit_value});
    lost.points.push_back({t, books.lost_J / unit.unit_value});
    if (plan.releases) released.points.push_back({t, books.released_J / unit.unit_value});
    if (plan.friction) surface.points.push_back({t, books.surface_J / unit.unit_value});
    if (plan.drag) air.points.push_back({t, books.air_J / unit.unit_value});
  }
  chart.series = std::move(bodies);
  if (spins) chart.series.push_back(spin);
  chart.series.push_back(total);
  if (plan.potential) chart.series.push_back(potential);
  if (springs) chart.series.push_back(spring);
  if (plan.friction) chart.series.push_back(surface);
  if (plan.drag) chart.series.push_back(air);
  if (insides) {
    chart.series.push_back(internal);
    for (frame::ChartSeries& line : equipartitionLines(timeline, plan, theme, scene.internal_dof))
      chart.series.push_back(std::move(line));
  }
  chart.series.push_back(lost);
  if (plan.releases) chart.series.push_back(released);
  const double top = 1.05 * plan.energy_full_scale_J / unit.unit_value;
  chart.min = {0.0, -kFloorMargin * top};
  chart.max = {timeline.duration_s(), top};
  return chart;
}

frame::ChartModel momentumChart(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                                const FramePlan& plan, const Theme& theme) {
  frame::ChartModel chart;
  const bool one_d = scene.dimensions == 1;
  chart.title =
      one_d ? text::tr("Momentum against time") : text::tr("Momentum (magnitude) against time");
  chart.x_label = axisLabel(text::symbol(Symbol::kTime), "s");
  const std::string p = text::symbol(Symbol::kMomentum);
  chart.y_label = axisLabel(one_d ? p : "|" + p + "|", "kg·m/s");
  const std::vector<physics::BodyDef>& defs = timeline.world().bodies;
  const std::size_t n = defs.size();
  const bool per_body = n <= kMaxBodySeries;
  std::vector<frame::ChartSeries> bodies(per_body ? n : 0);
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    bodies[i] = {p + subscript(int(i) + 1), bodyColor(theme, i, scene.bodies[i]), {}, false};
  }
  frame::ChartSeries total{std::string("Σ") + p, theme.total, {}, true};
  // With friction, the momentum the surface took: Σp plus it is the start's.
  frame::ChartSeries surface{surfaceWord(plan.cloth), theme.surface, {}, false};
  double low = 0.0, high = 0.0;
  for (double t : sampleTimes(timeline)) {
    const physics::Snapshot snapshot = timeline.sample(t);
    core::Vec2 sum{0.0, 0.0};
    for (std::size_t i = 0; i < n; ++i) {
      const core::Vec2 p =
          defs[i].mass_kg * (snapshot.bodies[i].velocity_mps - plan.frame_velocity_mps);
      sum += p;
      const double value = one_d ? p.x() : p.norm();
      if (per_body) bodies[i].points.push_back({t, value});
      low = std::min(low, value);
      high = std::max(high, value);
    }
    const double value = one_d ? sum.x() : sum.norm();
    total.points.push_back({t, value});
    low = std::min(low, value);
    high = std::max(high, value);
    if (plan.friction) {
      const core::Vec2& taken = snapshot.surface_momentum_kgmps;
      const double surface_value = one_d ? taken.x() : taken.norm();
      surface.points.push_back({t, surface_value});
      low = std::min(low, surface_value);
      high = std::max(high, surface_value);
    }
  }
  chart.series = std::move(bodies);
  chart.series.push_back(total);
  if (plan.friction) chart.series.push_back(surface);
  const double pad = 0.05 * std::max(high - low, 1e-9);  // at least kFloorMargin
  chart.min = {0.0, low - pad};  // below a low of 0 too, clear of the x axis
  chart.max = {timeline.duration_s(), high + pad};
  return chart;
}

frame::ChartModel forceChart(const physics::Timeline& timeline, const FramePlan& plan,
                             const Theme& theme) {
  frame::ChartModel chart;
  chart.title = text::tr("Contact force against time");
  chart.x_label = axisLabel(text::symbol(Symbol::kTime), "s");
  chart.y_label = axisLabel(text::symbol(Symbol::kForce), "N");
  frame::ChartSeries force{text::symbol(Symbol::kForce), theme.bodies[0], {}, false};
  const std::vector<physics::SoftContact>& contacts = timeline.softContacts();
  double high = 0.0, low = 0.0;
  for (const physics::SoftContact& contact : contacts) {
    force.points.push_back({contact.start_s, 0.0});
    for (const physics::ContactForceSample& sample : contact.samples) {
      force.points.push_back({sample.time_s, sample.force_N});
      high = std::max(high, sample.force_N);
      low = std::min(low, sample.force_N);
    }
    force.points.push_back({contact.end_s, 0.0});
  }
  const double top = high > 0.0 ? 1.1 * high : 1.0;
  chart.min = {0.0, low - kFloorMargin * (top - low)};
  chart.max = {timeline.duration_s(), top};
  if (contacts.size() == 1) {
    // One contact lasts milliseconds: zoom onto it.
    const physics::SoftContact& c = contacts.front();
    const double d = std::max(c.end_s - c.start_s, 1e-9);
    chart.min.x() = std::max(0.0, c.start_s - 0.5 * d);
    chart.max.x() = c.end_s + 0.5 * d;
    double impulse_Ns = 0.0;  // area under the pulse (trapezoids)
    for (std::size_t k = 1; k < c.samples.size(); ++k) {
      impulse_Ns += 0.5 * (c.samples[k].force_N + c.samples[k - 1].force_N) *
                    (c.samples[k].time_s - c.samples[k - 1].time_s);
    }
    // The title stays short and the numbers go on lines of their own, most important first: a
    // short chart gives up the start time, then the impulse. The impulse is the whole contact's,
    // which a video shows from its first frame, before the pulse is drawn: "total", so it is
    // not read as the impulse so far.
    chart.notes = {
        // TRANSLATORS: a line under the force chart's title; {impulse} is "0.52 N·s".
        text::fill(text::tr("total impulse {impulse}"),
                   {{"impulse", text::formatValue(impulse_Ns, "N·s")}}),
        // TRANSLATORS: a line under the force chart's title; {time} is "t = 1.2 s".
        text::fill(text::tr("contact from {time}"), {{"time", timeText(c.start_s, plan.formats)}})};
  } else if (contacts.empty()) {
    chart.title = text::tr("Contact force: no soft contacts in this scene");
  }
  force.points.insert(force.points.begin(), {chart.min.x(), 0.0});
  force.points.push_back({chart.max.x(), 0.0});
  chart.series.push_back(force);
  return chart;
}

}  // namespace

frame::ChartModel buildChart(const scene::SceneDesc& scene, const physics::Timeline& timeline,
                             const FramePlan& plan, const Theme& theme,
                             const std::string& quantity) {
  if (quantity == kSpeedChartQuantity) {
    return speedHistogram(timeline, plan, theme, timeline.duration_s());
  }
  if (quantity == "force") return forceChart(timeline, plan, theme);
  if (quantity == "momentum") return momentumChart(scene, timeline, plan, theme);
  return energyChart(scene, timeline, plan, theme);
}

}  // namespace collide::compose
