#pragma once
// Colours used for bodies and the energy bar. Okabe–Ito hues: distinguishable with the common forms
// of colour-vision deficiency; blue and orange are bodies 1 and 2, gray is energy lost.
#include <cstddef>

#include "render/frame_model.hpp"
#include "scene/scene_desc.hpp"

namespace collide::app {

render::Rgba bodyColor(std::size_t index, const scene::BodyDesc& body);
render::Rgba lostEnergyColor();

}  // namespace collide::app
