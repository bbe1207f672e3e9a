// Tests of the comparison itself (no GL): tolerance, counting, orientation independence.
#include "golden.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "png_io.hpp"

namespace collide::test {
namespace {

core::Image filled(int w, int h, std::uint8_t value) {
  core::Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c) image.pixel(x, y)[c] = value;
  return image;
}

TEST(GoldenCompareTest, IdenticalImagesHaveNoDifference) {
  const core::Image a = filled(8, 4, 100);
  const ImageDifference d = compareImages(a.view(), a.view(), 3);
  EXPECT_TRUE(d.same_size);
  EXPECT_EQ(d.pixels_beyond, 0);
  EXPECT_EQ(d.max_channel_diff, 0);
  EXPECT_DOUBLE_EQ(d.rms, 0.0);
}

TEST(GoldenCompareTest, CountsOnlyPixelsBeyondTolerance) {
  const core::Image a = filled(4, 4, 100);
  core::Image b = filled(4, 4, 100);
  b.pixel(0, 0)[0] = 103;  // at the tolerance: fine
  b.pixel(1, 0)[2] = 104;  // beyond it
  b.pixel(2, 3)[3] = 90;   // alpha counts too
  const ImageDifference d = compareImages(a.view(), b.view(), 3);
  EXPECT_EQ(d.pixels_beyond, 2);
  EXPECT_EQ(d.max_channel_diff, 10);
  EXPECT_NEAR(d.rms, std::sqrt((9.0 + 16.0 + 100.0) / 64.0), 1e-12);
}

TEST(GoldenCompareTest, SizeMismatchIsReported) {
  EXPECT_FALSE(compareImages(filled(4, 4, 0).view(), filled(4, 5, 0).view(), 3).same_size);
}

TEST(GoldenCompareTest, PngRoundTripKeepsBottomUpViewsUpright) {
  core::Image top_down(3, 2);
  top_down.pixel(0, 0)[0] = 255;  // red mark in the top-left corner
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) top_down.pixel(x, y)[3] = 255;
  // The same picture as a bottom-up view: rows stored in reverse, negative stride.
  core::Image reversed(3, 2);
  for (int y = 0; y < 2; ++y) std::memcpy(reversed.pixel(0, 1 - y), top_down.pixel(0, y), 12);
  const core::ImageView bottom_up{reversed.pixel(0, 1), 3, 2, -12};

  const std::string path = goldenFailureDir() + "/self_test/roundtrip.png";
  writePng(path, bottom_up);
  const core::Image back = readPng(path);
  EXPECT_EQ(compareImages(back.view(), top_down.view(), 0).pixels_beyond, 0);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace collide::test
