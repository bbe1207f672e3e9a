// SPDX-License-Identifier: MIT
// Presets where stored energy comes in: bodies that start together and are pushed apart. The
// numbers are chosen so that the results follow by hand from conservation of momentum and the
// released energy Q = 1/2 m1 v1^2 + 1/2 m2 v2^2 (bodies at rest); each comment gives them.
#include "scene/preset_builders.hpp"
#include "text/translate.hpp"

namespace collide::scene::detail {

// Two carts at rest, touching, with a compressed spring between them that is let go at
// t = 0.5 s and gives them Q = 3 J. Sum p = 0: 1 kg v1 = -2 kg v2, so 3 J = 1/2 (1)(2 v2)^2 +
// 1/2 (2) v2^2 = 3 v2^2: v2 = 1 m/s, v1 = -2 m/s. Equal and opposite momenta (2 kg m/s), speeds in
// the inverse ratio of the masses.
SceneDesc springCarts(const Parameters&) {
  SceneDesc scene =
      presetScene(1, "spring-carts", text::tr("A released spring pushes two carts apart"), 3.0, 1.0,
                  {block(text::trc("preset body", "cart 1"), 1.0, 0.5, -0.25, 0.0),
                   block(text::trc("preset body", "cart 2"), 2.0, 0.6, 0.3, 0.0)});
  scene.releases.push_back({0, 1, 0.5, 3.0, std::nullopt});
  return scene;
}

// A 4 kg rifle fires a 10 g bullet at t = 0.25 s with Q = 802 J: Sum p = 0 gives 0.01 kg v_b =
// -4 kg v_r, and 802 J = 1/2 (0.01) v_b^2 + 1/2 (4) v_r^2 gives v_b = 400 m/s, v_r = -1 m/s: the
// recoil. The bullet stops in a wall 3.5 m away (e = 0), which takes its 800 J; the rifle keeps
// 2 J. (Drawn wider than a bullet, so that its number fits beside it while it touches the rifle.)
SceneDesc recoil(const Parameters&) {
  SceneDesc scene =
      presetScene(1, "recoil", text::tr("A rifle fires a bullet and recoils"), 2.0, 1.0,
                  {block(text::trc("preset body", "rifle"), 4.0, 0.8, 0.0, 0.0),
                   block(text::trc("preset body", "bullet"), 0.01, 0.12, 0.46, 0.0)});
  scene.walls.push_back({text::trc("preset wall", "wall"), {4.0, 0.0}, {-1.0, 0.0}, 0.0});
  scene.releases.push_back({0, 1, 0.25, 802.0, std::nullopt});
  scene.view.slow_motion_factor = 10.0;
  return scene;
}

}  // namespace collide::scene::detail
