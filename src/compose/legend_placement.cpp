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

// Whether nothing runs between two lines of a legend one over the other in a column (as
// placeLegend keeps free): the room between them, as wide as the narrower.
bool roomBetweenFree(const std::vector<Box>& lines, const Obstacles& obstacles, double row) {
  constexpr double kSameColumnPx = 0.5;
  for (const Box& a : lines) {
    for (const Box& b : lines) {
      const bool one_column =
          std::abs(a.x0 - b.x0) <= kSameColumnPx || std::abs(a.x1 - b.x1) <= kSameColumnPx;
      if (!one_column || std::abs(b.y0 - a.y0 - row) > kSameColumnPx) continue;
      const Box between{std::max(a.x0, b.x0), a.y1, std::min(a.x1, b.x1), b.y0};
      if (between.y1 > between.y0 && !obstacles.isFree(between)) return false;
    }
  }
  return true;
}

// Whether `lines` stand as one legend of widths_px's lines would: no farther apart than its
// rows and columns take (a line kept from a legend listed long before stands elsewhere).
bool oneLegend(const std::vector<Box>& lines, const std::vector<double>& widths_px, double row,
               double em) {
  constexpr double kRoundingPx = 0.5;
  double top = lines.front().y0, bottom = top, left = lines.front().x0, right = lines.front().x1;
  for (const Box& b : lines) {
    top = std::min(top, b.y0);
    bottom = std::max(bottom, b.y0);
    left = std::min(left, b.x0);
    right = std::max(right, b.x1);
  }
  double across = 0.0;
  for (const double w : widths_px) across += w + em;
  const double n = static_cast<double>(widths_px.size());
  return bottom - top <= (n - 1.0) * row + kRoundingPx && right - left <= across + kRoundingPx;
}

// The places beside `lines` (placed before, flush with their columns' left edges or, `flush_right`,
// their right ones) where a new line `width_px` wide may go, in the order keepLegend tries them.
std::vector<core::Vec2> besideLegend(const std::vector<Box>& lines, double width_px, double row,
                                     double em, bool flush_right) {
  double top = lines.front().y0, bottom = top, left = lines.front().x0, right = lines.front().x1;
  std::vector<double> columns;  // their flush edges
  for (const Box& b : lines) {
    top = std::min(top, b.y0);
    bottom = std::max(bottom, b.y0);
    left = std::min(left, b.x0);
    right = std::max(right, b.x1);
    const double edge = flush_right ? b.x1 : b.x0;
    if (std::find(columns.begin(), columns.end(), edge) == columns.end()) columns.push_back(edge);
  }
  std::sort(columns.begin(), columns.end());
  const int rows = static_cast<int>(std::lround((bottom - top) / row)) + 1;
  // First the legend's free cells in reading order, row by row and the row under it: a line
  // that joins (or comes back) stands where a legend placed afresh would list it, by its body's
  // number, not under the first column (a row of a track's legend, filled as its lines join).
  std::vector<core::Vec2> places;
  for (int r = 0; r <= rows; ++r) {
    for (const double edge : columns) {
      places.push_back({flush_right ? edge - width_px : edge, top + row * r});
    }
  }
  for (const double edge : columns) {
    double lowest = -std::numeric_limits<double>::infinity();
    double highest = std::numeric_limits<double>::infinity();
    for (const Box& b : lines) {
      if ((flush_right ? b.x1 : b.x0) != edge) continue;
      lowest = std::max(lowest, b.y0);
      highest = std::min(highest, b.y0);
    }
    const double x = flush_right ? edge - width_px : edge;
    places.push_back({x, lowest + row});
    places.push_back({x, highest - row});
  }
  for (const double x : {left - em - width_px, right + em}) {
    for (int r = 0; r < rows; ++r) places.push_back({x, top + row * r});
  }
  return places;
}

