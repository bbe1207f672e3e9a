#pragma once
// Themes: the colours of a frame. Bodies take Okabe–Ito hues, distinguishable with the common forms
// of colour-vision deficiency (blue and orange are bodies 1 and 2); gray is energy lost. Every
// colour also carries a text label in the picture, so colour is never the only cue.
#include <cstddef>
#include <string>
#include <vector>

#include "frame/frame_model.hpp"
#include "scene/scene_desc.hpp"

namespace collide::compose {

struct Theme {
  std::string name;
  frame::FrameStyle style;
  std::vector<frame::Rgba> bodies;  // cycled by body index
  frame::Rgba lost;                 // energy lost (bar and chart)
  frame::Rgba potential;            // potential energy (bar and chart), with gravity
  frame::Rgba spring;               // energy stored in a compressed soft contact
  frame::Rgba total;                // chart: total kinetic energy
  // Energy released from a store (a spring let go, a shot, e > 1): told apart from the blue,
  // orange and gray beside it also with each kind of colour blindness (palette_test.cpp).
  frame::Rgba released;
  // What sliding friction took (heat in the surface): a gray of its own lightness beside the
  // loss's.
  frame::Rgba surface;
  // The energy chart's dashed equipartition levels (molecules with insides): a green told apart
  // from the total's black (white), the internal energy's pink and the loss's gray beside it.
  frame::Rgba equipartition;
  // What air drag took: a violet far from the bodies' colours, the grays and the sky blue of
  // potential energy in every kind of colour vision.
  frame::Rgba air;
};

// "light" (default), "dark", "high-contrast".
const std::vector<std::string>& themeNames();
// Throws core::InputError naming the value and the allowed names. `what` names the option or key.
const Theme& themeNamed(const std::string& name, const std::string& what = "--theme");

frame::Rgba bodyColor(const Theme& theme, std::size_t index, const scene::BodyDesc& body);

}  // namespace collide::compose
