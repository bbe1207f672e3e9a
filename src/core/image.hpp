#pragma once
// RGBA8 images. An ImageView may run bottom-up (negative row stride) so a GL readback can be
// handed to a sink without flipping rows in memory.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace collide::core {

// Non-owning view of RGBA8 pixels, 4 bytes per pixel, straight (non-premultiplied) alpha.
struct ImageView {
  const std::uint8_t* top_row = nullptr;  // first byte of the image's top row
  int width = 0;                          // pixels
  int height = 0;                         // pixels
  std::ptrdiff_t row_stride = 0;          // bytes from one row to the row below; may be negative

  const std::uint8_t* row(int y) const { return top_row + row_stride * y; }
  const std::uint8_t* pixel(int x, int y) const { return row(y) + 4 * x; }
};

// Pixels [x0, x1) × [y0, y1) of an image, top row 0.
struct ImageRect {
  int x0 = 0, y0 = 0;
  int x1 = 0, y1 = 0;
};

// Joins rectangles that overlap into their bounding box until none do: every pixel the
// input covered is then in exactly one rectangle, so work done per rectangle is done once. (A
// moving body's regions of a few frames overlap almost wholly; their box is little more.)
void joinOverlapping(std::vector<ImageRect>& rects);

// Owning RGBA8 image stored top-down with tightly packed rows.
class Image {
 public:
  Image() = default;
  Image(int width, int height);
  // Copies any view (bottom-up or top-down) into a tightly packed top-down image.
  static Image copyOf(const ImageView& view);

  int width() const { return width_; }
  int height() const { return height_; }
  std::uint8_t* data() { return pixels_.data(); }
  const std::uint8_t* data() const { return pixels_.data(); }
  std::uint8_t* pixel(int x, int y) {
    return pixels_.data() + 4 * (static_cast<std::size_t>(y) * width_ + x);
  }
  const std::uint8_t* pixel(int x, int y) const {
    return pixels_.data() + 4 * (static_cast<std::size_t>(y) * width_ + x);
  }
  ImageView view() const { return ImageView{pixels_.data(), width_, height_, 4 * width_}; }

 private:
  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> pixels_;
};

}  // namespace collide::core
