#pragma once
// Where a dimension line's text goes (a ballistic pendulum's rise h beside its line, and the
// notes with the speed that rise gives back): the first of a few candidate places, in order of
// preference, that the label placement finds free; decided on the frame description, never by
// reading pixels back. Placed before the bodies' labels, which then keep clear of it.
#include <functional>
#include <vector>

#include "render/frame_model.hpp"
#include "render/layout.hpp"
#include "render/text_metrics.hpp"

namespace collide::compose {

struct PixelSegment {
  core::Vec2 a, b;
};

// The lines a dimension draws (two extension lines and the dimension line), in pixels, as the
// painter draws them (render/draw_strings.cpp).
std::vector<PixelSegment> dimensionLines(const render::DimensionModel& dim,
                                         const render::FrameLayout& layout,
                                         const render::WorldToPixel& to_px);

// Sets label_at and notes_at_px of every dimension of `suspension`: the label beside its line,
// the notes in `notes_m`'s corner or another corner of `clip`, each at the first candidate
// `is_free` accepts and apart from each other. A label with no free place gives way (is
// cleared: the line still shows the height), as a crowded body's label does; notes with none stay
// unplaced (and are not drawn at this size). Returns the boxes taken, for the other labels to
// keep clear of.
std::vector<render::PixelRect> placeDimensionTexts(
    render::SuspensionModel& suspension, const render::FrameLayout& layout,
    const render::WorldToPixel& to_px, const render::PixelRect& clip, render::TextMetrics& metrics,
    const std::function<bool(const render::PixelRect&)>& is_free);

}  // namespace collide::compose
