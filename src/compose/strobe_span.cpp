// The time span a strobe photographs (strobe_plan.hpp's strobeSpan_s): where a swing turns.
#include <algorithm>
#include <optional>
#include <vector>

#include "compose/strobe_plan.hpp"

namespace collide::compose {
namespace {

// Samples of the kinetic energy between the first collision and the end: enough that a swing's
// turn (a broad minimum, energy falling as the square of the time to it) is bracketed by three of
// them, however long the run, and few enough to cost no more than choosing the rate does.
constexpr int kSpanEnergySamples = 400;
// Bisection steps on the bracket: 60 halvings take it below a double's resolution of the time.
constexpr int kSpanSearchSteps = 60;
// "At rest" relative to the most kinetic energy sampled after the collision. Just past the turn,
// by dt, a body keeps ½·m·(a·dt)², a its tangential acceleration (g at most): with dt below
// kSpanPastTurn_s that is below 1e-20 of a swing's energy at 1 m/s. 1e-9 keeps a wide margin and
// still tells a turn from a slow passage (a pendulum at 3% of its top speed keeps 1e-3).
constexpr double kSpanRestFraction = 1e-9;
// The span ends this far past the turn found, so that a picture asking whether the swing has
// reached its top (the ballistic pendulum's rise: suspension_view.cpp bisects to 1e-12 s) answers
// yes at the last image. The momentum a swing gains in it (g times 1e-11 s per kg) stays below
// what the picture's numbers read as round-off of zero (1e-9 of the largest value).
constexpr double kSpanPastTurn_s = 1e-11;

// The kinetic energy at t_s, disks' spin included: a disk still spinning is not at rest.
double strobeKineticEnergy_J(const physics::Timeline& timeline, double t_s) {
  return timeline.kineticEnergy(timeline.sample(t_s));
}

// Whether t_s lies inside a soft contact (a spring-damper pair at its deepest compression may
// rest for an instant when their momenta cancel: that is the collision, not a swing turning).
bool insideSoftContact(const physics::Timeline& timeline, double t_s) {
  for (const physics::CollisionEvent& event : timeline.collisions()) {
    if (event.time_s > t_s) break;
    if (t_s <= event.time_s + event.contact_duration_s) return true;
  }
  return false;
}

// The first instant after the panel's first collision between bodies at which every body is at
// rest and then moves again, outside any soft contact; none where there is no such instant.
std::optional<double> firstTurnAfterCollision(const StrobeSubject& panel, double duration_s) {
  if (panel.strobed) return std::nullopt;  // a gas: never all at rest
  double first_s = -1.0;
  for (const physics::CollisionEvent& event : panel.timeline.collisions()) {
    if (event.hitsWall() || event.time_s <= 0.0 || event.time_s >= duration_s) continue;
    first_s = event.time_s;
    break;
  }
  if (first_s < 0.0) return std::nullopt;
  const double step_s = (duration_s - first_s) / kSpanEnergySamples;
  std::vector<double> energy_J(kSpanEnergySamples + 1);
  for (int k = 1; k <= kSpanEnergySamples; ++k)
    energy_J[k] = strobeKineticEnergy_J(panel.timeline, first_s + k * step_s);
  const double most_J = *std::max_element(energy_J.begin() + 1, energy_J.end());
  if (!(most_J > 0.0)) return std::nullopt;
  for (int k = 2; k < kSpanEnergySamples; ++k) {
    // A minimum the energy rises from again (a body that stops for good does not end the span:
    // its images stack into one anyway).
    if (!(energy_J[k] <= energy_J[k - 1] && energy_J[k] < energy_J[k + 1])) continue;
    // The fastest body just before: at the turn it stops and comes back (its velocity reverses).
    double lo_s = first_s + (k - 1) * step_s, hi_s = first_s + (k + 1) * step_s;
    const physics::Snapshot before = panel.timeline.sample(lo_s);
    std::size_t fastest = 0;
    for (std::size_t i = 0; i < before.bodies.size(); ++i) {
      if (before.bodies[i].velocity_mps.squaredNorm() >
          before.bodies[fastest].velocity_mps.squaredNorm())
        fastest = i;
    }
    const core::Vec2 heading_mps = before.bodies[fastest].velocity_mps;
    const auto comingBack = [&](double t_s) {
      return panel.timeline.sample(t_s).bodies[fastest].velocity_mps.dot(heading_mps) <= 0.0;
    };
    if (!comingBack(hi_s)) continue;  // slowed down without turning
    for (int i = 0; i < kSpanSearchSteps; ++i) {
      const double mid_s = 0.5 * (lo_s + hi_s);
      (comingBack(mid_s) ? hi_s : lo_s) = mid_s;
    }
    const double turn_s = hi_s + kSpanPastTurn_s;
    if (strobeKineticEnergy_J(panel.timeline, turn_s) <= kSpanRestFraction * most_J &&
        !insideSoftContact(panel.timeline, turn_s))
      return turn_s;
  }
  return std::nullopt;
}

}  // namespace

double strobeSpan_s(const std::vector<StrobeSubject>& panels, double duration_s) {
  double end_s = 0.0;
  for (const StrobeSubject& panel : panels) {
    const std::optional<double> turn_s = firstTurnAfterCollision(panel, duration_s);
    if (!turn_s) return duration_s;
    end_s = std::max(end_s, *turn_s);
  }
  return panels.empty() ? duration_s : std::min(end_s, duration_s);
}

}  // namespace collide::compose
