// SPDX-License-Identifier: MIT
#include "working/working.hpp"

#include <cmath>

#include "core/error.hpp"
#include "text/number_format.hpp"
#include "text/translate.hpp"
#include "text/wording.hpp"
#include "working/steps.hpp"

namespace collide::working {
namespace {

std::string partnerName(const physics::Timeline& timeline, const physics::CollisionEvent& event) {
  const physics::WorldDef& world = timeline.world();
  if (event.hitsWall()) return world.walls[std::size_t(event.wallIndex())].name;
  return world.bodies[std::size_t(event.body_b)].name;
}

std::string titleOf(const Impact& impact, std::size_t index, std::size_t count) {
  const physics::CollisionEvent& event = impact.event;
  const std::string time = text::equation(text::symbol(text::Symbol::kTime),
                                          text::formatReading(event.time_s, impact.formats.time));
  if (event.release) {
    // TRANSLATORS: the title of the working of a release (a spring let go, a shot fired);
    // {a} and {b} are the names of the bodies, {time} is "t = 0.500 s".
    return text::fill(text::trc("working title",
                                "Release {index} of {count}: {a} and {b} pushed apart at {time}"),
                      {{"index", text::formatScaled(static_cast<long long>(index) + 1, 0)},
                       {"count", text::formatScaled(static_cast<long long>(count), 0)},
                       {"a", impact.timeline.world().bodies[std::size_t(event.body_a)].name},
                       {"b", partnerName(impact.timeline, event)},
                       {"time", time}});
  }
  // TRANSLATORS: the title of a working; {a} and {b} are the names of the bodies (or a body
  // and a wall), {time} is "t = 1.167 s".
  return text::fill(text::trc("working title", "Impact {index} of {count}: {a} and {b} at {time}"),
                    {{"index", text::formatScaled(static_cast<long long>(index) + 1, 0)},
                     {"count", text::formatScaled(static_cast<long long>(count), 0)},
                     {"a", impact.timeline.world().bodies[std::size_t(event.body_a)].name},
                     {"b", partnerName(impact.timeline, event)},
                     {"time", time}});
}

bool onString(const physics::Timeline& timeline, int body) {
  return body >= 0 && timeline.world().bodies[std::size_t(body)].on_string;
}

bool hasGravity(const physics::Timeline& timeline) {
  return timeline.world().gravity_mps2.norm() > 0.0;
}

// A bullet into a block hanging at rest on a string: they stick, then rise together.
bool isBallisticPendulum(const Impact& impact) {
  const physics::CollisionEvent& event = impact.event;
  if (event.hitsWall() || event.restitution != 0.0 || !hasGravity(impact.timeline)) return false;
  return onString(impact.timeline, event.body_a) != onString(impact.timeline, event.body_b);
}

// Balls hanging in a row, all on strings.
bool isCradle(const Impact& impact) {
  const std::vector<physics::BodyDef>& bodies = impact.timeline.world().bodies;
  if (bodies.size() < 3 || impact.event.hitsWall()) return false;
  for (const physics::BodyDef& body : bodies) {
    if (!body.on_string) return false;
  }
  return true;
}

// Two blocks and one wall, elastic everywhere, nothing else: Galperin's pi-blocks.
bool isPiBlocks(const Impact& impact) {
  const physics::WorldDef& world = impact.timeline.world();
  if (world.dimensions != 1 || world.bodies.size() != 2 || world.walls.size() != 1) return false;
  if (world.restitution != 1.0 || world.walls[0].restitution != 1.0) return false;
  return world.pair_restitution.empty() && !hasGravity(impact.timeline) &&
         world.restitution_model.law == physics::RestitutionLaw::kConstant &&
         world.contact_model == physics::ContactModel::kImpulse;
}

// A wall that gravity pulls the body onto: a ball bouncing on the floor.
bool isBounce(const Impact& impact) {
  const core::Vec2 gravity = impact.timeline.world().gravity_mps2;
  return impact.event.hitsWall() && impact.timeline.world().dimensions == 2 &&
         gravity.norm() > 0.0 && impact.event.normal.dot(gravity) > 0.0;
}

bool isStuckCluster(const Impact& impact) {
  const physics::WorldDef& world = impact.timeline.world();
  return world.dimensions == 2 && !impact.event.hitsWall() && impact.event.merged &&
         world.inelastic_mode == physics::InelasticMode::kStick && !isBallisticPendulum(impact);
}

void addKindOf(const Impact& impact, Working& working) {
  if (impact.event.release) {
    addRelease(impact, working);
    return;
  }
  if (impact.timeline.world().contact_model == physics::ContactModel::kSpringDamper &&
      !impact.event.hitsWall()) {
    addSoftContact(impact, working);
  } else if (isBallisticPendulum(impact)) {
    addBallisticPendulum(impact, working);
  } else if (isStuckCluster(impact)) {
    addStuckCluster(impact, working);
  } else if (isBounce(impact)) {
    addBouncingBall(impact, working);
  } else if (impact.event.hitsWall()) {
    addWall(impact, working);
  } else if (!addSkid(impact, working)) {
    addTwoBodies(impact, working);
    if (isCradle(impact)) addCradle(impact, working);
  }
  if (isPiBlocks(impact)) addPiBlocks(impact, working);
  addRestitutionLaw(impact, working);
}

// The releases before event k of the log (releases are counted apart from impacts in titles).
std::size_t releasesBefore(const physics::Timeline& timeline, std::size_t k) {
  std::size_t releases = 0;
  for (std::size_t i = 0; i < k; ++i) releases += timeline.collisions()[i].release ? 1 : 0;
  return releases;
}

}  // namespace

std::size_t impactCount(const physics::Timeline& timeline) {
  return timeline.collisions().size();
}

Working workingFor(const physics::Timeline& timeline, std::size_t impact_index) {
  COLLIDE_ASSERT(impact_index < impactCount(timeline), "workingFor: no such impact");
  const physics::CollisionEvent& event = timeline.collisions()[impact_index];
  const Impact impact{timeline, event, formatsFor(timeline, event), timeline.world().dimensions};
  // Releases are numbered among releases, impacts among impacts; impacts past the stored log are
  // counted too (collisionCount() counts every event, releases included).
  const std::size_t releases = releasesBefore(timeline, impact_index);
  const std::size_t all_releases = releasesBefore(timeline, timeline.collisions().size());
  Working working;
  working.title = event.release ? titleOf(impact, releases, all_releases)
                                : titleOf(impact, impact_index - releases,
                                          std::size_t(timeline.collisionCount()) - all_releases);
  addKindOf(impact, working);
  return working;
}

}  // namespace collide::working
