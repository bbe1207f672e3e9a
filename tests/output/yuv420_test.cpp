// RGBA to Y'CbCr 4:2:0: every sample against the BT.709 limited-range value computed here in double
// precision from the definitions (Rec. ITU-R BT.709-6 items 3.2-3.5: luma weights, colour
// differences, 219 and 224 levels from 16 and around 128), with each chroma sample from the mean
// of its 2x2 pixels.
#include "output/yuv420.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace collide::output {
namespace {

struct Exact {
  double luma = 0;
  double cb = 0;
  double cr = 0;
};

// Y'CbCr of the colour (r, g, b), R'G'B' components in 0..255.
Exact bt709(double r, double g, double b) {
  const double kr = 0.2126;
  const double kb = 0.0722;
  const double e_y = (kr * r + (1 - kr - kb) * g + kb * b) / 255.0;  // E'Y in 0..1
  const double e_cb = (b / 255.0 - e_y) / 1.8556;                    // E'CB in -0.5..0.5
  const double e_cr = (r / 255.0 - e_y) / 1.5748;                    // E'CR in -0.5..0.5
  return {16 + 219 * e_y, 128 + 224 * e_cb, 128 + 224 * e_cr};
}

struct Planes {
  int width;
  int height;
  std::vector<std::uint8_t> luma, cb, cr, alpha;
  Planes(int w, int h)
      : width(w), height(h), luma(w * h), cb(w * h / 4), cr(w * h / 4), alpha(w * h) {}
  Yuv420Planes view(bool with_alpha) {
    return {luma.data(),
            width,
            cb.data(),
            width / 2,
            cr.data(),
            width / 2,
            with_alpha ? alpha.data() : nullptr,
            width};
  }
};

// An image of random colours with some pure and extreme ones in its first rows.
core::Image testImage(int width, int height) {
  core::Image image(width, height);
  std::mt19937 random(19);
  std::uniform_int_distribution<int> level(0, 255);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      for (int c = 0; c < 4; ++c) p[c] = static_cast<std::uint8_t>(level(random));
    }
  }
  const std::uint8_t pure[][3] = {{0, 0, 0},   {255, 255, 255}, {255, 0, 0},  {0, 255, 0},
                                  {0, 0, 255}, {255, 255, 0},   {0, 255, 255}};
  for (int k = 0; k < 7; ++k) {  // whole 2x2 blocks, so chroma sees the pure colour too
    for (int dy = 0; dy < 2; ++dy) {
      for (int dx = 0; dx < 2; ++dx) {
        std::uint8_t* p = image.pixel(2 * k + dx, dy);
        p[0] = pure[k][0];
        p[1] = pure[k][1];
        p[2] = pure[k][2];
      }
    }
  }
  return image;
}

// The largest distance of any sample from its exact value (rounding alone gives up to 0.5).
double worstError(const core::Image& image, const Planes& planes) {
  double worst = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      const Exact exact = bt709(p[0], p[1], p[2]);
      worst = std::max(worst, std::abs(planes.luma[y * image.width() + x] - exact.luma));
    }
  }
  for (int y = 0; y < image.height() / 2; ++y) {
    for (int x = 0; x < image.width() / 2; ++x) {
      double mean[3] = {0, 0, 0};
      for (int dy = 0; dy < 2; ++dy) {
        for (int dx = 0; dx < 2; ++dx) {
          for (int c = 0; c < 3; ++c) mean[c] += image.pixel(2 * x + dx, 2 * y + dy)[c] / 4.0;
        }
      }
      const Exact exact = bt709(mean[0], mean[1], mean[2]);
      const std::size_t at = static_cast<std::size_t>(y * image.width() / 2 + x);
      worst = std::max(worst, std::abs(planes.cb[at] - exact.cb));
      worst = std::max(worst, std::abs(planes.cr[at] - exact.cr));
    }
  }
  return worst;
}

TEST(Yuv420Test, EverySampleIsTheExactBt709ValueRounded) {
  // 1280 wide: the vectorised loops' full steps; 86: a remainder after them.
  for (const int width : {1280, 86}) {
    const core::Image image = testImage(width, 32);
    Planes planes(width, 32);
    rgbaToYuv420Bt709(image.view(), planes.view(false));
    // Half a level of rounding, and 1/50 of a level for the fixed-point weights.
    EXPECT_LE(worstError(image, planes), 0.52) << "width " << width;
  }
}