// keepLegend with each line kept flush with the left edge it had or, `flush_right`, its right
// edge (a line whose text grew or shrank at an event: "v₂ = 0 m/s" to "v₂′ = +1.50 m/s"), or,
// `centred`, its middle (no new line: a new one takes a column's flush edge).
std::optional<std::vector<core::Vec2>> keepFlush(const std::vector<double>& widths_px,
                                                 const std::vector<std::optional<KeptLine>>& wanted,
                                                 const Obstacles& obstacles,
                                                 const frame::FrameLayout& layout, double line,
                                                 bool flush_right, bool centred,
                                                 const LegendLineAccepts& accepts) {
  const std::size_t n = widths_px.size();
  if (centred && std::any_of(wanted.begin(), wanted.end(), [](const auto& w) { return !w; })) {
    return std::nullopt;
  }
  const double row = kLegendLineSpacing * layout.text_px;
  const auto boxAt = [&](const core::Vec2& at, std::size_t k) {
    return Box{at.x(), at.y(), at.x() + widths_px[k], at.y() + line};
  };
  // Each placed line an obstacle to the next, so that new lines keep the gaps between texts.
  Obstacles with_lines = obstacles;
  std::vector<Box> lines;
  std::vector<core::Vec2> at(n, core::Vec2{0.0, 0.0});
  for (std::size_t k = 0; k < n; ++k) {
    if (!wanted[k]) continue;
    const double kept_share = centred ? 0.5 : (flush_right ? 1.0 : 0.0);
    const double grew_px = kept_share * (widths_px[k] - wanted[k]->width_px);
    at[k] = wanted[k]->px - core::Vec2{grew_px, 0.0};
    const Box box = boxAt(at[k], k);
    if (!with_lines.isFree(box)) return std::nullopt;
    lines.push_back(box);
    with_lines.addText(box);
  }
  if (lines.empty() || !oneLegend(lines, widths_px, row, layout.text_px)) return std::nullopt;
  for (std::size_t k = 0; k < n; ++k) {
    if (wanted[k]) continue;
    bool found = false;
    for (const core::Vec2& place :
         besideLegend(lines, widths_px[k], row, layout.text_px, flush_right)) {
      if (!with_lines.isFree(boxAt(place, k))) continue;
      if (accepts && !accepts(k, boxAt(place, k))) continue;
      at[k] = place;
      lines.push_back(boxAt(place, k));
      with_lines.addText(lines.back());
      found = true;
      break;
    }
    if (!found) return std::nullopt;
  }
  if (!roomBetweenFree(lines, obstacles, row)) return std::nullopt;
  return at;
}

// The width of column c of a legend of `columns`: as wide as its widest line or, `evenly`, as
// the widest line of all (a row of a track's legend, so that a line whose number grows at an
// event, "+1.21" to "+0.424", keeps its left edge where the row's last stands by the scene's
// edge).
double columnWidth(const std::vector<double>& widths_px, std::size_t columns, std::size_t c,
                   bool evenly) {
  const std::vector<double> column_w = frame::legendColumnWidths(widths_px, columns);
  return evenly ? *std::max_element(column_w.begin(), column_w.end()) : column_w[c];
}

// Each column's left edge from the legend's, an em between columns.
std::vector<double> columnsAt(const std::vector<double>& widths_px, std::size_t columns, double em,
                              bool evenly) {
  std::vector<double> column_x(columns, 0.0);
  for (std::size_t c = 1; c < columns; ++c) {
    column_x[c] = column_x[c - 1] + columnWidth(widths_px, columns, c - 1, evenly) + em;
  }
  return column_x;
}

