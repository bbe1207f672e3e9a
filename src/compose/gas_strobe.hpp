#pragma once
// The stroboscope photograph of a gas (gas_view.hpp). Every molecule's image at every flash is a
// field of overlapping dots that teaches nothing; a textbook marks a few molecules instead and
// shows each one's images along its zig-zag path (straight between collisions, a corner at each),
// with the rest of the gas drawn once, faint, where it is at the end: the picture shows the mean
// free path, the random walk and speeds changing at every collision.
#include <cstddef>
#include <vector>

#include "compose/frame_builder.hpp"
#include "compose/palette.hpp"
#include "core/vec.hpp"
#include "frame/frame_model.hpp"
#include "physics/timeline.hpp"
#include "scene/scene_desc.hpp"

namespace collide::compose {

inline constexpr std::size_t kMarkedMolecules = 3;
// At most this many images of each marked molecule: enough flashes that the images show speed
// changing along the path, few enough that a path of a hundred corners stays readable.
inline constexpr int kGasStrobeMaxImages = 101;

// The marked molecules, in order: the ones that start nearest the middles of the left, middle and
// right thirds of the region the gas starts in, so their paths begin apart.
std::vector<std::size_t> markedMolecules(const physics::Timeline& timeline);

// Body i's path over [0, end_s] in the drawing frame: its centre at the start, at each of its
// collisions (the corners of the zig-zag), at most step_s apart between them, and at the end.
std::vector<core::Vec2> moleculePath(const scene::SceneDesc& scene,
                                     const physics::Timeline& timeline, const FramePlan& plan,
                                     std::size_t body, double end_s, double step_s);

// The colour of marked molecule k: the theme's body colours in turn.
frame::Rgba markedColour(const Theme& theme, std::size_t k);

// Opacity of the rest of the gas, drawn once at the end.
inline constexpr float kGasBackgroundAlpha = 0.3f;

// The strobe's last frame of a gas: marked molecule k solid in markedColour(k) with its path as
// its trail, every other molecule in the theme's gray at kGasBackgroundAlpha.
void markGasStrobe(frame::PanelModel& panel, const std::vector<std::size_t>& marked,
                   const scene::SceneDesc& scene, const physics::Timeline& timeline,
                   const FramePlan& plan, const Theme& theme, double end_s);

}  // namespace collide::compose
