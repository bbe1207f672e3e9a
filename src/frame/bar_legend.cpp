// SPDX-License-Identifier: MIT
#include "frame/bar_legend.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace collide::frame {
namespace {

// Entries placed in the search for each count of rows, at most: a legend has a handful of
// entries, whose search takes a few hundred; this bounds a pathological one.
constexpr long kMostSteps = 20000;
constexpr double kSlackPx = 1e-6;

// A depth-first search over the rows of the entries, left to right, each entry as far left as
// the entries before it allow (so a row assignment that fits is found by its earliest places),
// its box moved right so its column lands on its swatch where the row's end allows.
class StaircaseSearch {
 public:
  StaircaseSearch(const std::vector<double>& widths, double size_px, double swatch_px, double x0,
                  double x1)
      : w_(widths),
        half_swatch_(0.5 * swatch_px),
        step_(kBarColumnStepEm * size_px),
        gap_(kBarFlowGapEm * size_px),
        clear_(kBarLeaderClearEm * size_px),
        x0_(x0),
        x1_(x1),
        row_(widths.size(), 0),
        left_(widths.size(), 0.0),
        column_(widths.size(), 0.0) {}

  // The staircase in `rows` rows with its leaders landing nearest their swatches, if any.
  bool search(int rows) {
    rows_ = rows;
    steps_ = 0;
    best_cost_ = std::numeric_limits<double>::infinity();
    place(0, 0.0);
    return best_cost_ < std::numeric_limits<double>::infinity();
  }
  const BarStaircase& best() const { return best_; }

 private:
  void place(std::size_t k, double cost) {
    if (++steps_ > kMostSteps || cost >= best_cost_) return;
    if (k == w_.size()) {
      best_cost_ = cost;
      best_ = {left_, column_, row_, rows_, true};
      return;
    }
    for (int r = 0; r < rows_ && best_cost_ > 0.0; ++r) {
      // The least left end and column the entries before allow.
      double least_x = x0_;
      double least_c = k > 0 ? column_[k - 1] + step_ : -std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < k; ++i) {
        if (row_[i] == r) least_x = std::max(least_x, left_[i] + w_[i] + gap_);
        // Below an entry on its left: its leader comes down right of that entry's box.
        if (r > row_[i]) least_c = std::max(least_c, left_[i] + w_[i] + clear_);
        // Above one on its left: its box starts right of that entry's leader.
        if (row_[i] > r) least_x = std::max(least_x, column_[i] + clear_);
      }
      const double x = std::max(least_x, std::min(least_c - half_swatch_, x1_ - w_[k]));
      const double c = std::max(least_c, x + half_swatch_);
      if (x + w_[k] > x1_ + kSlackPx || c > x + w_[k] - half_swatch_ + kSlackPx) continue;
      row_[k] = r;
      left_[k] = x;
      column_[k] = c;
      place(k + 1, cost + (c - x - half_swatch_));
    }
  }

  const std::vector<double>& w_;
  double half_swatch_, step_, gap_, clear_, x0_, x1_;
  std::vector<int> row_;
  std::vector<double> left_, column_;
  int rows_ = 1;
  long steps_ = 0;
  double best_cost_ = 0.0;
  BarStaircase best_;
};

}  // namespace

BarStaircase barStaircase(const std::vector<double>& widths_px, double size_px, double swatch_px,
                          double x0_px, double x1_px) {
  const int n = static_cast<int>(widths_px.size());
  if (n == 0) return {};
  StaircaseSearch search(widths_px, size_px, swatch_px, x0_px, x1_px);
  for (int rows = 1; rows <= n; ++rows) {
    if (search.search(rows)) return search.best();
  }
  // Too wide for any: a row each, the leftmost lowest, each a column step right of the one
  // before where the row's end allows.
  BarStaircase fallback;
  fallback.rows = n;
  fallback.clear = false;
  for (int k = 0; k < n; ++k) {
    const double x =
        std::max(x0_px, std::min(x0_px + k * kBarColumnStepEm * size_px, x1_px - widths_px[k]));
    fallback.x0_px.push_back(x);
    fallback.column_px.push_back(x + 0.5 * swatch_px);
    fallback.row.push_back(n - 1 - k);
  }
  return fallback;
}

}  // namespace collide::frame
