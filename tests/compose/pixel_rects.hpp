#pragma once
// Whether frame rectangles overlap or hold one another, for the frame-description checks:
// written out plainly, independently of compose's and render's own geometry.
#include "frame/layout.hpp"

namespace collide::test {

// Whether a and b share more than `slack` pixels across and up or down (slack 0: any area).
inline bool overlaps(const frame::PixelRect& a, const frame::PixelRect& b, double slack = 0.0) {
  return a.x0 + slack < b.x1 && b.x0 + slack < a.x1 && a.y0 + slack < b.y1 && b.y0 + slack < a.y1;
}

// Whether `inner` lies within `outer`, reaching at most `slack` pixels beyond it.
inline bool inside(const frame::PixelRect& inner, const frame::PixelRect& outer, double slack) {
  return inner.x0 >= outer.x0 - slack && inner.y0 >= outer.y0 - slack &&
         inner.x1 <= outer.x1 + slack && inner.y1 <= outer.y1 + slack;
}

}  // namespace collide::test
