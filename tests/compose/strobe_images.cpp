// SPDX-License-Identifier: MIT
#include "strobe_images.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace collide::strobe_images {

// Half width and half height of a body: a disk its radius, a block half its size.
core::Vec2 halfSize(const scene::BodyDesc& body) {
  const double half = body.shape == "disk" ? body.size_m : 0.5 * body.size_m;
  return {half, half};
}

// Where body i is drawn at t: in 1D on the track (centre at half its height), in 2D where it is.
core::Vec2 drawnAt(const scene::SceneDesc& scene, const physics::Timeline& timeline, std::size_t i,
                   double t_s) {
  const core::Vec2 p = timeline.sample(t_s).bodies[i].position_m;
  if (scene.dimensions == 1) return {p.x(), halfSize(scene.bodies[i]).y()};
  return p;
}

// The collisions inside (0, end_s) that a strobe pictures at their instants, from the event log:
// those between bodies; where there is none, those with walls (a ball bouncing on a floor).
std::vector<physics::CollisionEvent> picturedCollisions(const physics::Timeline& timeline,
                                                        double end_s) {
  std::vector<physics::CollisionEvent> between_bodies, with_walls;
  for (const physics::CollisionEvent& event : timeline.collisions()) {
    if (event.time_s <= 0.0 || event.time_s >= end_s) continue;
    (event.hitsWall() ? with_walls : between_bodies).push_back(event);
  }
  return between_bodies.empty() ? with_walls : between_bodies;
}

// The bodies of a collision: two, or one where its partner is a wall.
std::vector<std::size_t> bodiesOf(const physics::CollisionEvent& event) {
  std::vector<std::size_t> out{static_cast<std::size_t>(event.body_a)};
  if (!event.hitsWall()) out.push_back(static_cast<std::size_t>(event.body_b));
  return out;
}

// The instants of the pictured collisions of body i.
std::vector<double> impactsOf(const physics::Timeline& timeline, std::size_t i, double end_s) {
  std::vector<double> out;
  for (const physics::CollisionEvent& event : picturedCollisions(timeline, end_s)) {
    for (const std::size_t body : bodiesOf(event)) {
      if (body == i) out.push_back(event.time_s);
    }
  }
  return out;
}

// Overlap beyond round-off; touching is not overlapping.
bool overlap(const Image& a, const Image& b) {
  const core::Vec2 d = (a.center - b.center).cwiseAbs(), reach = a.half + b.half;
  const double slack = 1e-6 * reach.x();
  if (a.disk && b.disk) return d.norm() < reach.x() - slack;
  return d.x() < reach.x() - slack && d.y() < reach.y() - slack;
}

// The images of each body in a panel's strobe: every ghost matched to the body and flash, or
// collision of that body, whose drawn place it is (a ghost that is no body's image at any such
// instant fails the test), then the last. tagged: each ghost must carry its body's tag.
std::vector<std::vector<Image>> imagesByBody(const scene::SceneDesc& scene,
                                             const physics::Timeline& timeline,
                                             const frame::PanelModel& panel, double rate_hz,
                                             double end_s, bool tagged) {
  const std::size_t bodies = scene.bodies.size();
  const int flashes = static_cast<int>(std::floor(end_s * rate_hz + 1e-9)) + 1;
  std::vector<std::vector<core::Vec2>> places(bodies);  // [body][flash], all but the last
  for (int k = 0; k + 1 < flashes; ++k) {
    for (std::size_t i = 0; i < bodies; ++i) {
      places[i].push_back(drawnAt(scene, timeline, i, k / rate_hz));
    }
  }
  std::vector<std::vector<Image>> images(bodies);
  // A ghost is body i's at flash k where it has body i's colour (the last image's) and height
  // and stands where body i was at k / rate. (A glider's ghost is its block, its bumpers
  // drawn beside it, so its width is the ghost's own.)
  const auto sameColour = [](const frame::Rgba& a, const frame::Rgba& b) {
    return a.r == b.r && a.g == b.g && a.b == b.b;
  };
  for (const frame::BodyModel& ghost : panel.ghosts) {
    std::optional<std::pair<std::size_t, int>> match;
    for (std::size_t i = 0; i < bodies && i < panel.bodies.size() && !match; ++i) {
      const double half_height = halfSize(scene.bodies[i]).y();
      if (std::abs(ghost.half_extent_m.y() - half_height) > 1e-9 * half_height ||
          !sameColour(ghost.fill, panel.bodies[i].fill)) {
        continue;
      }
      for (int k = 0; k + 1 < flashes && !match; ++k) {
        if ((ghost.center_m - places[i][k]).norm() <= 1e-9 * (1.0 + places[i][k].norm())) {
          match = {i, k};
          images[i].push_back({ghost.center_m, ghost.half_extent_m,
                               ghost.shape == frame::BodyShape::kDisk, k, k / rate_hz,
                               "body " + std::to_string(i + 1) + " flash " + std::to_string(k),
                               ghost.over_bodies});
        }
      }
      for (const double t_s : impactsOf(timeline, i, end_s)) {
        const core::Vec2 at = drawnAt(scene, timeline, i, t_s);
        if (match || (ghost.center_m - at).norm() > 1e-9 * (1.0 + at.norm())) continue;
        match = {i, kImpact};
        images[i].push_back(
            {ghost.center_m, ghost.half_extent_m, ghost.shape == frame::BodyShape::kDisk, kImpact,
             t_s,
             "body " + std::to_string(i + 1) + " at the collision at " + std::to_string(t_s) + " s",
             ghost.over_bodies});
      }
    }
    // Numbered as its body is (a crowded scene's number inside each body), so it is told from
    // its neighbours by more than a faint colour: every image, also one a last image covers part
    // of and which is drawn over the bodies (its number then stands above it, issue 37: "every
    // faint image in a crowded strobe numbered"); untagged only where covered and not drawn over.
    const auto shape = [](const frame::BodyModel& body) {
      return Image{
          body.center_m, body.half_extent_m, body.shape == frame::BodyShape::kDisk, kLast, 0.0, {}};
    };
    bool covered = false;
    for (const frame::BodyModel& body : panel.bodies)
      covered = covered || overlap(shape(ghost), shape(body));
    if (match && tagged && (!covered || ghost.over_bodies)) {
      EXPECT_EQ(ghost.tag, panel.bodies[match->first].tag)
          << "the image of body " << match->first + 1 << " at (" << ghost.center_m.x() << ", "
          << ghost.center_m.y() << ")";
    } else if (match && tagged) {
      EXPECT_EQ(ghost.tag, "") << "a number half under body " << match->first + 1
                               << "'s last image";
    }
    EXPECT_TRUE(match.has_value())
        << "a ghost at (" << ghost.center_m.x() << ", " << ghost.center_m.y()
        << ") is no body's image at a flash or at one of its collisions";
  }
  for (std::size_t i = 0; i < bodies && i < panel.bodies.size(); ++i) {
    const frame::BodyModel& last = panel.bodies[i];
    if (last.fill.a < kFaint) continue;  // a gas's unmarked molecule: background, drawn once
    images[i].push_back({last.center_m, last.half_extent_m, last.shape == frame::BodyShape::kDisk,
                         kLast, end_s, "body " + std::to_string(i + 1) + " last"});
  }
  return images;
}

}  // namespace collide::strobe_images
