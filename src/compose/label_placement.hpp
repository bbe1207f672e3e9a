#pragma once
// Label placement: where each body's label ("m₁ = 1.00 kg") and velocity readout go in a picture
// of a given size, decided on the frame description, never by reading pixels back.
//
// Point-feature placement after Christensen, Marks & Shieber (ACM TOG 1995): every label has
// candidate boxes around its body (nearest ring first, farther rings need a leader line); a
// candidate costs its distance and, far more, any overlap with another label, a body, an arrow, a
// wall, the track, a contact flash, the ruler, the momentum inset or the frame edge, and being
// nearer another body than its own. Greedy in priority order, then rounds of local improvement.
// A label that fits nowhere gives way: crowded scenes lose it and keep the number in the body.
#include "frame/frame_model.hpp"
#include "text/text_measure.hpp"

namespace collide::compose {

// Fills BodyModel::label_at and velocity_label_at of every panel of `frame` for a
// width_px × height_px picture (both > 0) whose text is at least text_floor_px (a printed
// figure's, frame::printTextFloorPx; 0: none), and the panels' placed_for_* sizes. A label with
// no free place is cleared (its body gets its number as tag).
void placeLabels(frame::FrameModel& frame, int width_px, int height_px, text::TextMeasure& metrics,
                 double text_floor_px = 0.0);

}  // namespace collide::compose
