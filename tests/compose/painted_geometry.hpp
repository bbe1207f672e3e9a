#pragma once
// What the painter draws in a panel besides text, in frame pixels, for the label checks: bodies,
// velocity arrows, and the marks text must keep clear of (walls with their hatching, contact
// flashes, strings, pivots and beams). Recomputed from the FrameModel and render's layout,
// independently of compose's own obstacle list.
#include <cstddef>
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"
#include "pixel_distances.hpp"

namespace collide::compose_test {

struct PaintedArrow {
  core::Vec2 tail, tip;
  double half_width;
  std::size_t body;
};

// A mark drawn as a thick segment (a disk when a == b): walls with their hatching, contact flashes.
struct PaintedMark {
  core::Vec2 a, b;
  double half_width;
  std::string what;
};

// Every body's outline, in the order of panel.bodies.
std::vector<PixelBody> paintedBodies(const frame::PanelModel& panel,
                                     const frame::WorldToPixel& to_px);

// The velocity arrows of the bodies that show one.
std::vector<PaintedArrow> paintedArrows(const frame::PanelModel& panel,
                                        const frame::FrameLayout& layout,
                                        const frame::WorldToPixel& to_px);

// Walls, flashes, strings, pivots and beams; `area` is the panel's world area, width_px and
// height_px the frame's size (a 2D wall reaches across all of it).
std::vector<PaintedMark> paintedMarks(const frame::PanelModel& panel,
                                      const frame::FrameLayout& layout,
                                      const frame::WorldToPixel& to_px,
                                      const frame::PixelRect& area, int width_px, int height_px);

}  // namespace collide::compose_test
