#include "compose/legend_placement.hpp"

#include <cmath>
#include <limits>

namespace collide::compose {
namespace {

constexpr double kLegendLineSpacing = 1.3;  // of the text size, as the painter draws the legend

}  // namespace

std::optional<std::vector<core::Vec2>> placeLegend(double column_px, std::size_t n,
                                                   const Obstacles& obstacles,
                                                   const render::FrameLayout& layout, double line) {
  if (n == 0) return std::nullopt;
  const double pitch = column_px + layout.text_px;  // a column and an em between columns
  const double row = kLegendLineSpacing * layout.text_px;
  const Box& clip = obstacles.clip();
  const double gap = layout.gap_px;
  const double step_x = std::max(1.0, layout.text_px), step_y = std::max(1.0, 0.5 * line);
  std::optional<core::Vec2> best_at;
  std::size_t best_columns = 0;
  double best_score = std::numeric_limits<double>::infinity();
  for (std::size_t columns = 1; columns <= n; ++columns) {
    const std::size_t rows = (n + columns - 1) / columns;
    const double w = pitch * static_cast<double>(columns) - layout.text_px;
    const double h = row * static_cast<double>(rows - 1) + line;
    // From the top-right corner leftwards and down, in steps of an em and half a line.
    for (double y = clip.y0 + gap; y + h <= clip.y1 - gap; y += step_y) {
      for (double x = clip.x1 - gap - w; x >= clip.x0 + gap; x -= step_x) {
        const double score = std::hypot(clip.x1 - (x + w), y - clip.y0) + 0.5 * gap * columns;
        if (score >= best_score) break;  // farther along this row only gets worse
        if (!obstacles.isFree({x, y, x + w, y + h})) continue;
        best_score = score;
        best_at = core::Vec2{x, y};
        best_columns = columns;
        break;
      }
    }
  }
  if (!best_at) return std::nullopt;
  std::vector<core::Vec2> at;
  for (std::size_t k = 0; k < n; ++k) {
    at.push_back(*best_at + core::Vec2{pitch * static_cast<double>(k % best_columns),
                                       row * static_cast<double>(k / best_columns)});
  }
  return at;
}

}  // namespace collide::compose
