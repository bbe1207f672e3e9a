#include "core/image.hpp"

#include <algorithm>
#include <cstring>

#include "core/error.hpp"

namespace collide::core {

Image::Image(int width, int height)
    : width_(width), height_(height), pixels_(static_cast<std::size_t>(width) * height * 4, 0) {
  COLLIDE_ASSERT(width >= 0 && height >= 0, "negative image size");
}

Image Image::copyOf(const ImageView& view) {
  Image image(view.width, view.height);
  const std::size_t row_bytes = static_cast<std::size_t>(view.width) * 4;
  for (int y = 0; y < view.height; ++y) {
    std::memcpy(image.pixel(0, y), view.row(y), row_bytes);
  }
  return image;
}

void joinOverlapping(std::vector<ImageRect>& rects) {
  const auto meet = [](const ImageRect& a, const ImageRect& b) {
    return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
  };
  bool joined = true;
  while (joined) {
    joined = false;
    for (std::size_t i = 0; i < rects.size(); ++i) {
      for (std::size_t j = i + 1; j < rects.size();) {
        if (meet(rects[i], rects[j])) {
          rects[i] = {std::min(rects[i].x0, rects[j].x0), std::min(rects[i].y0, rects[j].y0),
                      std::max(rects[i].x1, rects[j].x1), std::max(rects[i].y1, rects[j].y1)};
          rects.erase(rects.begin() + static_cast<std::ptrdiff_t>(j));
          joined = true;
        } else {
          ++j;
        }
      }
    }
  }
}

}  // namespace collide::core
