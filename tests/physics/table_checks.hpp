#pragma once
// The checks shared by the property tests over random tables with a surface that takes energy
// and momentum (plane_friction_property_test.cpp, rolling_property_test.cpp), at `samples` + 1
// instants of the run: the books add up (kinetic + lost + to the surface = the start plus what
// was released), the kinetic energy never rises, what went to the surface never falls; without
// walls the bodies' momentum plus the surface's is the start's; no body overlaps another or a
// wall. Each failure ASSERTs (callers stop at HasFailure()).
#include <gtest/gtest.h>

#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"

namespace collide::physics::testing {

// Tolerances relative to the scene's energy and momentum scales, and in metres.
inline constexpr double kTableBooksRelative = 1e-11, kTableMomentumRelative = 1e-13;
inline constexpr double kTableOverlap_m = 1e-10;

// scale_J: the energy the tolerances are relative to.
inline void checkTableBooks(const Timeline& timeline, int samples, double scale_J, int scene) {
  const double start_J = energyBooks(timeline, 0.0).total_J();
  const double until = timeline.simulatedUntil_s();
  double kinetic_before = start_J, surface_before = 0.0;
  for (int k = 0; k <= samples; ++k) {
    const double t = until * k / samples;
    const EnergyBooks books = energyBooks(timeline, t);
    ASSERT_NEAR(books.total_J(), start_J + books.released_J, kTableBooksRelative * scale_J)
        << "scene " << scene << " t " << t;
    ASSERT_LE(books.kineticTotal_J(), kinetic_before + kTableBooksRelative * scale_J)
        << "scene " << scene << " t " << t;
    ASSERT_GE(books.surface_J, surface_before - kTableBooksRelative * scale_J)
        << "scene " << scene << " t " << t;
    kinetic_before = books.kineticTotal_J();
    surface_before = books.surface_J;
  }
  for (const Warning& warning : timeline.warnings()) {
    ASSERT_NE(warning.kind, WarningKind::kEnergyLedger) << "scene " << scene << warning.message;
  }
}

// p_scale: the momentum the tolerance is relative to; with_walls: the walls take momentum too,
// so only the overlaps are checked.
inline void checkTableMomentumAndOverlap(const Timeline& timeline, int samples, double p_scale,
                                         bool with_walls, int scene) {
  const WorldDef& world = timeline.world();
  const core::Vec2 p0 = timeline.momentum(timeline.initialState());
  const double until = timeline.simulatedUntil_s();
  for (int k = 0; k <= samples; ++k) {
    const double t = until * k / samples;
    const Snapshot s = timeline.sample(t);
    if (!with_walls) {
      ASSERT_LE((timeline.momentum(s) + s.surface_momentum_kgmps - p0).norm(),
                kTableMomentumRelative * p_scale)
          << "scene " << scene << " t " << t;
    }
    for (std::size_t a = 0; a < s.bodies.size(); ++a) {
      for (std::size_t b = a + 1; b < s.bodies.size(); ++b) {
        const double gap = (s.bodies[b].position_m - s.bodies[a].position_m).norm() -
                           world.bodies[a].size_m - world.bodies[b].size_m;
        ASSERT_GE(gap, -kTableOverlap_m) << "scene " << scene << " t " << t;
      }
      for (const WallDef& wall : world.walls) {
        const double clearance = (s.bodies[a].position_m - wall.point_m).dot(wall.normal);
        ASSERT_GE(clearance - world.bodies[a].size_m, -kTableOverlap_m)
            << "scene " << scene << " t " << t << " wall " << wall.name;
      }
    }
  }
}

}  // namespace collide::physics::testing
