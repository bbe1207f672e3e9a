#pragma once
// Where a copy of a frame is out of date: a buffer that keeps the pixels of a frame it was given
// earlier (a GL readback buffer, an encoder's staged frame) needs again only the rectangles drawn
// since then. Both the GL rasterizer and the encode thread keep one per buffer.
#include <vector>

#include "core/image.hpp"

namespace collide::core {

class StaleRects {
 public:
  // Notes `changed` (top row 0; nullptr: the whole frame) as drawn since the buffer was last
  // brought up to date. A buffer already stale everywhere stays so.
  void note(const std::vector<ImageRect>* changed);
  // The buffer must be brought up to date whole next time (it never was, or its pixels were
  // changed in place).
  void markWhole() {
    whole_ = true;
    rects_.clear();
  }
  // What to bring up to date now, after which the buffer counts as up to date: nullptr where the
  // whole frame, else the rectangles noted since the last take(), joined so that each pixel is in
  // one rectangle. The answer stays valid (and unchanged by note()) until the next take().
  const std::vector<ImageRect>* take();

 private:
  bool whole_ = true;  // a new buffer holds nothing yet
  std::vector<ImageRect> rects_;
  std::vector<ImageRect> taken_;  // take()'s answer
};

}  // namespace collide::core
