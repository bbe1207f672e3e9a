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

// Small differences on a few dozen pixels pass; one more pixel fails.
TEST(GoldenJudgeTest, AFewDozenSlightlyDifferentPixelsPassAndOneMoreFails) {
  const core::Image expected = filled(40, 20, 100);
  core::Image actual = filled(40, 20, 100);
  GoldenOptions options;
  for (long i = 0; i < options.max_pixels_beyond; ++i)
    actual.pixel(int(i % 40), int(i / 40))[1] = 110;
  EXPECT_TRUE(judgeImages(actual.view(), expected.view(), options));
  actual.pixel(39, 19)[1] = 110;
  const ::testing::AssertionResult verdict = judgeImages(actual.view(), expected.view(), options);
  EXPECT_FALSE(verdict);
  EXPECT_NE(std::string(verdict.message())
                .find(std::to_string(options.max_pixels_beyond + 1) +
                      " px differ by more than 3/255 (cap"),
            std::string::npos)
      << verdict.message();
}

// A single pixel past the gross tolerance fails, and the message says where it is.
TEST(GoldenJudgeTest, OnePixelFarOffFailsAndIsLocated) {
  const core::Image expected = filled(40, 20, 255);
  core::Image actual = filled(40, 20, 255);
  actual.pixel(7, 5)[0] = 255 - 49;
  const ::testing::AssertionResult verdict = judgeImages(actual.view(), expected.view());
  EXPECT_FALSE(verdict);
  EXPECT_NE(std::string(verdict.message())
                .find("1 px differ by more than 48/255 (none allowed) "
                      "within x 7..7, y 5..5"),
            std::string::npos)
      << verdict.message();
  actual.pixel(7, 5)[0] = 255 - 48;  // at the gross tolerance: one pixel beyond 3/255, fine
  EXPECT_TRUE(judgeImages(actual.view(), expected.view()));
}

// An allowance admits far-off pixels inside its rectangle up to its own cap, and nowhere else.
TEST(GoldenJudgeTest, AnAllowanceCoversItsRectangleUpToItsCap) {
  const core::Image expected = filled(40, 20, 255);
  core::Image actual = filled(40, 20, 255);
  GoldenOptions options;
  options.allowances.push_back({10, 0, 10, 20, 2, "a test"});
  actual.pixel(10, 0)[2] = 0;
  actual.pixel(19, 19)[2] = 0;
  EXPECT_TRUE(judgeImages(actual.view(), expected.view(), options));
  actual.pixel(15, 9)[2] = 0;  // a third inside: over the allowance's cap
  ::testing::AssertionResult verdict = judgeImages(actual.view(), expected.view(), options);
  EXPECT_FALSE(verdict);
  EXPECT_NE(std::string(verdict.message())
                .find("3 px differ by more than 48/255 inside the "
                      "allowance for a test (cap 2)"),
            std::string::npos)
      << verdict.message();
  actual.pixel(15, 9)[2] = 255;
  actual.pixel(20, 0)[2] = 0;  // just outside the rectangle
  EXPECT_FALSE(judgeImages(actual.view(), expected.view(), options));
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
