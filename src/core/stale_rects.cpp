#include "core/stale_rects.hpp"

namespace collide::core {

void StaleRects::note(const std::vector<ImageRect>* changed) {
  if (whole_) return;
  if (changed == nullptr) {
    markWhole();
  } else {
    rects_.insert(rects_.end(), changed->begin(), changed->end());
  }
}

const std::vector<ImageRect>* StaleRects::take() {
  const bool whole = whole_;
  taken_.swap(rects_);
  rects_.clear();
  whole_ = false;
  if (whole) return nullptr;
  // The rectangles of several frames overlap (a body moving a little each frame): each pixel
  // brought up to date once.
  joinOverlapping(taken_);
  return &taken_;
}

}  // namespace collide::core
