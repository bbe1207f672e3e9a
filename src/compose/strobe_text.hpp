#pragma once
// The words of a stroboscope photograph: its time span and its caption.
#include <string>

#include "physics/timeline.hpp"
#include "text/number_format.hpp"

namespace collide::compose {

// "t = 0–2.5 s": the span from 0 to duration_s, its end with the fewest decimals (at most the
// picture's time format's) that write duration_s exactly, its start (exactly 0) as "0". A
// strobe's span is mostly the scene's whole run, a number the scene gives, so "2.500" would only
// add width to the header; where it ends at a swing's turn ("0.517"), "0.000" would too. A range
// with an en dash rather than " to ": the header is the title's line (ballistic-pendulum's title
// wrapped beside "t = 0 to 0.517 s").
std::string strobeSpanText(double duration_s, const text::QuantityFormat& time);

// "Stroboscopic image: 25 images per second (101 in all), earlier images fainter": the plural by
// a whole rate ("1 image per second"); a fractional rate as the time between images ("one image
// every 0.4 s"), which reads right in every language. `overlaps_left_out`: some images of a
// moving body were left out so that none overlaps (strobeGhosts), and the caption says so.
// `marked_gas`: a gas's strobe, which shows a few marked molecules and their paths and the rest
// of the gas once (gas_strobe.hpp); the caption says so before anything else is added.
// `impact_images`: images added at the instants of collisions, off the flashes' steps
// (strobeGhosts); the caption says how many, so no one reads their spacing as a speed.
// The first release (stored energy pushing two bodies apart) within a strobe's span, in words:
// "cart 1 and cart 2 start together at rest, pushed apart at t = 0.500 s"; text "" where there
// is none.
struct StrobeRelease {
  std::string text;
  bool from_rest = false;  // the image at the push is where they sat from the start
};
StrobeRelease strobeRelease(const physics::Timeline& timeline, double span_s,
                            const text::QuantityFormat& time);

// `release`: said after the rate, so that no one looks for an impact that did not happen;
// `release_images`: images added at the instants of releases, counted apart from the impacts'
// (not for a release from rest, whose image is where the bodies stood all along).
std::string strobeCaption(double rate_hz, int images, bool overlaps_left_out,
                          bool marked_gas = false, int impact_images = 0,
                          const StrobeRelease& release = {}, int release_images = 0);

}  // namespace collide::compose
