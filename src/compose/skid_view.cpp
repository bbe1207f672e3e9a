// SPDX-License-Identifier: MIT
#include "compose/skid_view.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "text/translate.hpp"

namespace collide::compose {
namespace {

// The line stands at this share of the trailing body's height.
constexpr double kLineHeight = 0.5;

// A skid's trailing face as drawn now: where it is, and the bottom and height of its body.
struct TrailingFace {
  double x_m = 0.0, bottom_m = 0.0, height_m = 0.0;
};

TrailingFace trailingFace(const Skid& skid, const frame::PanelModel& panel) {
  TrailingFace face;
  bool found = false;
  for (int body : skid.bodies) {
    const frame::BodyModel& drawn = panel.bodies[static_cast<std::size_t>(body)];
    const double x = drawn.center_m.x() + (skid.rightward ? -1.0 : 1.0) * drawn.half_extent_m.x();
    if (found && (skid.rightward ? x >= face.x_m : x <= face.x_m)) continue;
    found = true;
    face = {x, drawn.center_m.y() - drawn.half_extent_m.y(), 2.0 * drawn.half_extent_m.y()};
  }
  return face;
}

// Whether the body slides with sliding friction: a kinetic μ on a surface that presses on it.
bool slides(const physics::WorldDef& world, int body) {
  return world.surface_gravity_mps2 > 0.0 && world.bodies[body].friction > 0.0;
}

// The first collision after `from` (by index) that involves one of `bodies`; +inf: none.
double nextCollision_s(const physics::Timeline& timeline, std::size_t from,
                       const std::vector<int>& bodies) {
  const std::vector<physics::CollisionEvent>& events = timeline.collisions();
  for (std::size_t k = from + 1; k < events.size(); ++k) {
    const physics::CollisionEvent& e = events[k];
    for (int body : bodies) {
      if (e.body_a == body || e.body_b == body) return e.time_s;
    }
  }
  return std::numeric_limits<double>::infinity();
}

// The skid of `bodies`, moving at v_mps after the impact `k`; none where they stand still or do
// not slide with friction.
void addSkid(std::vector<Skid>& skids, const physics::Timeline& timeline, std::size_t k,
             std::vector<int> bodies, double v_mps) {
  const physics::WorldDef& world = timeline.world();
  const bool any_slides =
      std::any_of(bodies.begin(), bodies.end(), [&](int body) { return slides(world, body); });
  if (v_mps == 0.0 || !any_slides) return;
  Skid skid;
  skid.from_s = timeline.collisions()[k].time_s;
  skid.until_s = nextCollision_s(timeline, k, bodies);
  skid.rightward = v_mps > 0.0;
  skid.bodies = std::move(bodies);
  skids.push_back(std::move(skid));
}

}  // namespace

std::vector<Skid> findSkids(const physics::Timeline& timeline) {
  std::vector<Skid> skids;
  const physics::WorldDef& world = timeline.world();
  if (world.dimensions != 1 || !physics::hasFriction(world)) return skids;
  const std::vector<physics::CollisionEvent>& events = timeline.collisions();
  for (std::size_t k = 0; k < events.size(); ++k) {
    const physics::CollisionEvent& e = events[k];
    if (e.hitsWall() || e.release) continue;
    if (e.merged) {
      addSkid(skids, timeline, k, {e.body_a, e.body_b}, e.velocity_a_after_mps.x());
      continue;
    }
    addSkid(skids, timeline, k, {e.body_a}, e.velocity_a_after_mps.x());
    addSkid(skids, timeline, k, {e.body_b}, e.velocity_b_after_mps.x());
  }
  return skids;
}

double skidLength_m(const Skid& skid, const physics::Timeline& timeline, double t_s) {
  if (t_s <= skid.from_s) return 0.0;
  const int body = skid.bodies.front();
  const double end_s = std::min(t_s, skid.until_s);
  return std::abs(timeline.sample(end_s).bodies[body].position_m.x() -
                  timeline.sample(skid.from_s).bodies[body].position_m.x());
}

double longestSkid_m(const std::vector<Skid>& skids, const physics::Timeline& timeline) {
  double longest = 0.0;
  for (const Skid& skid : skids) {
    const double end_s = std::min(skid.until_s, timeline.simulatedUntil_s());
    longest = std::max(longest, skidLength_m(skid, timeline, end_s));
  }
  return longest;
}

void addSkids(frame::PanelModel& panel, const physics::Timeline& timeline,
              const std::vector<Skid>& skids, const text::QuantityFormat& length, double t_s) {
  int shown = 0;
  for (const Skid& skid : skids) {
    if (!(t_s > skid.from_s && t_s < skid.until_s)) continue;
    const TrailingFace face = trailingFace(skid, panel);
    const double d = skidLength_m(skid, timeline, t_s);
    frame::DimensionModel dim;
    dim.axis = frame::DimensionAxis::kHorizontal;
    dim.id = "skid." + std::to_string(++shown);
    // From the road where the trailing face was at the impact to that face now, the line at its
    // middle height: in the free road behind the bodies, clear of the readouts over them.
    dim.line_at_m = face.bottom_m + kLineHeight * face.height_m;
    dim.from_m = {face.x_m + (skid.rightward ? -d : d), panel.track_y_m};
    dim.to_m = {face.x_m, dim.line_at_m};
    // TRANSLATORS: d is the distance a car (or two cars locked together) skidded along the road
    // since the impact, with locked wheels.
    const std::string pattern = text::tr("skid d = {length}");
    dim.label = text::fill(pattern, {{"length", text::formatReading(d, length)}});
    panel.dimensions.push_back(std::move(dim));
  }
}

}  // namespace collide::compose
