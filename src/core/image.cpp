#include "core/image.hpp"

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

}  // namespace collide::core
