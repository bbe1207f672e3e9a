// SPDX-License-Identifier: MIT
// Rolling balls: the scene's `rolling`, a body's `rolling_mu` and `spin`, and the checks on
// what a rolling table can go with (docs/scene-format.md, "Rolling balls").
#include <algorithm>

#include "scene/field_table.hpp"
#include "scene/reader_parts.hpp"
#include "scene/scene_io.hpp"

namespace collide::scene::detail {

void readBodyRolling(Fields& f, BodyDesc& body) {
  body.rolling_friction = f.number("rolling_mu", fieldRange("body", "rolling_mu")).value_or(0.0);
  if (f.has("spin")) body.spin = f.choice("spin", {"follow", "stop", "draw"}).value_or("");
}

namespace {

// A problem on the top-level key `key`: what the scene has that a rolling table cannot go with.
void refuseRolling(Fields& top, const char* key, const std::string& what) {
  top.problem(top.node(key), key, what);
}

}  // namespace

void checkRolling(Fields& top, const SceneDesc& scene) {
  if (!scene.rolling) {
    const bool keyed = std::any_of(scene.bodies.begin(), scene.bodies.end(), [](const auto& b) {
      return b.rolling_friction > 0.0 || !b.spin.empty();
    });
    if (keyed) {
      refuseRolling(top, "body",
                    "rolling_mu or spin on a body of a table whose balls do not roll; allowed: "
                    "them with rolling = true");
    }
    return;
  }
  if (scene.dimensions != 2) {
    refuseRolling(top, "rolling",
                  "balls rolling on a 1D track; allowed: rolling = true on a table "
                  "(dimensions = 2)");
  } else if (scene.gravity_mps2.x() != 0.0 || scene.gravity_mps2.y() != 0.0) {
    refuseRolling(top, "rolling",
                  "rolling balls with gravity in the plane; allowed: a level table "
                  "(no gravity; surface_gravity presses the balls on)");
  }
  if (scene.contact.model == ContactModelKind::kSpringDamper ||
      scene.contact.inelastic == InelasticMode::kStick) {
    refuseRolling(top, "rolling",
                  "rolling balls with a spring-damper or sticking contact; allowed: "
                  "contact.model = \"impulse\" with inelastic = \"slip\"");
  }
  const bool hanging = std::any_of(scene.bodies.begin(), scene.bodies.end(),
                                   [](const auto& b) { return b.pivot_m.has_value(); });
  const bool dragged = std::any_of(scene.bodies.begin(), scene.bodies.end(), [](const auto& b) {
    return b.drag_linear_kgps > 0.0 || b.drag_quadratic_kgpm > 0.0;
  });
  if (hanging || dragged || scene.internal_dof > 0) {
    refuseRolling(top, "rolling",
                  "rolling balls with a body on a string, air drag or insides; "
                  "allowed: free balls that only the cloth slows");
  }
}

}  // namespace collide::scene::detail
