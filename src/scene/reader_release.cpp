// SPDX-License-Identifier: MIT
// Reads [[release]] (stored energy pushing two touching bodies apart) and checks the keys that
// let energy in: releases in a 1D scene, between bodies that touch at t = 0; e above 1 only with
// super_elastic = true (the ranges say so), rigid impacts and no strings.
#include <algorithm>
#include <cmath>

#include "scene/field_table.hpp"
#include "scene/reader_parts.hpp"
#include "scene/scene_io.hpp"

namespace collide::scene::detail {
namespace {

// A body named by its 1-based index or its name.
std::optional<int> releaseBody(const SceneDesc& scene, const toml::node& node) {
  if (const auto* i = node.as_integer()) {
    if (i->get() >= 1 && i->get() <= static_cast<std::int64_t>(scene.bodies.size())) {
      return static_cast<int>(i->get() - 1);
    }
  } else if (const auto* s = node.as_string()) {
    for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
      if (scene.bodies[k].name == s->get()) return static_cast<int>(k);
    }
  }
  return std::nullopt;
}

double halfWidth(const BodyDesc& body) {
  return body.shape == "disk" ? body.size_m : 0.5 * body.size_m;
}

// The bodies, left one first, when they touch (to a part in 1e9, as the layout check allows).
bool orderTouching(const SceneDesc& scene, ReleaseDesc& release) {
  if (scene.bodies[release.body_a].position_m.x() > scene.bodies[release.body_b].position_m.x()) {
    std::swap(release.body_a, release.body_b);
  }
  const BodyDesc &a = scene.bodies[release.body_a], &b = scene.bodies[release.body_b];
  const double gap = (b.position_m.x() - halfWidth(b)) - (a.position_m.x() + halfWidth(a));
  return std::abs(gap) <=
         1e-9 * std::max({1.0, std::abs(a.position_m.x()), std::abs(b.position_m.x())});
}

void readOneRelease(Fields& f, SceneDesc& scene) {
  f.allowOnly(sectionKeys("release"));
  const std::string allowed =
      "allowed: two different bodies that touch at t = 0, each a 1-based index or a body's name "
      "(e.g. [1, 2])";
  ReleaseDesc release;
  const toml::node* bodies = f.node("bodies");
  const toml::array* list = bodies != nullptr ? bodies->as_array() : nullptr;
  std::optional<int> a, b;
  if (list != nullptr && list->size() == 2) {
    a = releaseBody(scene, *list->get(0));
    b = releaseBody(scene, *list->get(1));
  }
  if (bodies == nullptr) {
    f.missing("bodies", allowed);
  } else if (!a || !b || *a == *b) {
    f.problem(bodies, "bodies", "not two different bodies of this scene; " + allowed);
  }
  const Range& time = fieldRange("release", "time");
  if (!f.has("time")) f.missing("time", time.text());
  release.time_s = f.number("time", time).value_or(0.0);
  if (f.has("time") && release.time_s > scene.duration_s) {
    f.problem(f.node("time"), "time",
              "after the scene's end; allowed: a time from 0 to the duration, " +
                  plainNumber(scene.duration_s) + " s");
  }
  release.energy_J = f.number("energy", fieldRange("release", "energy"));
  release.speed_mps = f.number("speed", fieldRange("release", "speed"));
  if (f.has("energy") == f.has("speed")) {
    f.problem(f.has("energy") ? f.node("speed") : nullptr, "energy",
              "give one of energy and speed; allowed: energy (J, more than 0) or speed (m/s, "
              "more than 0)");
  }
  if (scene.dimensions != 1) {
    f.problem(bodies, "bodies", "a release in a 2D scene; allowed: releases in 1D scenes only");
  } else if (a && b && *a != *b) {
    release.body_a = *a;
    release.body_b = *b;
    if (!orderTouching(scene, release)) {
      f.problem(bodies, "bodies", "they do not touch at t = 0; " + allowed);
    }
  }
  scene.releases.push_back(release);
}

// The largest e a scene gives any pair or wall.
double largestRestitution(const SceneDesc& scene) {
  double e = std::max(scene.restitution, scene.string_restitution);
  for (const WallDesc& wall : scene.walls) e = std::max(e, wall.restitution.value_or(0.0));
  if (scene.box) e = std::max(e, scene.box->restitution.value_or(0.0));
  for (const PairDesc& pair : scene.pairs) e = std::max(e, pair.restitution);
  return e;
}

}  // namespace

void readReleases(const toml::array& tables, const Origins& origins, Problems& problems,
                  SceneDesc& scene) {
  for (std::size_t i = 0; i < tables.size(); ++i) {
    Fields f(*tables.get(i)->as_table(), "release." + std::to_string(i + 1), origins, problems);
    readOneRelease(f, scene);
  }
  std::stable_sort(scene.releases.begin(), scene.releases.end(),
                   [](const ReleaseDesc& p, const ReleaseDesc& q) { return p.time_s < q.time_s; });
}

void checkSuperElastic(Fields& top, const SceneDesc& scene) {
  if (!(largestRestitution(scene) > 1.0)) return;
  const bool strings = std::any_of(scene.bodies.begin(), scene.bodies.end(),
                                   [](const BodyDesc& body) { return body.pivot_m.has_value(); });
  if (scene.contact.model == ContactModelKind::kSpringDamper) {
    top.problem(top.node("super_elastic"), "super_elastic",
                "e above 1 with contact.model = \"spring-damper\", whose damper can only take "
                "energy; allowed: e above 1 with contact.model = \"impulse\"");
  } else if (strings) {
    top.problem(top.node("super_elastic"), "super_elastic",
                "e above 1 with bodies on strings; allowed: e above 1 for free bodies and walls");
  }
}

void checkInternal(Fields& top, const SceneDesc& scene) {
  if (scene.internal_dof == 0) return;
  const bool strings = std::any_of(scene.bodies.begin(), scene.bodies.end(),
                                   [](const BodyDesc& body) { return body.pivot_m.has_value(); });
  const bool pair_e = scene.restitution != 1.0 ||
                      std::any_of(scene.pairs.begin(), scene.pairs.end(),
                                  [](const PairDesc& pair) { return pair.restitution != 1.0; });
  std::string wrong;
  if (scene.dimensions != 2) {
    wrong = "internal energy of blocks on a line; allowed: internal with dimensions = 2 (disks)";
  } else if (scene.contact.model == ContactModelKind::kSpringDamper) {
    wrong =
        "internal with contact.model = \"spring-damper\"; allowed: internal with "
        "contact.model = \"impulse\"";
  } else if (strings) {
    wrong = "internal with bodies on strings; allowed: internal for free disks";
  } else if (pair_e) {
    wrong =
        "internal with e below or above 1 between bodies (their impacts conserve energy); "
        "allowed: internal with restitution = 1 (walls may take their own e)";
  }
  if (!wrong.empty()) top.problem(top.node("internal"), "internal", wrong);
}

}  // namespace collide::scene::detail
