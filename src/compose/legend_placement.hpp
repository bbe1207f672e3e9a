#pragma once
// Where a crowded scene's legend goes: the readouts and mass labels that found no room by their
// bodies, in rows and columns in a free place of the scene, on two lines each where need be.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "compose/placement_obstacles.hpp"
#include "core/vec.hpp"
#include "frame/layout.hpp"
#include "text/text_measure.hpp"

namespace collide::compose {

// Where the lines of a legend go, widths_px[k] wide each and `line` pixels high: in rows and
// columns (filled row by row, as the bodies stand; each column as wide as its widest line, an em
// between columns) in a place of the scene that `obstacles` leaves free around each line, the one
// nearest the scene's top-right corner (a 1D scene has room above its bodies; the heading's line
// reads there), fewer columns winning ties; each line's top-left corner, in order; at most
// most_columns columns. None where no arrangement fits (or there are no lines).
// `fewest_rows`: fewer rows win ties instead (a track's scene: its bodies and their arrows' rows
// move along under the legend, and a column reaching down into those rows is in their way when
// a body comes under it, so that the legend moves).
std::optional<std::vector<core::Vec2>> placeLegend(const std::vector<double>& widths_px,
                                                   const Obstacles& obstacles,
                                                   const frame::FrameLayout& layout, double line,
                                                   std::size_t most_columns = SIZE_MAX,
                                                   bool fewest_rows = false);

// Where the lines of a legend go as one column beside `near` (the box of the bodies it names):
// above, below, right or left of it, flush with its middle or either edge, the nearest place
// that `obstacles` leaves free, at most farthest_px from it; each line's top-left corner, in
// order. None where no place that near is free. A legend by its bodies (each numbered) reads as
// theirs; one in the scene's corner, hundreds of pixels off, asks the reader to search. Right
// of them under their arrows' rows only where `under_arrows_ok` takes the lines' corners there
// (none: not there).
using LegendAccepts = std::function<bool(const std::vector<core::Vec2>&)>;
std::optional<std::vector<core::Vec2>> placeLegendNear(const std::vector<double>& widths_px,
                                                       const Obstacles& obstacles,
                                                       const frame::FrameLayout& layout,
                                                       double line, const Box& near,
                                                       double farthest_px,
                                                       const LegendAccepts& under_arrows_ok = {});

// Where a legend's line stood before: its top-left corner and its width then.
struct KeptLine {
  core::Vec2 px;
  double width_px;
};

// Where the lines of a legend go where some stood before, so that they hold still: each line
// that has a place in `wanted` there (flush with its left edge, else with its right one: its text
// grew or shrank; else, all of them kept, with its middle, else slid along its row no farther than
// its text grew, the least that fits), and each new one (none in `wanted`) in the first free place
// beside them: under a column's lowest line, over its top one, or in a new column left or right of
// them on the rows they stand on. Each line's top-left corner, in order. None where a line that
// stood before is no longer free (or nothing between it and the line under it), none stood before,
// or a new line finds no room, or none that `accepts` takes for it (new line k at a box: by its own
// body).
using LegendLineAccepts = std::function<bool(std::size_t k, const Box& box)>;
std::optional<std::vector<core::Vec2>> keepLegend(
    const std::vector<double>& widths_px, const std::vector<std::optional<KeptLine>>& wanted,
    const Obstacles& obstacles, const frame::FrameLayout& layout, double line,
    const LegendLineAccepts& accepts = {});

// A text broken in two at a space, and the widths of its lines.
struct WrappedText {
  std::string first, second;
  double first_px, second_px;
};

// Each text broken at the space that makes its wider line (the second indented by an em of
// size_px) narrowest; none where one of them has no space.
std::optional<std::vector<WrappedText>> wrapInTwo(const std::vector<std::string>& texts,
                                                  text::TextMeasure& metrics, double size_px);

}  // namespace collide::compose
