// SPDX-License-Identifier: MIT
#pragma once
// A strobe's images read back from its frame description, each matched to its body and instant
// (a flash, or a collision of that body) from the Timeline, independently of compose: what
// strobe_spacing_test.cpp and strobe_gas_test.cpp share.
#include <cstddef>
#include <string>
#include <vector>

#include "frame/frame_model.hpp"
#include "physics/timeline.hpp"
#include "scene/scene_desc.hpp"

namespace collide::strobe_images {

// Half width and half height of a body: a disk its radius, a block half its size.
core::Vec2 halfSize(const scene::BodyDesc& body);

// Where body i is drawn at t: in 1D on the track (centre at half its height), in 2D where it is.
core::Vec2 drawnAt(const scene::SceneDesc& scene, const physics::Timeline& timeline, std::size_t i,
                   double t_s);

struct Image {
  core::Vec2 center, half;
  bool disk;
  int flash;         // k: taken at t = k / rate; kLast: the last, solid image; kImpact: a collision
  double t_s;        // when it was taken (the last image: the end of the run)
  std::string what;  // "body 2 flash 3", "body 2 at the collision at 0.68 s" or "body 2 last"
  bool over = false;  // drawn over the bodies (it lies on a last image, which would hide it)
};
inline constexpr int kLast = -1;
inline constexpr int kImpact = -2;

// The collisions inside (0, end_s) that a strobe pictures at their instants, from the event log:
// those between bodies; where there is none, those with walls (a ball bouncing on a floor).
std::vector<physics::CollisionEvent> picturedCollisions(const physics::Timeline& timeline,
                                                        double end_s);

// The bodies of a collision: two, or one where its partner is a wall.
std::vector<std::size_t> bodiesOf(const physics::CollisionEvent& event);

// The instants of the pictured collisions of body i.
std::vector<double> impactsOf(const physics::Timeline& timeline, std::size_t i, double end_s);
// A last image fainter than this is background, not a photographed body (the rest of a gas).
inline constexpr float kFaint = 0.5f;
// A strobe of more bodies than this photographs a few marked ones (a gas), not every collision.
inline constexpr std::size_t kFewBodies = 100;

// Overlap beyond round-off; touching is not overlapping.
bool overlap(const Image& a, const Image& b);

// The images of each body in a panel's strobe: every ghost matched to the body and flash, or
// collision of that body, whose drawn place it is (a ghost that is no body's image at any such
// instant fails the test), then the last. tagged: each ghost must carry its body's tag.
std::vector<std::vector<Image>> imagesByBody(const scene::SceneDesc& scene,
                                             const physics::Timeline& timeline,
                                             const frame::PanelModel& panel, double rate_hz,
                                             double end_s, bool tagged = false);

}  // namespace collide::strobe_images
