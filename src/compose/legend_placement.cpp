#include "compose/legend_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide::compose {
namespace {

constexpr double kLegendLineSpacing = 1.3;  // of the text size, as the painter draws the legend

// From `first` towards `last` (inclusive) in steps of `step` (its sign the direction), and
// `last` itself; none where `last` lies behind `first`.
std::vector<double> steps(double first, double last, double step) {
  std::vector<double> at;
  if ((last - first) * step < 0.0) return at;
  for (double v = first; (last - v) * step > 0.0; v += step) at.push_back(v);
  at.push_back(last);
  return at;
}

}  // namespace

std::optional<std::vector<core::Vec2>> placeLegend(double column_px, std::size_t n,
                                                   const Obstacles& obstacles,
                                                   const render::FrameLayout& layout, double line,
                                                   std::size_t most_columns) {
  if (n == 0) return std::nullopt;
  const double pitch = column_px + layout.text_px;  // a column and an em between columns
  const double row = kLegendLineSpacing * layout.text_px;
  const Box& clip = obstacles.clip();
  const double gap = layout.gap_px;
  const double step_x = std::max(1.0, layout.text_px), step_y = std::max(1.0, 0.5 * line);
  std::optional<core::Vec2> best_at;
  std::size_t best_columns = 0;
  double best_score = std::numeric_limits<double>::infinity();
  for (std::size_t columns = 1; columns <= std::min(n, most_columns); ++columns) {
    const std::size_t rows = (n + columns - 1) / columns;
    const double w = pitch * static_cast<double>(columns) - layout.text_px;
    const double h = row * static_cast<double>(rows - 1) + line;
    // From the top-right corner leftwards and down, in steps of an em and half a line, and flush
    // with the left and bottom edges (the steps can miss a free stretch there: a band under the
    // ruler's numbers).
    const std::vector<double> ys = steps(clip.y0 + gap, clip.y1 - gap - h, step_y);
    const std::vector<double> xs = steps(clip.x1 - gap - w, clip.x0 + gap, -step_x);
    for (const double y : ys) {
      for (const double x : xs) {
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

std::optional<std::vector<WrappedText>> wrapInTwo(const std::vector<std::string>& texts,
                                                  text::TextMeasure& metrics, double size_px) {
  std::vector<WrappedText> all;
  for (const std::string& text : texts) {
    std::optional<WrappedText> best;
    for (std::size_t at = text.find(' '); at != std::string::npos; at = text.find(' ', at + 1)) {
      WrappedText w{text.substr(0, at), text.substr(at + 1), 0.0, 0.0};
      if (w.first.empty() || w.second.empty()) continue;
      w.first_px = metrics.width(w.first, size_px);
      w.second_px = metrics.width(w.second, size_px);
      if (!best || std::max(w.first_px, size_px + w.second_px) <
                       std::max(best->first_px, size_px + best->second_px)) {
        best = w;
      }
    }
    if (!best) return std::nullopt;
    all.push_back(*best);
  }
  return all;
}

}  // namespace collide::compose