TEST(Yuv420Test, PureColoursReachTheEndsOfTheLimitedRange) {
  const core::Image image = testImage(64, 4);
  Planes planes(64, 4);
  rgbaToYuv420Bt709(image.view(), planes.view(false));
  EXPECT_EQ(planes.luma[0], 16);  // black
  EXPECT_EQ(planes.cb[0], 128);   // no colour
  EXPECT_EQ(planes.cr[0], 128);
  EXPECT_EQ(planes.luma[2], 235);  // white
  EXPECT_EQ(planes.cb[1], 128);
  EXPECT_EQ(planes.cr[2], 240);  // red: Cr at its top
  EXPECT_EQ(planes.cb[4], 240);  // blue: Cb at its top
  EXPECT_EQ(planes.cb[5], 16);   // yellow: Cb at its bottom
  EXPECT_EQ(planes.cr[6], 16);   // cyan: Cr at its bottom
}

TEST(Yuv420Test, BottomUpViewGivesUprightPlanesAndAlphaIsCopied) {
  const core::Image image = testImage(64, 16);
  Planes upright(64, 16);
  rgbaToYuv420Bt709(image.view(), upright.view(true));
  // The same picture stored upside down, seen through a view with a negative stride.
  std::vector<std::uint8_t> flipped(64 * 16 * 4);
  for (int y = 0; y < 16; ++y) {
    std::copy_n(image.pixel(0, y), 64 * 4, flipped.data() + (15 - y) * 64 * 4);
  }
  const core::ImageView bottom_up{flipped.data() + 15 * 64 * 4, 64, 16, -64 * 4};
  Planes from_bottom_up(64, 16);
  rgbaToYuv420Bt709(bottom_up, from_bottom_up.view(true));
  EXPECT_EQ(from_bottom_up.luma, upright.luma);
  EXPECT_EQ(from_bottom_up.cb, upright.cb);
  EXPECT_EQ(from_bottom_up.cr, upright.cr);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 64; ++x) {
      ASSERT_EQ(upright.alpha[y * 64 + x], image.pixel(x, y)[3]) << x << "," << y;
    }
  }
  EXPECT_EQ(from_bottom_up.alpha, upright.alpha);
}

TEST(Yuv420Test, ConvertingTheChangedRectanglesGivesTheWholeConversionOfTheNewFrame) {
  // Planes holding frame `before`, then only the rectangles in which `after` differs converted
  // again: every sample must equal `after` converted whole. Rectangles start and end on odd rows
  // and columns too (a chroma sample comes from a 2x2 block), share a block, and include a single
  // pixel, a whole row and the last column.
  const int width = 86, height = 24;
  const core::Image before = testImage(width, height);
  core::Image after = testImage(width, height);
  const std::vector<core::ImageRect> changed = {
      {3, 1, 10, 2}, {11, 5, 20, 8}, {21, 8, 22, 9}, {0, 13, 86, 16}, {79, 20, 86, 24}};
  std::mt19937 random(7);
  for (const core::ImageRect& r : changed) {
    for (int y = r.y0; y < r.y1; ++y) {
      for (int x = r.x0; x < r.x1; ++x) {
        for (int c = 0; c < 4; ++c) after.pixel(x, y)[c] = static_cast<std::uint8_t>(random());
      }
    }
  }
  Planes updated(width, height);
  rgbaToYuv420Bt709(before.view(), updated.view(true));
  rgbaToYuv420Bt709(after.view(), updated.view(true), changed);
  Planes whole(width, height);
  rgbaToYuv420Bt709(after.view(), whole.view(true));
  EXPECT_EQ(updated.luma, whole.luma);
  EXPECT_EQ(updated.cb, whole.cb);
  EXPECT_EQ(updated.cr, whole.cr);
  EXPECT_EQ(updated.alpha, whole.alpha);
  // And samples outside the widened rectangles are not written at all: planes of zeros keep them.
  Planes only_rects(width, height);
  rgbaToYuv420Bt709(after.view(), only_rects.view(false), changed);
  EXPECT_EQ(only_rects.luma[3 * width + 40], 0);   // row 3: no rectangle's block reaches it
  EXPECT_EQ(only_rects.luma[1 * width + 1], 0);    // column 1: left of the first block (2, 0)
  EXPECT_EQ(only_rects.cb[5 * width / 2 + 5], 0);  // pixel rows 10 and 11
  // Row 0 and column 2: in the first rectangle's widened blocks.
  EXPECT_EQ(only_rects.luma[2], whole.luma[2]);
  EXPECT_EQ(only_rects.cb[1], whole.cb[1]);
}

}  // namespace
}  // namespace collide::output
