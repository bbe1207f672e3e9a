// SPDX-License-Identifier: MIT
// Air drag: a body's `drag_linear` and `drag_quadratic`, and the checks on what drag can go with
// (docs/scene-format.md).
#include <algorithm>

#include "scene/field_table.hpp"
#include "scene/reader_parts.hpp"
#include "scene/scene_io.hpp"

namespace collide::scene::detail {
namespace {

bool anyBody(const SceneDesc& scene, double BodyDesc::*coefficient) {
  return std::any_of(scene.bodies.begin(), scene.bodies.end(),
                     [&](const BodyDesc& body) { return body.*coefficient > 0.0; });
}

}  // namespace

void readBodyDrag(Fields& f, BodyDesc& body) {
  body.drag_linear_kgps = f.number("drag_linear", fieldRange("body", "drag_linear")).value_or(0.0);
  body.drag_quadratic_kgpm =
      f.number("drag_quadratic", fieldRange("body", "drag_quadratic")).value_or(0.0);
  if (body.pivot_m && (f.has("drag_linear") || f.has("drag_quadratic"))) {
    const char* key = f.has("drag_linear") ? "drag_linear" : "drag_quadratic";
    f.problem(f.node(key), key,
              "a body on a string swings without drag; allowed: drag on free bodies");
  }
}

void checkDrag(Fields& top, const SceneDesc& scene) {
  const bool quadratic = anyBody(scene, &BodyDesc::drag_quadratic_kgpm);
  if (!quadratic && !anyBody(scene, &BodyDesc::drag_linear_kgps)) return;
  if (scene.contact.model == ContactModelKind::kSpringDamper) {
    top.problem(top.node("contact"), "contact",
                "contact.model = \"spring-damper\" with air drag; allowed: drag with "
                "contact.model = \"impulse\"");
  }
  const bool friction = std::any_of(scene.bodies.begin(), scene.bodies.end(), [](const auto& b) {
    return b.friction > 0.0 || b.static_friction.value_or(0.0) > 0.0;
  });
  if (friction) {
    top.problem(top.node("body"), "body",
                "sliding friction and air drag in one scene; allowed: one of the two");
  }
  if (scene.dimensions == 2 && quadratic) {
    top.problem(top.node("dimensions"), "dimensions",
                "a plane with quadratic drag on a body; allowed: drag_quadratic on a 1D track "
                "(dimensions = 1), drag_linear in 1D and 2D");
  } else if (scene.dimensions == 2 && scene.contact.inelastic == InelasticMode::kStick) {
    top.problem(top.node("contact"), "contact",
                "contact.inelastic = \"stick\" with air drag (a spinning cluster's drag is not "
                "modelled); allowed: drag with contact.inelastic = \"slip\"");
  } else if (quadratic && scene.gravity_mps2.x() != 0.0) {
    top.problem(top.node("gravity"), "gravity",
                "gravity along the track with quadratic drag; allowed: drag_quadratic without "
                "gravity along the track, or drag_linear with it");
  }
}

}  // namespace collide::scene::detail
