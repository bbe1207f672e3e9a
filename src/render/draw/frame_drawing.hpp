#pragma once
// Private: a FrameModel laid out and turned into canvas batches (shapes and text), no GL, no
// Cairo. The one place a frame is laid out: the GL renderer (MeshCanvas) and the vector painter
// (VectorCanvas) paint what it draws; tests inspect the batches directly.
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"
#include "render/draw/canvas.hpp"

namespace collide::render {

// Speeds at or below this draw no arrow (m/s): a body at rest, up to solver round-off.
inline constexpr double kRestSpeed_mps = 1e-6;

// Clears `canvas` and fills it with `frame` laid out by `layout` (computeFrameLayout of the
// frame's size and shapeOf(frame)).
void drawFrame(const frame::FrameModel& frame, const frame::FrameLayout& layout, Canvas& canvas);

// The pieces, each appending to the current batch (drawFrame opens the batches).
void drawPanelWorld(const frame::PanelModel& panel, const frame::FrameStyle& style,
                    const frame::PanelLayout& where, const frame::FrameLayout& layout,
                    Canvas& canvas);
void drawMomentumInset(const frame::PanelModel& panel, const frame::FrameStyle& style,
                       const frame::PanelLayout& where, const frame::FrameLayout& layout,
                       Canvas& canvas);
void drawPanelReadouts(const frame::PanelModel& panel, const frame::FrameStyle& style,
                       const frame::PanelLayout& where, const frame::FrameLayout& layout,
                       Canvas& canvas);
void drawChart(const frame::ChartModel& chart, const frame::FrameStyle& style,
               const frame::PixelRect& where, const frame::FrameLayout& layout, Canvas& canvas);
// The working of an impact, typeset (draw_working.cpp), in its place of the chart column.
void drawWorking(const frame::WorkingModel& working, const frame::FrameStyle& style,
                 const frame::PixelRect& where, const frame::FrameLayout& layout, Canvas& canvas);

// Bodies on strings (draw_strings.cpp): bars, strings and arc trails under the bodies.
void drawSuspensionUnder(const frame::SuspensionModel& suspension, const frame::FrameStyle& style,
                         const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                         ShapeSink& mesh);
// Dimension lines (draw_dimensions.cpp) and their text over the bodies, the text where compose
// placed it when `placed` (the panel was placed for this size), else beside the line and at the
// notes' corner.
void drawDimensions(const std::vector<frame::DimensionModel>& dimensions,
                    const frame::FrameStyle& style, const frame::FrameLayout& layout,
                    const frame::WorldToPixel& to_px, bool placed, Canvas& canvas);

// The calibration stick on the x ruler and the cross at the origin (draw_calibration.cpp), when
// panel.calibration asks for them: the cross under the bodies, the stick with the ruler.
void drawOriginCross(const frame::PanelModel& panel, const frame::FrameStyle& style,
                     const frame::FrameLayout& layout, const frame::WorldToPixel& to_px,
                     const frame::PixelRect& area, ShapeSink& mesh);
void drawCalibrationStick(const frame::PanelModel& panel, const frame::FrameStyle& style,
                          const frame::PanelLayout& where, const frame::FrameLayout& layout,
                          const frame::WorldToPixel& to_px, const frame::PixelRect& area,
                          Canvas& canvas);

// Shared helpers.
// A velocity arrow of `shape` (arrowShape) from tail_px along direction (pixels, y down); an
// off-scale one with a break in its shaft.
void drawArrowShape(const core::Vec2& tail_px, const core::Vec2& direction,
                    const frame::ArrowShape& shape, const frame::Rgba& color, ShapeSink& mesh);
// The layout's record of an arrow of `shape` drawn from tail_px along direction (pixels, y
// down) for `value_mps` at `scale_px_per_mps` (frame/drawn_items.hpp).
frame::DrawnArrow drawnArrow(const core::Vec2& tail_px, const core::Vec2& direction,
                             const frame::ArrowShape& shape, double value_mps,
                             double scale_px_per_mps);
frame::Rgba withAlpha(const frame::Rgba& c, double alpha_factor);
// Black or white, whichever reads better on `fill`.
frame::Rgba contrastingText(const frame::Rgba& fill);
// A tick spacing of 1, 2 or 5 × 10^k, the smallest that is at least min_step (> 0).
double niceStep(double min_step);
// "%g"-style number without trailing zeros, e.g. 0.5, 2, 1.25 (German 0,5, 2, 1,25).
std::string tickLabel(double value, const text::NumberStyle& numbers);

}  // namespace collide::render
