#pragma once
// The words and numbers on a frame: labels with subscripts and primes, readouts and the caption.
// Every number goes through text/number_format.hpp with one format per quantity for the whole
// picture (PictureFormats): energies on one frame share their unit (mJ, J, kJ), each amount shows
// three significant figures, and times keep one number of decimals.
#include <string>

#include "core/vec.hpp"
#include "text/number_format.hpp"

namespace collide::compose {

// How each quantity is written throughout one picture, chosen from its largest value there.
struct PictureFormats {
  text::QuantityFormat energy = text::quantityFormat(1.0, "J");
  text::QuantityFormat speed = text::quantityFormat(1.0, "m/s");
  text::QuantityFormat momentum = text::quantityFormat(1.0, "kg·m/s");
  text::QuantityFormat time = text::quantityFormat(1.0, "s", 4);
  text::QuantityFormat length = text::quantityFormat(1.0, "m");  // a length measured (a skid)
};

// Formats for a picture whose energies reach energy_J, speeds speed_mps, momenta momentum_Ns and
// which lasts duration_s (times are read with the decimals that give the duration four figures:
// "t = 0.000 s" to "t = 4.000 s"), and whose longest length measured is length_m (0: none).
PictureFormats pictureFormats(double energy_J, double speed_mps, double momentum_Ns,
                              double duration_s, double length_m = 0.0);

// "₁", "₁₂": a 1-based index as Unicode subscript digits.
std::string subscript(int index);
// "t = 1.167 s"; "t = 0.000 s" at the start (the picture's decimals).
std::string timeText(double t_s, const PictureFormats& formats);
// "collisions: 3", the info line's count.
std::string collisionsSoFar(int count);
// "m₁ = 1.00 kg", "m₁ = 1500 kg"; a body that feels air drag: "m₂ = 0.200 kg, with drag".
std::string massLabel(int index, double mass_kg, bool with_air_drag = false);
// 1D: "v₁ = +2.00 m/s" (signed); 2D: "v₁ = 1.50 m/s, −30°" (speed and direction, degrees
// counter-clockwise from +x). `primed` marks a velocity after a collision of that body: "v₁′".
std::string velocityLabel(int index, const core::Vec2& velocity_mps, bool primed, int dimensions,
                          const PictureFormats& formats);
// 1D: "+1.00 kg·m/s"; 2D: "(1.00, −0.50) kg·m/s".
std::string momentumText(const core::Vec2& momentum_Ns, int dimensions,
                         const PictureFormats& formats);
// A value of a panel parameter as its heading: "e = 0.5", "m₂ = 3 kg", else "key = value".
std::string panelHeading(const std::string& key, double value);

}  // namespace collide::compose
