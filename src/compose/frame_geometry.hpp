#pragma once
// Where a body is drawn: blocks stand on the track (y = 0) as squares; disks on a line rest on it;
// in 2D a body is drawn at its position. All in the drawing frame (moving at frame_velocity).
#include "core/vec.hpp"
#include "physics/timeline.hpp"
#include "scene/scene_desc.hpp"

namespace collide::compose {

inline bool isDisk(const scene::BodyDesc& body) {
  return body.shape == "disk";
}

inline bool isGlider(const scene::BodyDesc& body) {
  return body.shape == "glider";
}

// A glider's bumper at each end, uncompressed, m: part of its width size_m.
inline double bumperLength_m(const scene::BodyDesc& body) {
  constexpr double kBumperShare = 0.22;  // of the glider's width, each end
  return isGlider(body) ? kBumperShare * body.size_m : 0.0;
}

// Half width and half height of the body as it collides (a glider: bumpers included), m.
inline core::Vec2 halfExtent(const scene::BodyDesc& body) {
  const double half = isDisk(body) ? body.size_m : 0.5 * body.size_m;
  return {half, half};
}

// Centre of the drawn body at time t_s, seen from a frame moving at frame_velocity_mps (which
// coincided with the lab frame at t = 0).
inline core::Vec2 drawnCenter(const scene::SceneDesc& scene, std::size_t i,
                              const physics::BodyState& state, double t_s,
                              const core::Vec2& frame_velocity_mps) {
  const core::Vec2 shifted = state.position_m - t_s * frame_velocity_mps;
  if (scene.dimensions == 1) return {shifted.x(), halfExtent(scene.bodies[i]).y()};
  return shifted;
}

}  // namespace collide::compose
