// SPDX-License-Identifier: MIT
// Sliding friction: a body's `friction` and `static_friction`, the scene's `surface_gravity`,
// and the checks on what friction can go with (docs/scene-format.md).
#include <algorithm>

#include "scene/field_table.hpp"
#include "scene/reader_parts.hpp"
#include "scene/scene_io.hpp"

namespace collide::scene::detail {

void readBodyFriction(Fields& f, BodyDesc& body) {
  body.friction = f.number("friction", fieldRange("body", "friction")).value_or(0.0);
  body.static_friction = f.number("static_friction", fieldRange("body", "static_friction"));
  if (body.static_friction && *body.static_friction < body.friction) {
    f.problem(f.node("static_friction"), "static_friction",
              "below the body's friction (" + plainNumber(body.friction) +
                  "); allowed: a static coefficient at least the kinetic one");
  }
  if (body.pivot_m && (f.has("friction") || f.has("static_friction"))) {
    const char* key = f.has("friction") ? "friction" : "static_friction";
    f.problem(f.node(key), key,
              "a body on a string slides on no surface; allowed: friction for free bodies");
  }
}

void checkFriction(Fields& top, const SceneDesc& scene) {
  const bool friction = std::any_of(scene.bodies.begin(), scene.bodies.end(), [](const auto& b) {
    return b.friction > 0.0 || b.static_friction.value_or(0.0) > 0.0;
  });
  if (!friction) return;
  if (scene.contact.model == ContactModelKind::kSpringDamper) {
    top.problem(top.node("contact"), "contact",
                "contact.model = \"spring-damper\" with sliding friction; allowed: friction with "
                "contact.model = \"impulse\"");
  }
  // On a table the path of a sliding disk is straight only while nothing but friction acts
  // along the table: gravity in the plane would bend it into a curve with no closed form.
  if (scene.dimensions == 2 && (scene.gravity_mps2.x() != 0.0 || scene.gravity_mps2.y() != 0.0)) {
    top.problem(top.node("gravity"), "gravity",
                "gravity in the plane with sliding friction on a body; allowed: friction on a "
                "level table (no gravity in a 2D scene; surface_gravity presses the disks on)");
  }
}

}  // namespace collide::scene::detail
