#include "render/print_layout.hpp"

#include <cmath>

#include "render/layout.hpp"

namespace collide::render {
namespace {

constexpr double kCmPerInch = 2.54;

}  // namespace

PrintFrame rasterPrintFrame(const PrintSize& print) {
  return {print.width_px, print.height_px, print.dots_per_inch,
          printTextFloorPx(print.dots_per_inch)};
}

PrintFrame vectorPrintFrame(const PrintSize& print) {
  if (print.dots_per_inch >= kVectorLayoutPpi) {
    return {print.width_px, print.height_px, print.px_per_inch,
            printTextFloorPx(print.px_per_inch)};
  }
  const int width_px =
      static_cast<int>(std::lround(print.width_cm / kCmPerInch * kVectorLayoutPpi));
  const int height_px =
      static_cast<int>(std::lround(print.height_cm / kCmPerInch * kVectorLayoutPpi));
  // The page is width_cm wide exactly, and height_cm to within half a pixel.
  const double px_per_inch = width_px / (print.width_cm / kCmPerInch);
  return {width_px, height_px, px_per_inch, printTextFloorPx(px_per_inch)};
}

}  // namespace collide::render
