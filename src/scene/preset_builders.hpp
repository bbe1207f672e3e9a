#pragma once
// Internal to collide_scene: the functions that build each preset from its
// parameters.
#include <map>
#include <string>
#include <vector>

#include "scene/scene_desc.hpp"

namespace collide::scene::detail {

using Parameters = std::map<std::string, double>;

// preset_builders.cpp: what every preset is built from.

// A body with every field given (position and velocity as x, y; y = 0 in 1D).
BodyDesc body(const std::string& name, const std::string& shape, double mass_kg, double size_m,
              core::Vec2 position_m, core::Vec2 velocity_mps);

// A block on the line: its centre at x_m, moving at v_mps.
BodyDesc block(const std::string& name, double mass_kg, double width_m, double x_m, double v_mps);

// A preset's scene: 1 (on a line) or 2 (in a plane) dimensions, its name,
// title, duration and the restitution of its collisions, with `bodies`;
// everything else as SceneDesc has it.
SceneDesc presetScene(int dimensions, const std::string& name, const std::string& title,
                      double duration_s, double e, std::vector<BodyDesc> bodies = {});

// presets_1d.cpp
SceneDesc workedExample(const Parameters&);
SceneDesc elastic(const Parameters&);
SceneDesc perfectlyInelastic(const Parameters&);
SceneDesc compareRestitution(const Parameters&);
SceneDesc heavyLight(const Parameters&);
SceneDesc carCrash(const Parameters&);
SceneDesc accidentReconstruction(const Parameters&);
SceneDesc airDrag(const Parameters&);
SceneDesc clay(const Parameters&);
SceneDesc bulletBlock(const Parameters&);
SceneDesc airTrack(const Parameters&);
SceneDesc granularChain(const Parameters&);
SceneDesc softContact(const Parameters&);
SceneDesc piBlocks(const Parameters&);  // parameter "digits": 1..9

// presets_release.cpp
SceneDesc springCarts(const Parameters&);
SceneDesc recoil(const Parameters&);

// presets_strings.cpp
SceneDesc newtonsCradle(const Parameters&);  // parameter "moving": balls swung in, 1..4
SceneDesc ballisticPendulum(const Parameters&);

// presets_2d.cpp
SceneDesc bouncingBall(const Parameters&);
SceneDesc billiardsGlancing(const Parameters&);
SceneDesc billiardsBreak(const Parameters&);  // parameter "rows": rows in the rack, 1..5
SceneDesc stick2d(const Parameters&);
SceneDesc billiardsFollow(const Parameters&);
SceneDesc billiardsDraw(const Parameters&);

// presets_drag.cpp
SceneDesc airDragThrow(const Parameters&);

// preset_ideal_gas.cpp
SceneDesc idealGas(const Parameters&);  // parameter "disks": 2..1000

}  // namespace collide::scene::detail
