#pragma once
// Where a dimension line's text goes (a ballistic pendulum's rise h beside its line, and the
// notes with the speed that rise gives back; a skid's length by its line): the first of a few
// candidate places, in order of preference, that the panel's obstacles leave free; decided on the
// frame description, never by reading pixels back. Placed before the bodies' labels, which then
// keep clear of it.
#include "compose/placement_obstacles.hpp"
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"
#include "text/text_measure.hpp"

namespace collide::compose {

// Sets label_at and notes_at_px of every dimension of `panel`: the label beside its line,
// the notes in `notes_m`'s corner or another corner of the obstacles' clip, each at the first
// candidate `obstacles` leaves free (the notes, where no corner is, at the free place nearest
// `notes_m`), and adds each text placed to `obstacles`. On a screen neither is left out: a label
// with no candidate free goes to the free place nearest its line, notes with none are set smaller
// (down to the caption size) and then over the string's swing. Only a printed figure too small
// for them lets the label give way (cleared: the line still shows the height) and leaves the
// notes unplaced (not drawn at that size; the figure's caption says them).
void placeDimensionTexts(frame::PanelModel& panel, const frame::FrameLayout& layout,
                         const frame::WorldToPixel& to_px, text::TextMeasure& metrics,
                         Obstacles& obstacles);

}  // namespace collide::compose
