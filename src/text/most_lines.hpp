// SPDX-License-Identifier: MIT
#pragma once
// The most lines any of a few texts takes, counted once for each size and width it is asked at
// and kept: a video's caption at the widest of each of its shapes, its widest info line
// (compose/text_patterns.hpp).
// The widest caption is not always the one that breaks into the most lines (a narrower one of
// another shape may break worse), so the layout keeps the most any takes; it lays out every
// frame several times, and the painter tries a few sizes, always at the same few sizes and
// widths through a video, so each is wrapped once per video and size rather than per frame.
#include <array>
#include <cstddef>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "text/text_wrap.hpp"

namespace collide::text {

class MostLines {
 public:
  explicit MostLines(std::vector<std::string> texts);

  const std::vector<std::string>& texts() const { return texts_; }

  // The most lines captionLinesBesideScale gives any of texts() at these (0: no text). `width`
  // must measure alike in every call (the painter's measure, which the texts were made with):
  // the count is kept by size and widths alone. Safe to call from several threads.
  std::size_t captionLines(double size_px, double caption_width_px, double scale_room_px,
                           const TextWidth& width) const;
  // The most lines wrapText gives any of texts() at these (no scale arrow at the end), kept alike.
  std::size_t lines(double size_px, double width_px, const TextWidth& width) const {
    return captionLines(size_px, width_px, 0.0, width);
  }

 private:
  std::vector<std::string> texts_;
  mutable std::mutex mutex_;
  mutable std::map<std::array<double, 3>, std::size_t> counted_;
};

}  // namespace collide::text
