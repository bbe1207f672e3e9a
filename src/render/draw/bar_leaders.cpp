// SPDX-License-Identifier: MIT
#include "render/draw/bar_leaders.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace collide::render {
namespace {

// Rounds of choosing ends: a few settle the legends of five or six entries.
constexpr int kRounds = 4;

double cross(const core::Vec2& a, const core::Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Whether the segments ab and cd cross or touch.
bool segmentsMeet(const core::Vec2& a, const core::Vec2& b, const core::Vec2& c,
                  const core::Vec2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) &&
      ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))) {
    return true;
  }
  const auto on = [](const core::Vec2& p, const core::Vec2& q, const core::Vec2& r) {
    return std::abs(cross(q - p, r - p)) < 1e-9 && std::min(p.x(), q.x()) <= r.x() &&
           r.x() <= std::max(p.x(), q.x()) && std::min(p.y(), q.y()) <= r.y() &&
           r.y() <= std::max(p.y(), q.y());
  };
  return on(a, b, c) || on(a, b, d) || on(c, d, a) || on(c, d, b);
}

// Whether the segment ab enters `box` grown by pad_px (Liang-Barsky clipping).
bool segmentEntersBox(const core::Vec2& a, const core::Vec2& b, const frame::PixelRect& box,
                      double pad_px) {
  const core::Vec2 d = b - a;
  double enter = 0.0, leave = 1.0;
  const double lo[2] = {box.x0 - pad_px, box.y0 - pad_px};
  const double hi[2] = {box.x1 + pad_px, box.y1 + pad_px};
  for (int k = 0; k < 2; ++k) {
    if (std::abs(d[k]) < 1e-12) {
      if (a[k] < lo[k] || a[k] > hi[k]) return false;
      continue;
    }
    double t0 = (lo[k] - a[k]) / d[k], t1 = (hi[k] - a[k]) / d[k];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
  }
  return enter < leave;
}

}  // namespace

std::vector<core::Vec2> barLeaderEnds(const std::vector<BarLeaderEntry>& entries, double clear_px) {
  // Each entry's candidate ends, the swatch first.
  std::vector<std::vector<core::Vec2>> candidates;
  for (const BarLeaderEntry& entry : entries) {
    const frame::PixelRect& box = entry.box;
    const double inset = std::min(clear_px, 0.5 * box.width());
    candidates.push_back({entry.swatch_px,
                          {std::clamp(entry.from_px.x(), box.x0 + inset, box.x1 - inset), box.y0},
                          {box.x1 - inset, box.y0},
                          {box.x0 + inset, box.y0},
                          {0.5 * (box.x0 + box.x1), box.y0}});
  }
  // Every leader at its swatch, then rounds in which each takes the first end that runs into
  // fewest other entries and other leaders as they stand, until none changes.
  std::vector<std::size_t> chosen(entries.size(), 0);
  const auto runsInto = [&](std::size_t i, const core::Vec2& end) {
    int count = 0;
    for (std::size_t j = 0; j < entries.size(); ++j) {
      if (j == i) continue;
      if (segmentEntersBox(entries[i].from_px, end, entries[j].box, clear_px)) ++count;
      if (segmentsMeet(entries[i].from_px, end, entries[j].from_px, candidates[j][chosen[j]])) {
        ++count;
      }
    }
    return count;
  };
  for (int round = 0; round < kRounds; ++round) {
    bool changed = false;
    for (std::size_t i = 0; i < entries.size(); ++i) {
      std::size_t best = 0;
      int fewest = std::numeric_limits<int>::max();
      for (std::size_t c = 0; c < candidates[i].size() && fewest > 0; ++c) {
        const int count = runsInto(i, candidates[i][c]);
        if (count < fewest) fewest = count, best = c;
      }
      changed = changed || best != chosen[i];
      chosen[i] = best;
    }
    if (!changed) break;
  }
  std::vector<core::Vec2> ends;
  for (std::size_t i = 0; i < entries.size(); ++i) ends.push_back(candidates[i][chosen[i]]);
  return ends;
}

}  // namespace collide::render
