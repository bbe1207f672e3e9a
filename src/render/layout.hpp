#pragma once
// Where things go in a frame, in pixels. Public so tests (and later the text layer) can compute
// exactly where the renderer draws, e.g. the energy bar's segment boundaries.
//
// Pixel coordinates: origin at the top-left corner of the image, x to the right, y downwards, one
// unit per pixel; pixel (i, j) covers [i, i+1) × [j, j+1). Every size is a fraction of the frame
// height, so 640×360 and 3840×2160 show the same picture (to within a pixel of rounding).
#include <vector>

#include "core/vec.hpp"
#include "render/frame_model.hpp"

namespace collide::render {

struct PixelRect {
  double x0 = 0.0, y0 = 0.0;  // top-left corner, pixels
  double x1 = 0.0, y1 = 0.0;  // bottom-right corner, pixels; x1 >= x0, y1 >= y0
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

struct FrameLayout {
  int width_px = 0;
  int height_px = 0;
  PixelRect scene;            // the world is fitted into this area (upper part of the frame)
  int world_clip_y1_px = 0;   // track, bodies and arrows are clipped to rows [0, this)
  PixelRect bar_outer;        // outer edge of the energy bar's frame; whole pixels
  PixelRect bar_inner;        // inside of the frame: full_scale_J spans its width; whole pixels
  double bar_frame_px = 0;    // thickness of the bar's frame (whole pixels, >= 1)
  double outline_px = 0;      // body outline thickness
  double track_px = 0;        // track line thickness; the line lies just below track_y_m
  double arrow_gap_px = 0;    // from a body's top to its arrow's centre line
  double arrow_shaft_px = 0;  // shaft thickness
  double arrow_head_length_px = 0;  // along the arrow
  double arrow_head_width_px = 0;   // across the arrow, full width
};

// The layout of a width_px × height_px frame (both > 0).
FrameLayout computeFrameLayout(int width_px, int height_px);

// Uniform world → pixel mapping: metres stay square, the view window is centred in the scene area
// and as large as fits. World y points up, pixel y down.
struct WorldToPixel {
  double px_per_m = 1.0;
  core::Vec2 origin_px = {0.0, 0.0};  // pixel position of the world origin

  core::Vec2 toPixel(const core::Vec2& world_m) const {
    return {origin_px.x() + px_per_m * world_m.x(), origin_px.y() - px_per_m * world_m.y()};
  }
};

// Fits `view` into `area`. A degenerate view (zero width or height) fits by its other side.
WorldToPixel fitView(const ViewWindow& view, const PixelRect& area);

// The x positions (pixels) of the energy bar's segment boundaries inside `inner`: element 0 is
// inner.x0 and element i+1 = inner.x0 + inner.width() · (E_0 + … + E_i) / full_scale_J, clamped to
// [inner.x0, inner.x1]; negative energies count as 0. Size = segments + 1. Segment i is drawn over
// [edges[i], edges[i+1]] × [inner.y0, inner.y1].
std::vector<double> barSegmentEdgesPx(const EnergyBar& bar, const PixelRect& inner);

}  // namespace collide::render
