#pragma once
// Closed forms for the presets the frame and chart tests read: the state at any time of two
// blocks meeting once on a line, two smooth disks meeting once, and a ball dropped onto a floor
// (up to its second landing), worked out from the scene's inputs alone.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "frame_text_check.hpp"
#include "scene/scene_desc.hpp"

namespace collide::test {

inline double kinetic(const std::vector<BodyTruth>& bodies) {
  double sum = 0.0;
  for (const BodyTruth& b : bodies) sum += 0.5 * b.mass_kg * b.velocity_mps.squaredNorm();
  return sum;
}

inline std::vector<BodyTruth> initialBodies(const scene::SceneDesc& scene) {
  std::vector<BodyTruth> bodies;
  for (const scene::BodyDesc& b : scene.bodies) bodies.push_back({b.mass_kg, b.velocity_mps});
  return bodies;
}

inline core::Vec2 momentumOf(const std::vector<BodyTruth>& bodies) {
  core::Vec2 p(0.0, 0.0);
  for (const BodyTruth& b : bodies) p += b.mass_kg * b.velocity_mps;
  return p;
}

// Two blocks on a line meeting once: contact when the gap between their faces has closed;
// then v₁′ = ((m₁ − e m₂) v₁ + (1 + e) m₂ v₂) / (m₁ + m₂) and its mirror, and ½ μ (1 − e²) u²
// lost.
inline PanelTruth twoBlocks(const scene::SceneDesc& scene, double e, double t_s) {
  const scene::BodyDesc &a = scene.bodies.at(0), &b = scene.bodies.at(1);
  const double m1 = a.mass_kg, m2 = b.mass_kg, v1 = a.velocity_mps.x(), v2 = b.velocity_mps.x();
  const double gap_m = (b.position_m.x() - 0.5 * b.size_m) - (a.position_m.x() + 0.5 * a.size_m);
  const double contact_s = gap_m / (v1 - v2);
  PanelTruth panel;
  panel.bodies = initialBodies(scene);
  panel.momentum_start_Ns = momentumOf(panel.bodies);
  panel.energy_start_J = kinetic(panel.bodies);
  if (t_s > contact_s) {
    panel.bodies[0].velocity_mps = {((m1 - e * m2) * v1 + (1 + e) * m2 * v2) / (m1 + m2), 0.0};
    panel.bodies[1].velocity_mps = {((1 + e) * m1 * v1 + (m2 - e * m1) * v2) / (m1 + m2), 0.0};
    panel.bodies[0].collided = panel.bodies[1].collided = true;
    panel.collisions = 1;
    panel.lost_J = 0.5 * (m1 * m2 / (m1 + m2)) * (1 - e * e) * (v1 - v2) * (v1 - v2);
  }
  return panel;
}

// Two smooth disks: contact when |d + w t| = r₁ + r₂ (d from disk 1 to disk 2, w their relative
// velocity); the impulse acts along the line of centres n with the normal closing speed u:
// J = (1 + e) u / (1/m₁ + 1/m₂); tangential components are kept.
inline PanelTruth twoDisks(const scene::SceneDesc& scene, double e, double t_s) {
  const scene::BodyDesc &a = scene.bodies.at(0), &b = scene.bodies.at(1);
  const core::Vec2 d = b.position_m - a.position_m, w = b.velocity_mps - a.velocity_mps;
  const double reach = a.size_m + b.size_m;
  const double dw = d.dot(w), ww = w.squaredNorm();
  const double contact_s = (-dw - std::sqrt(dw * dw - ww * (d.squaredNorm() - reach * reach))) / ww;
  PanelTruth panel;
  panel.bodies = initialBodies(scene);
  panel.momentum_start_Ns = momentumOf(panel.bodies);
  panel.energy_start_J = kinetic(panel.bodies);
  panel.momentum_diagram = scene.view.momentum_diagram;
  if (t_s > contact_s) {
    const core::Vec2 n = (d + w * contact_s) / reach;
    const double u = (a.velocity_mps - b.velocity_mps).dot(n);
    const double impulse = (1 + e) * u / (1 / a.mass_kg + 1 / b.mass_kg);
    panel.bodies[0].velocity_mps = a.velocity_mps - impulse / a.mass_kg * n;
    panel.bodies[1].velocity_mps = b.velocity_mps + impulse / b.mass_kg * n;
    panel.bodies[0].collided = panel.bodies[1].collided = true;
    panel.collisions = 1;
    const double mu = a.mass_kg * b.mass_kg / (a.mass_kg + b.mass_kg);
    panel.lost_J = 0.5 * mu * (1 - e * e) * u * u;
  }
  return panel;
}

// A ball dropped (horizontal speed only) onto a floor at y = 0: it lands when its centre is one
// radius up, at t_b = sqrt(2 (y₀ − r) / g), and leaves at e g t_b; until the next landing, at
// t_b (1 + 2e), y = r + e g t_b (t − t_b) − ½ g (t − t_b)². Potential energy is counted from the
// lowest point reached, the centre at r.
inline PanelTruth bouncingBall(const scene::SceneDesc& scene, double t_s) {
  const scene::BodyDesc& ball = scene.bodies.at(0);
  const double g = -scene.gravity_mps2.y(), e = scene.restitution, m = ball.mass_kg;
  const double r = ball.size_m, drop_m = ball.position_m.y() - r;
  EXPECT_EQ(ball.velocity_mps.y(), 0.0) << "the closed form below starts at rest vertically";
  const double landing_s = std::sqrt(2.0 * drop_m / g);
  EXPECT_LT(t_s, landing_s * (1.0 + 2.0 * e)) << "only the first bounce is worked out here";
  PanelTruth panel;
  panel.bodies = initialBodies(scene);
  panel.momentum_start_Ns = momentumOf(panel.bodies);
  panel.energy_start_J = kinetic(panel.bodies) + m * g * drop_m;
  double height_m = 0.0;  // of the centre above r
  if (t_s < landing_s) {
    panel.bodies[0].velocity_mps.y() = -g * t_s;
    height_m = drop_m - 0.5 * g * t_s * t_s;
  } else {
    const double after_s = t_s - landing_s, leaving_mps = e * g * landing_s;
    panel.bodies[0].velocity_mps.y() = leaving_mps - g * after_s;
    panel.bodies[0].collided = true;
    panel.collisions = 1;
    height_m = leaving_mps * after_s - 0.5 * g * after_s * after_s;
    panel.lost_J = 0.5 * m * (g * landing_s) * (g * landing_s) * (1 - e * e);
  }
  panel.potential_J = m * g * height_m;
  return panel;
}

}  // namespace collide::test
