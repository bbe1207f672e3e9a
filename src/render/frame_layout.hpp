// SPDX-License-Identifier: MIT
#pragma once
// The layout of a FrameModel as the painters draw it at a size, item by item, in pixels
// (frame/drawn_items.hpp): laid out by the painters' own code (render/draw's drawFrame) onto a
// canvas that records instead of painting. No GL, no Cairo: for `collide layout` and for tests
// that check a picture's layout without reading pixels.
#include <vector>

#include "frame/drawn_items.hpp"
#include "frame/frame_model.hpp"
#include "render/renderer_options.hpp"

namespace collide::render {

// What a Renderer of width_px × height_px (both > 0) made with `options` draws for `frame`.
// Throws FontError if a font cannot be loaded.
std::vector<frame::DrawnItem> drawnItems(const frame::FrameModel& frame, int width_px,
                                         int height_px, const RendererOptions& options = {});

}  // namespace collide::render
