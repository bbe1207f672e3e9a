// SPDX-License-Identifier: MIT
// air-drag through scene -> physics: the glider with the sail (quadratic drag c, mass m) slows as
// v = v0 / (1 + c v0 t / m), so it covers the gap d at t* = (m / (c v0))(e^(c d / m) - 1) and
// arrives at v0 e^(-c d / m); e = 1 between equal masses hands all of that to the glider at
// rest, which coasts on without drag. The air took 1/2 m (v0^2 - v*^2), the impact nothing, and
// the books add up at every instant. Every number from the preset's own masses, drag and places.
//
// air-drag-throw: two balls thrown alike from the floor, one to each side. The one without drag
// lands after 2 vy / g, vx times that away; the one with drag (rate r = k/m) moves as
//   x = x0 + vx (1 - e^(-rt)) / r,  y = y0 + (vy + g/r)(1 - e^(-rt)) / r - (g/r) t,
// so it lands where bisection on that y says, with the velocity its derivative gives; the air
// has then taken 1/2 m (v0^2 - v^2) (it lands at the height it left). The books add up, with the
// air's share, at every instant.
//
// Both pictures say which body feels the air: its mass label ends "with drag", the other's not.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "app/animation.hpp"
#include "app/world_from_scene.hpp"
#include "physics/energy_books.hpp"
#include "physics/simulate.hpp"
#include "scene/scene_desc.hpp"

