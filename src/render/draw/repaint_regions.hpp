#pragma once
// Private: which parts of a frame must be drawn again when the framebuffer still holds the frame
// drawn before it. A pixel's colour depends only on the primitives whose quads cover it (a shape's
// or a glyph's six vertices: nothing is drawn outside them), in the order they are drawn, each
// with its batch's clip, over the background. Outside the quads of the primitives that changed,
// old places and new, the same primitives cover a pixel in the same order, so it keeps its
// colour: drawing only the changed regions, clipped to them, gives the pixels of drawing the whole
// frame (RepaintGLTest checks that frame by frame) for a fraction of llvmpipe's clear and shading.
#include <cstddef>
#include <vector>

#include "render/draw/canvas.hpp"

namespace collide::render {

// What a MeshCanvas held, kept to compare the next frame with.
struct CanvasRecord {
  std::vector<Vertex> shapes;
  std::vector<TextVertex> text;
  std::vector<DrawBatch> batches;

  void keep(const MeshCanvas& canvas);  // copies, keeping capacity
};

// Whole-pixel rectangles inside the width_px × height_px frame (origin top-left) covering every
// pixel whose primitives differ between `before` and `now`, merged into at most `max_regions`
// (>= 1); empty if nothing changed. The whole frame if the two differ in their batches.
std::vector<frame::PixelRect> changedRegions(const CanvasRecord& before, const MeshCanvas& now,
                                             int width_px, int height_px, std::size_t max_regions);

}  // namespace collide::render
