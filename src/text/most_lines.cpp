// SPDX-License-Identifier: MIT
#include "text/most_lines.hpp"

#include <algorithm>

namespace collide::text {
namespace {

// A video asks at a few dozen sizes and widths at most; more means the widths change from frame
// to frame, and the kept counts are let go rather than grow without end.
constexpr std::size_t kMostKept = 512;

}  // namespace

MostLines::MostLines(std::vector<std::string> texts) : texts_(std::move(texts)) {}

std::size_t MostLines::captionLines(double size_px, double caption_width_px, double scale_room_px,
                                    const TextWidth& width) const {
  const std::array<double, 3> key{size_px, caption_width_px, scale_room_px};
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto kept = counted_.find(key);
    if (kept != counted_.end()) return kept->second;
  }
  // Counted unlocked: the measure may take a lock of its own (compose's), and two threads that
  // count the same key find the same number.
  std::size_t most = 0;
  for (const std::string& text : texts_) {
    most = std::max(
        most,
        captionLinesBesideScale(text, size_px, caption_width_px, scale_room_px, width).size());
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  if (counted_.size() >= kMostKept) counted_.clear();
  counted_.emplace(key, most);
  return most;
}

}  // namespace collide::text
