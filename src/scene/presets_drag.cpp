// SPDX-License-Identifier: MIT
// Presets with air drag in the plane (the 1D air-drag preset is in presets_1d.cpp).
#include <cmath>
#include <numbers>

#include "scene/preset_builders.hpp"
#include "text/translate.hpp"

namespace collide::scene::detail {

// Two equal 0.2 kg balls (radius 0.1 m) thrown from the floor at 8 m/s, 75 degrees up, one to
// each side: ball 1 to the left without drag, ball 2 to the right with k = 0.1 kg/s (k/m =
// 0.5 /s). Without drag the flight lasts 2 v0 sin 75 / g = 1.58 s and the range is
// v0^2 sin 150 / g = 3.26 m, the path symmetric about its top (3.04 m up). With drag the closed
// form (docs/physics.md, "Air drag") lands the ball after 1.41 s, 2.10 m out, falling more
// steeply than it rose; the air has taken 40% of its kinetic energy by then. The floor (e = 0)
// ends each flight; both balls then slide on. The run ends 0.16 s after the ball without drag
// lands, when each has slid more than its diameter from where it landed, so a strobe pictures
// both landings apart from the last images.
SceneDesc airDragThrow(const Parameters&) {
  const double speed_mps = 8.0, angle_rad = 75.0 * std::numbers::pi / 180.0;
  const double vx_mps = speed_mps * std::cos(angle_rad), vy_mps = speed_mps * std::sin(angle_rad);
  const double mass_kg = 0.2, radius_m = 0.1;
  SceneDesc scene =
      presetScene(2, "air-drag-throw", text::tr("Air drag shortens the throw"), 1.74, 0.0,
                  {body(text::trc("preset body", "no drag"), "disk", mass_kg, radius_m,
                        {-0.15, radius_m}, {-vx_mps, vy_mps}),
                   body(text::trc("preset body", "with drag"), "disk", mass_kg, radius_m,
                        {0.15, radius_m}, {vx_mps, vy_mps})});
  scene.bodies[1].drag_linear_kgps = 0.1;
  scene.gravity_mps2 = {0.0, -9.81};
  scene.walls.push_back(
      {text::trc("preset wall", "floor"), {0.0, 0.0}, {0.0, 1.0}, std::nullopt});  // e: the scene's
  return scene;
}

}  // namespace collide::scene::detail
