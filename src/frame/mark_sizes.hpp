#pragma once
// Sizes of the marks the painters draw in a panel's scene, as fractions of the layout scale
// (FrameLayout::scale_px): one definition for the painters and for compose's label placement,
// which keeps text clear of these marks and so must know them exactly.
#include <array>

#include "core/vec.hpp"
#include "frame/frame_model.hpp"
#include "frame/layout.hpp"

namespace collide::frame {

inline constexpr double kWallHatchSpacing = 0.025;  // between a wall's hatch strokes
inline constexpr double kWallHatchLength = 0.022;   // a hatch stroke, on the wall's solid side
inline constexpr double kCenterOfMassRadius = 0.02;
inline constexpr double kFlashRadius = 0.06;  // a contact flash at full strength
inline constexpr double kRulerTickLength = 0.02;
inline constexpr double kRulerMinStep = 0.2;          // ruler ticks at least this far apart
inline constexpr double kInsetSize = 0.3;             // the momentum box's side
inline constexpr double kInsetMaxShare = 0.4;         // of the scene width, at most
inline constexpr double kDimensionHead = 0.018;       // a dimension line's arrowheads
inline constexpr double kExtensionOverrun = 0.012;    // extension lines past the dimension line
inline constexpr double kSupportThickness = 0.012;    // the beam strings hang from
inline constexpr double kSupportHatchLength = 0.018;  // its hatch strokes, slanted up at 45°
inline constexpr double kPivotRadius = 0.006;         // a string's pivot on the beam

// Whether `body`'s number (BodyModel::tag) fits inside it, where the painter writes it: its inner
// radius (a disk's radius, a block's smaller half side) at least 0.45 of the small text size.
bool tagFitsInside(const BodyModel& body, const FrameLayout& layout, const WorldToPixel& to_px);
// Where the painter centres body `index`'s number inside it (`center_px`: its drawn centre): at
// its centre, but in a body a rigid link holds (PanelModel::bonds) half its inner radius off it,
// away from the link, so that the link's bar (drawn centre to centre) does not strike through
// the number (stick-2d: "1" and "2" under the bar).
core::Vec2 tagCenterPx(const PanelModel& panel, std::size_t index, const core::Vec2& center_px,
                       const WorldToPixel& to_px);

// The radius of a contact flash's burst as the painter draws it, pixels.
double flashRadiusPx(const FlashModel& flash, const FrameLayout& layout, const WorldToPixel& to_px);

struct PixelSegment {
  core::Vec2 a, b;
};

// A dimension line (DimensionModel) in pixels, as the painter draws it
// (render/draw/draw_dimensions.cpp) and as compose keeps its text clear of it.
struct DimensionGeometry {
  bool horizontal = false;
  core::Vec2 from_px, to_px;  // the two measured points, where their extension lines start
  // The arrowheads' tips on the dimension line, across from from_px and to_px.
  core::Vec2 from_tip_px, to_tip_px;
  double head_px = 0.0;  // the arrowheads' length
  double thin_px = 0.0;  // thickness of the lines
  // Whether the arrowheads stand outside the tips pointing in: a length too short for both
  // inside (a skid just begun).
  bool heads_outside = false;
  // The two extension lines (from each point to a little past the dimension line), then the
  // dimension line as drawn: between the tips, or from one outside head's base to the other's.
  std::array<PixelSegment, 3> lines;
};
DimensionGeometry dimensionGeometry(const DimensionModel& dim, const FrameLayout& layout,
                                    const WorldToPixel& to_px);

// Bodies on strings as the painter draws them (render/draw/draw_strings.cpp), and as text keeps
// clear of them: a string's thickness, the box a support beam takes with its hatching above it, a
// pivot's radius; pixels.
double stringThicknessPx(const FrameLayout& layout);
PixelRect supportBoxPx(const SupportModel& support, const FrameLayout& layout,
                       const WorldToPixel& to_px);
double pivotRadiusPx(const FrameLayout& layout);

// Where a panel's ruler goes (drawRuler in render/draw/draw_ruler.cpp draws it there): its axes
// over the drawn region only (an axis with no ticks is not drawn), the horizontal one at
// x_axis_y_px (its ticks and numbers below it), a 2D panel's vertical one at y_axis_x_px (its
// ticks and numbers left of it).
struct RulerPlacement {
  RulerAxis along_x, along_y;
  double x_axis_y_px = 0.0;
  double y_axis_x_px = 0.0;
};
RulerPlacement rulerPlacement(const PanelModel& panel, const PanelLayout& where,
                              const FrameLayout& layout, const WorldToPixel& to_px,
                              const PixelRect& area);

}  // namespace collide::frame