// keepLegend's last try for lines that all stood before, one of which grew where its middle no
// longer fits (ballistic-pendulum 640x360: "v₁′ = v₂′ = 0.0477 m/s, −143°" between the ruler and
// the notes that come at the top of the swing): the legend slides along its rows, the least it
// can, as far as the line grew at most, rather than leave for the bodies and come back.
std::optional<std::vector<core::Vec2>> slideAlong(
    const std::vector<double>& widths_px, const std::vector<std::optional<KeptLine>>& wanted,
    const Obstacles& obstacles, const frame::FrameLayout& layout, double line,
    const LegendLineAccepts& accepts) {
  double grew_px = 0.0;
  for (std::size_t k = 0; k < wanted.size(); ++k) {
    if (!wanted[k]) return std::nullopt;
    grew_px = std::max(grew_px, widths_px[k] - wanted[k]->width_px);
  }
  constexpr double kStepPx = 1.0;
  for (double slide_px = kStepPx; slide_px <= grew_px; slide_px += kStepPx) {
    for (const double sign : {-1.0, 1.0}) {
      std::vector<std::optional<KeptLine>> slid = wanted;
      for (auto& kept : slid) kept->px += core::Vec2{sign * slide_px, 0.0};
      if (auto at = keepFlush(widths_px, slid, obstacles, layout, line, false, true, accepts)) {
        return at;
      }
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::vector<core::Vec2>> keepLegend(
    const std::vector<double>& widths_px, const std::vector<std::optional<KeptLine>>& wanted,
    const Obstacles& obstacles, const frame::FrameLayout& layout, double line,
    const LegendLineAccepts& accepts) {
  if (widths_px.empty() || wanted.size() != widths_px.size()) return std::nullopt;
  if (auto left = keepFlush(widths_px, wanted, obstacles, layout, line, false, false, accepts)) {
    return left;
  }
  if (auto right = keepFlush(widths_px, wanted, obstacles, layout, line, true, false, accepts)) {
    return right;
  }
  // Neither edge free for a line that grew (ballistic-pendulum's readout by the panel's top left
  // corner, a digit wider at the top of the swing): its middle stays, where the eye reads it.
  if (auto middle = keepFlush(widths_px, wanted, obstacles, layout, line, false, true, accepts)) {
    return middle;
  }
  return slideAlong(widths_px, wanted, obstacles, layout, line, accepts);
}

std::optional<std::vector<core::Vec2>> placeLegend(const std::vector<double>& widths_px,
                                                   const Obstacles& obstacles,
                                                   const frame::FrameLayout& layout, double line,
                                                   std::size_t most_columns, bool fewest_rows) {
  const std::size_t n = widths_px.size();
  if (n == 0) return std::nullopt;
  const double em = layout.text_px;  // between columns
  const double row = kLegendLineSpacing * layout.text_px;
  const Box& clip = obstacles.clip();
  const double gap = layout.gap_px;
  // A gap inside the scene's edges, but no farther in than the frame's margin (the title's,
  // label_scene.cpp) where the clip reaches it: that margin is room enough from the frame's edge.
  // `edge`: the clip's, `from_frame`: its distance from the frame's edge, `in`: inwards (+1/-1).
  const double margin = layout.header.x0;
  const auto inside = [&](double edge, double from_frame, double in) {
    return from_frame > margin ? edge + in * gap
                               : edge + in * std::min(gap, std::max(0.0, margin - from_frame));
  };
  const Box inner{inside(clip.x0, clip.x0, 1.0), inside(clip.y0, clip.y0, 1.0),
                  inside(clip.x1, layout.width_px - clip.x1, -1.0),
                  inside(clip.y1, layout.height_px - clip.y1, -1.0)};
  const double step_x = std::max(1.0, layout.text_px), step_y = std::max(1.0, 0.5 * line);
  std::optional<core::Vec2> best_at;
  std::vector<double> best_column_x;
  std::size_t best_columns = 0;
  double best_score = std::numeric_limits<double>::infinity();
  for (std::size_t columns = 1; columns <= std::min(n, most_columns); ++columns) {
    const std::size_t rows = (n + columns - 1) / columns;
    const std::vector<double> column_x = columnsAt(widths_px, columns, em, fewest_rows);
    const double w = column_x.back() + columnWidth(widths_px, columns, columns - 1, fewest_rows);
    const double h = row * static_cast<double>(rows - 1) + line;
    // What must be free, from the legend's top-left corner: each line's own box (a short line
    // leaves room beside it, as a long readout beside the next label's leader) and the room
    // between it and the line under it, as wide as both, so that nothing runs between them.
    std::vector<Box> free;
    for (std::size_t k = 0; k < n; ++k) {
      const double x = column_x[k % columns], y = row * static_cast<double>(k / columns);
      const bool below = k + columns < n;
      const double wk = below ? std::min(widths_px[k], widths_px[k + columns]) : widths_px[k];
      free.push_back({x, y, x + widths_px[k], y + line});
      if (below) free.push_back({x, y, x + wk, y + row + line});
    }
    // From the top-right corner leftwards and down, in steps of an em and half a line, and flush
    // with the left and bottom edges (the steps can miss a free stretch there: a band under the
    // ruler's numbers).
    const std::vector<double> ys = steps(inner.y0, inner.y1 - h, step_y);
    const std::vector<double> xs = steps(inner.x1 - w, inner.x0, -step_x);
    for (const double y : ys) {
      for (const double x : xs) {
        const double score = std::hypot(clip.x1 - (x + w), y - clip.y0) +
                             0.5 * gap * static_cast<double>(fewest_rows ? rows : columns);
        if (score >= best_score) break;  // farther along this row only gets worse
        const bool all_free = std::all_of(free.begin(), free.end(), [&](const Box& b) {
          return obstacles.isFree({x + b.x0, y + b.y0, x + b.x1, y + b.y1});
        });
        if (!all_free) continue;
        best_score = score;
        best_at = core::Vec2{x, y};
        best_column_x = column_x;
        best_columns = columns;
        break;
      }
    }
  }
  if (!best_at) return std::nullopt;
  std::vector<core::Vec2> at;
  for (std::size_t k = 0; k < n; ++k) {
    at.push_back(*best_at + core::Vec2{best_column_x[k % best_columns],
                                       row * static_cast<double>(k / best_columns)});
  }
  return at;
}

std::optional<std::vector<core::Vec2>> placeLegendNear(const std::vector<double>& widths_px,
                                                       const Obstacles& obstacles,
                                                       const frame::FrameLayout& layout,
                                                       double line, const Box& near,
                                                       double farthest_px,
                                                       const LegendAccepts& under_arrows_ok) {
  // The place right of the bodies with its foot a gap above theirs (places[kUnderArrows]): under
  // the rows their arrows take, whose reach changes as a body turns at a wall (its arrow drawn
  // back from the wall, then from its centre), so that a legend there holds through the turn.
  constexpr std::size_t kUnderArrows = 6;
  const std::size_t n = widths_px.size();
  if (n == 0) return std::nullopt;
  const double row = kLegendLineSpacing * layout.text_px;
  const double w = *std::max_element(widths_px.begin(), widths_px.end());
  const double h = row * static_cast<double>(n - 1) + line;
  // Each line's box and the room between it and the next, as placeLegend keeps free.
  std::vector<Box> free;
  for (std::size_t k = 0; k < n; ++k) {
    const double y = row * static_cast<double>(k);
    free.push_back({0.0, y, widths_px[k], y + line});
    if (k + 1 < n)
      free.push_back({0.0, y, std::min(widths_px[k], widths_px[k + 1]), y + row + line});
  }
  // A region (the ruler and its numbers) or another body between the bodies and a place: the
  // legend there reads as the ruler's or that body's, not theirs.
  const auto acrossSomething = [&](const core::Vec2& at) {
    const Box legend{at.x(), at.y(), at.x() + w, at.y() + h};
    const Box both{std::min(near.x0, legend.x0), std::min(near.y0, legend.y0),
                   std::max(near.x1, legend.x1), std::max(near.y1, legend.y1)};
    const double from_y = std::min(near.y1, legend.y1), to_y = std::max(near.y0, legend.y0);
    const double from_x = std::min(near.x1, legend.x1), to_x = std::max(near.x0, legend.x0);
    const auto between = [&](const Box& r) {
      return (from_y <= r.y0 && r.y1 <= to_y && r.x0 < both.x1 && both.x0 < r.x1) ||
             (from_x <= r.x0 && r.x1 <= to_x && r.y0 < both.y1 && both.y0 < r.y1);
    };
    return std::any_of(obstacles.regions().begin(), obstacles.regions().end(), between) ||
           std::any_of(obstacles.bodies().begin(), obstacles.bodies().end(),
                       [&](const BodyOutline& body) { return between(body.bounds); });
  };
  const auto isFree = [&](const core::Vec2& at) {
    if (acrossSomething(at)) return false;
    return std::all_of(free.begin(), free.end(), [&](const Box& b) {
      return obstacles.isFree({at.x() + b.x0, at.y() + b.y0, at.x() + b.x1, at.y() + b.y1});
    });
  };
  const core::Vec2 mid = near.center();
  const double step = std::max(1.0, 0.25 * line);
  for (double d = layout.gap_px; d <= farthest_px; d += step) {
    const std::vector<core::Vec2> places{{mid.x() - 0.5 * w, near.y0 - d - h},
                                         {near.x0, near.y0 - d - h},
                                         {near.x1 - w, near.y0 - d - h},
                                         {mid.x() - 0.5 * w, near.y1 + d},
                                         {near.x0, near.y1 + d},
                                         {near.x1 - w, near.y1 + d},
                                         {near.x1 + d, near.y1 - layout.gap_px - h},
                                         {near.x1 + d, mid.y() - 0.5 * h},
                                         {near.x1 + d, near.y0},
                                         {near.x1 + d, near.y1 - h},
                                         {near.x0 - d - w, mid.y() - 0.5 * h},
                                         {near.x0 - d - w, near.y0},
                                         {near.x0 - d - w, near.y1 - h}};
    for (std::size_t p = 0; p < places.size(); ++p) {
      const bool under_arrows = p == kUnderArrows;
      if ((under_arrows && !under_arrows_ok) || !isFree(places[p])) continue;
      std::vector<core::Vec2> corners;
      for (std::size_t k = 0; k < n; ++k) corners.push_back(places[p] + core::Vec2{0.0, row * k});
      if (under_arrows && !under_arrows_ok(corners)) continue;
      return corners;
    }
  }
  return std::nullopt;
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
