#pragma once
// A stroboscope photograph's plan: the rate it flashes at and the images of the bodies it shows.
// FrameSource::strobeFrame draws them; this file decides them.
#include <cstddef>
#include <vector>

#include "compose/frame_builder.hpp"
#include "compose/palette.hpp"
#include "frame/frame_model.hpp"
#include "physics/timeline.hpp"
#include "scene/scene_desc.hpp"

namespace collide::compose {

// One panel's run, as the strobe sees it.
struct StrobeSubject {
  const scene::SceneDesc& scene;
  const physics::Timeline& timeline;
  const FramePlan& plan;
  const Theme& theme;
  // Only these bodies are photographed (a gas's marked molecules, gas_strobe.hpp); null: all.
  const std::vector<std::size_t>* strobed = nullptr;
};

inline constexpr int kMinStrobeImages = 6;
inline constexpr int kMaxStrobeImages = 2000;
// Collisions looked at for an image at the instant of impact (pi-blocks may log thousands).
inline constexpr std::size_t kMaxStrobeImpacts = 200;

// Flashes at t = k / rate_hz over [0, duration_s], the first at t = 0.
int strobeImageCount(double duration_s, double rate_hz);

// The time span a strobe photographs when it chooses its own rate: [0, the returned end]. The
// whole run, unless in every panel every body comes to rest for an instant after the panel's first
// collision between bodies and then moves again (a pendulum at the top of its swing): the swing
// back would retrace the images already drawn, which would all be left out (newtons-cradle kept
// no image of its swings), so the picture ends at that instant (the latest over panels) and its
// last, solid image stands where the swing turns. A gas's panel (strobed set) ends with the run.
double strobeSpan_s(const std::vector<StrobeSubject>& panels, double duration_s);

// The fastest round rate (50, 40, 25, 20, 10, 8, 5, 4, 2.5, 2, 1, 0.5, 0.25 or 0.1 per second) at
// which no body's image overlaps its next one (images of a body at rest stack into one), with at
// least kMinStrobeImages images and at most max_images; else the slowest rate that still gives
// that many. Only the bodies each panel photographs count.
double chooseStrobeRate_hz(const std::vector<StrobeSubject>& panels, double duration_s,
                           int max_images = kMaxStrobeImages);

// The collisions a strobe pictures at their instants, in time order, at most kMaxStrobeImpacts:
// those between bodies inside (0, duration_s); where there is none, those with walls (a ball
// bouncing on a floor: the bounce is what that picture is about, and a flash rarely catches it).
std::vector<const physics::CollisionEvent*> strobeImpacts(const physics::Timeline& timeline,
                                                          double duration_s);

// The earlier images of one panel (every flash but the last, whose image is the frame's solid
// bodies, `last`), in flash order, earlier ones fainter.
//
// keep_apart (the picture chose the rate): like a photograph a teacher would paste into notes,
// never a smear. Every body's last image is drawn. Then, since the flashes rarely catch the
// collision itself, the bodies of the first collision strobeImpacts pictures (two bodies, or a
// body and a wall) are drawn at the instant they meet (touching): the collision is what the
// picture is about. Then every body's first image (where it started), drawn even over a last
// image and beside its own image at the collision (partly under it), but not over the other
// body's image there. Then the pairs of
// the later collisions at their instants, in time order, then the flashes between (later bounces
// on a wall come after the flashes, whose equal steps draw each arc). Each of these
// is left out where it would overlap an image already drawn of any body at another instant
// (images of one instant may touch or press together: that is the contact). A body at
// rest is drawn once; a body coming to rest or moving slower than the rate suits shows only the
// flashes at which it has moved clear (still at equal steps of 1 / rate_hz, so spacing still
// reads as speed, only fewer). Bodies stuck together keep or leave out an image together, so
// they are spaced as one (a bullet stays inside its block).
// An image kept apart carries its body's tag (the number inside a crowded scene's bodies), where
// the panel photographs more than one body.
// Without keep_apart (the user set the rate) every flash shows every body, overlapping or not,
// and untagged (numbers on overlapping images would only pile up).
struct StrobeImages {
  std::vector<frame::BodyModel> ghosts;
  std::vector<std::size_t> ghost_bodies;  // the body each ghost is an image of
  // Some flash's image of a moving body was left out (not merely a body at rest drawn once; an
  // image at a collision's instant that gives way is none: impacts_shown counts those drawn).
  bool moving_left_out = false;
  int impacts_shown = 0;   // collisions pictured by an image at their instant (not at a flash)
  int releases_shown = 0;  // likewise releases (stored energy pushing two bodies apart)
};
StrobeImages strobeGhosts(const StrobeSubject& panel, double duration_s, double rate_hz,
                          const std::vector<frame::BodyModel>& last, bool keep_apart);

// Whether two images of one body overlap (touching is not overlapping). Disks by their distance,
// blocks by their boxes.
bool strobeImagesOverlap(const frame::BodyModel& a, const frame::BodyModel& b);

}  // namespace collide::compose
