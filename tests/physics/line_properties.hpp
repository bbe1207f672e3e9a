#pragma once
// Checks shared by the property tests over random line scenes where something outside the bodies
// takes energy (friction_property_test.cpp: the surface; drag_property_test.cpp: the air): the
// books add up at every sampled instant, the mechanical energy never rises, every impact obeys
// the definition of e, no body overlaps another, and the mirror image renumbered is the same
// motion. Each check ASSERTs; callers stop at HasFailure().
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "random_scenes.hpp"

namespace collide::physics::testing {

// Tolerances relative to the scene's energy and extent; the books are sums of a few hundred
// rounded terms at most.
inline constexpr double kLineBooksRelative = 1e-11, kLineOverlap_m = 1e-10;

// The scene's energy scale, J: its kinetic energy at the start, and gravity along the line
// giving a body its weight times the scene's extent (a few m).
inline double lineEnergyScale(const Timeline& timeline) {
  double scale = 1e-12;
  for (const BodyDef& body : timeline.world().bodies) {
    scale += 0.5 * body.mass_kg * body.velocity_mps.squaredNorm();
    scale += body.mass_kg * std::abs(timeline.world().gravity_mps2.x()) * 10.0;
  }
  return scale;
}

// Kinetic + gravity + lost + to the surface + to the air = the start + released at `samples`
// instants; the shares never negative; the mechanical energy never rising.
inline void checkLineBooks(const Timeline& timeline, int samples, int scene) {
  const double start_J = energyBooks(timeline, 0.0).total_J();
  const double scale_J = lineEnergyScale(timeline);
  const double slack_J = kLineBooksRelative * scale_J;
  double previous = timeline.mechanicalEnergy(timeline.sample(0.0));
  const double until = timeline.simulatedUntil_s();
  for (int k = 0; k <= samples; ++k) {
    const double t = until * k / samples;
    const EnergyBooks books = energyBooks(timeline, t);
    ASSERT_NEAR(books.total_J(), start_J + books.released_J, slack_J)
        << "scene " << scene << " t " << t;
    ASSERT_GE(books.surface_J, -slack_J) << "scene " << scene;
    ASSERT_GE(books.air_J, -slack_J) << "scene " << scene;
    const double mechanical = timeline.mechanicalEnergy(timeline.sample(t));
    ASSERT_LE(mechanical, previous + slack_J) << "scene " << scene << " t " << t;
    previous = mechanical;
  }
}

// No two neighbours overlap at `samples` instants (bodies on a line keep their order).
inline void checkLineOverlap(const Timeline& timeline, int samples, int scene) {
  const WorldDef& world = timeline.world();
  std::vector<int> order(world.bodies.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return world.bodies[a].position_m.x() < world.bodies[b].position_m.x();
  });
  for (int k = 0; k <= samples; ++k) {
    const Snapshot s = timeline.sample(timeline.simulatedUntil_s() * k / samples);
    for (std::size_t j = 0; j + 1 < order.size(); ++j) {
      const int a = order[j], b = order[j + 1];
      const double gap = s.bodies[b].position_m.x() - s.bodies[a].position_m.x() -
                         0.5 * (world.bodies[a].size_m + world.bodies[b].size_m);
      ASSERT_GE(gap, -kLineOverlap_m) << "scene " << scene << " sample " << k;
    }
  }
}

// Every impact obeys the definition of e and loses no negative energy; the ledger never warned.
inline void checkLineImpacts(const Timeline& timeline, int scene) {
  for (const CollisionEvent& event : timeline.collisions()) {
    const double scale =
        event.velocity_a_before_mps.norm() + event.velocity_b_before_mps.norm() + 1.0;
    const double before =
        (event.velocity_a_before_mps - event.velocity_b_before_mps).dot(event.normal);
    const double after =
        (event.velocity_a_after_mps - event.velocity_b_after_mps).dot(event.normal);
    ASSERT_NEAR(after, -event.restitution * before, 1e-12 * scale) << "scene " << scene;
    ASSERT_GE(event.energy_lost_J, -1e-13 * scale * scale) << "scene " << scene;
  }
  for (const Warning& warning : timeline.warnings()) {
    ASSERT_NE(warning.kind, WarningKind::kEnergyLedger) << "scene " << scene << warning.message;
  }
}

// The mirror image renumbered moves the same way, and its surface and air take the same energy,
// for runs of at most max_events impacts: beyond a few impacts rounding-level differences between
// a scene and its image grow (docs/physics.md, simultaneous impacts). Runs where the resting rule
// ended a bounce series are left out too: the gaps at the end of such a series are rounding
// noise, and the next impact of a partner comes due at a time that noise sets. Whether it
// compared.
inline bool checkLineMirror(const Timeline& timeline, int max_events, int scene) {
  if (timeline.collisionCount() > max_events) return false;
  for (const CollisionEvent& event : timeline.collisions()) {
    if (event.collapse_rule) return false;
  }
  const WorldDef& world = timeline.world();
  const Timeline image = simulate(mirroredAndRenumbered(world));
  EXPECT_EQ(image.collisionCount(), timeline.collisionCount()) << "scene " << scene;
  double speed = 1.0, extent = 1.0;
  for (const BodyDef& body : world.bodies) {
    speed = std::max(speed, body.velocity_mps.norm());
    extent = std::max(extent, body.position_m.norm());
  }
  const double energy = 1e-12 * lineEnergyScale(timeline);
  const int n = static_cast<int>(world.bodies.size());
  for (double t : {0.5 * timeline.simulatedUntil_s(), timeline.simulatedUntil_s()}) {
    const Snapshot s = timeline.sample(t), m = image.sample(t);
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(s.bodies[i].position_m.x(), -m.bodies[n - 1 - i].position_m.x(), 1e-12 * extent)
          << "scene " << scene << " t " << t;
      EXPECT_NEAR(s.bodies[i].velocity_mps.x(), -m.bodies[n - 1 - i].velocity_mps.x(),
                  1e-12 * speed)
          << "scene " << scene << " t " << t;
    }
    EXPECT_NEAR(s.energy_to_surface_J, m.energy_to_surface_J, energy) << "scene " << scene;
    EXPECT_NEAR(s.energy_to_air_J, m.energy_to_air_J, energy) << "scene " << scene;
  }
  return true;
}

}  // namespace collide::physics::testing