namespace collide {
namespace drag_preset_physics_test {

TEST(DragPresetPhysicsTest, TheSailedGliderArrivesWhenAndAsFastAsTheClosedFormSays) {
  const physics::WorldDef world = app::worldFromScene(scene::loadPreset("air-drag"));
  ASSERT_EQ(world.bodies.size(), 2u);
  const physics::BodyDef &sail = world.bodies[0], &glider = world.bodies[1];
  ASSERT_EQ(sail.mass_kg, glider.mass_kg);
  ASSERT_EQ(world.restitution, 1.0);
  const double m = sail.mass_kg, c = sail.drag_quadratic_kgpm, v0 = sail.velocity_mps.x();
  ASSERT_GT(c, 0.0);
  ASSERT_EQ(glider.drag_quadratic_kgpm + glider.drag_linear_kgps, 0.0);
  const double d =
      (glider.position_m.x() - 0.5 * glider.size_m) - (sail.position_m.x() + 0.5 * sail.size_m);
  const double t_hit = (m / (c * v0)) * std::expm1(c * d / m);
  const double v_hit = v0 * std::exp(-c * d / m);
  const physics::Timeline timeline = physics::simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 1);
  const physics::CollisionEvent& impact = timeline.collisions().front();
  EXPECT_NEAR(impact.time_s, t_hit, 1e-14 * t_hit);
  EXPECT_NEAR(impact.velocity_a_before_mps.x(), v_hit, 1e-14 * v0);
  const physics::Snapshot end = timeline.sample(world.duration_s);
  EXPECT_NEAR(end.bodies[0].velocity_mps.x(), 0.0, 1e-14 * v0);
  EXPECT_NEAR(end.bodies[1].velocity_mps.x(), v_hit, 1e-14 * v0);
  EXPECT_NEAR(end.bodies[1].position_m.x(),
              glider.position_m.x() + v_hit * (world.duration_s - t_hit), 1e-12);
  // The air took what the sail's glider lost on its way; the elastic impact nothing.
  const double start_J = 0.5 * m * v0 * v0;
  EXPECT_NEAR(timeline.totalEnergyToAir(), 0.5 * m * (v0 * v0 - v_hit * v_hit), 1e-13 * start_J);
  EXPECT_NEAR(timeline.totalEnergyLost(), 0.0, 1e-15 * start_J);
  for (int k = 0; k <= 300; ++k) {
    const double t = world.duration_s * k / 300;
    const physics::EnergyBooks books = physics::energyBooks(timeline, t);
    EXPECT_NEAR(books.total_J(), start_J, 1e-12 * start_J) << "t " << t;
  }
}

// The first t in (0, 10] at which the closed form's height falls back to y0, by bisection.
double landingWithDrag_s(double vy, double g, double r) {
  auto rise = [&](double t) { return (vy + g / r) * -std::expm1(-r * t) / r - (g / r) * t; };
  double lo = 1e-3, hi = 10.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (rise(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(DragPresetPhysicsTest, TheThrowWithDragLandsShortWhereTheClosedFormSays) {
  const physics::WorldDef world = app::worldFromScene(scene::loadPreset("air-drag-throw"));
  ASSERT_EQ(world.bodies.size(), 2u);
  const physics::BodyDef &plain = world.bodies[0], &dragged = world.bodies[1];
  ASSERT_EQ(plain.drag_linear_kgps + plain.drag_quadratic_kgpm, 0.0);
  ASSERT_GT(dragged.drag_linear_kgps, 0.0);
  ASSERT_EQ(plain.mass_kg, dragged.mass_kg);
  ASSERT_EQ(plain.velocity_mps.x(), -dragged.velocity_mps.x());
  ASSERT_EQ(plain.velocity_mps.y(), dragged.velocity_mps.y());
  const double m = dragged.mass_kg, r = dragged.drag_linear_kgps / m, g = -world.gravity_mps2.y();
  const double vx = dragged.velocity_mps.x(), vy = dragged.velocity_mps.y();
  const double t_plain = 2.0 * vy / g, t_drag = landingWithDrag_s(vy, g, r);
  const double range_plain = vx * t_plain, range_drag = vx * -std::expm1(-r * t_drag) / r;
  const physics::Timeline timeline = physics::simulate(world);
  ASSERT_EQ(timeline.collisionCount(), 2);
  const physics::CollisionEvent &first = timeline.collisions()[0],
                                &second = timeline.collisions()[1];
  // The ball with drag lands first, on the floor.
  ASSERT_EQ(first.body_a, 1);
  ASSERT_TRUE(first.hitsWall());
  EXPECT_NEAR(first.time_s, t_drag, 1e-13 * t_drag);
  EXPECT_NEAR(first.velocity_a_before_mps.x(), vx * std::exp(-r * t_drag), 1e-13 * vx);
  const double vy_land = vy * std::exp(-r * t_drag) + (g / r) * std::expm1(-r * t_drag);
  EXPECT_NEAR(first.velocity_a_before_mps.y(), vy_land, 1e-13 * vy);
  const physics::Snapshot landed = timeline.sample(t_drag);
  EXPECT_NEAR(landed.bodies[1].position_m.x() - dragged.position_m.x(), range_drag, 1e-12);
  const double v_land2 = std::pow(vx * std::exp(-r * t_drag), 2) + vy_land * vy_land;
  const double start_J = m * (vx * vx + vy * vy);  // both balls
  EXPECT_NEAR(landed.energy_to_air_J, 0.5 * m * (vx * vx + vy * vy - v_land2), 1e-13 * start_J);
  // The ball without drag lands later and farther out, on its parabola.
  ASSERT_EQ(second.body_a, 0);
  EXPECT_NEAR(second.time_s, t_plain, 1e-13 * t_plain);
  EXPECT_NEAR(timeline.sample(t_plain).bodies[0].position_m.x() - plain.position_m.x(),
              -range_plain, 1e-12);
  EXPECT_LT(range_drag, 0.7 * range_plain);
  // The books, with the air's share, at every instant; the air's share never falls.
  double air_J = 0.0;
  for (int k = 0; k <= 400; ++k) {
    const double t = world.duration_s * k / 400;
    const physics::EnergyBooks books = physics::energyBooks(timeline, t);
    EXPECT_NEAR(books.total_J(), physics::energyBooks(timeline, 0.0).total_J(), 1e-12 * start_J)
        << "t " << t;
    EXPECT_GE(books.air_J, air_J) << "t " << t;
    air_J = books.air_J;
  }
  EXPECT_GT(air_J, landed.energy_to_air_J);  // sliding on after its landing, it slows on
}

// The label is read off the frame a still at t = 0 draws, in English; which body has drag is read
// off the preset's world, not the label code.
TEST(DragPresetPhysicsTest, TheMassLabelSaysWhichBodyFeelsTheAir) {
  for (const char* preset : {"air-drag", "air-drag-throw"}) {
    const scene::SceneDesc scene = scene::loadPreset(preset);
    const physics::WorldDef world = app::worldFromScene(scene);
    const frame::FrameModel frame = app::animate(scene, {1280, 720}).frames.frameAtSimulated(0.0);
    const frame::PanelModel& panel = frame.panels.front();
    // A label that gave way to the panel's legend is read there.
    const auto mass_label = [&](std::size_t b) {
      if (!panel.bodies[b].label.empty()) return panel.bodies[b].label;
      for (const frame::ReadoutLegend::Entry& entry : panel.legend.entries) {
        if (entry.mass && entry.body == static_cast<int>(b)) return entry.text;
      }
      return std::string();
    };
    ASSERT_EQ(panel.bodies.size(), world.bodies.size()) << preset;
    int with_drag = 0;
    for (std::size_t b = 0; b < world.bodies.size(); ++b) {
      const bool feels_air =
          world.bodies[b].drag_linear_kgps > 0.0 || world.bodies[b].drag_quadratic_kgpm > 0.0;
      with_drag += feels_air ? 1 : 0;
      const std::string label = mass_label(b);
      const std::string suffix = ", with drag";
      const bool says_drag =
          label.size() > suffix.size() &&
          label.compare(label.size() - suffix.size(), suffix.size(), suffix) == 0;
      EXPECT_EQ(says_drag, feels_air) << preset << " body " << b + 1 << ": " << label;
      EXPECT_EQ(label.rfind("m", 0), 0u) << preset << ": " << label;
    }
    EXPECT_EQ(with_drag, 1) << preset;  // one of the two, so the label tells them apart
  }
}

}  // namespace drag_preset_physics_test
}  // namespace collide
