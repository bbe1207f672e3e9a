#pragma once
// Golden-image comparison for tests. Baselines live in the source tree under golden_frames/
// (e.g. "render/two_blocks.png"); failures leave actual, expected and an amplified difference
// under <build>/golden_failures/ with the same relative name.
//
// Two levels, so that llvmpipe's small variation passes and a changed digit does not:
// - a pixel whose channels all lie within channel_tolerance matches;
// - up to max_pixels_beyond pixels may differ by more (anti-aliased edges on another CPU);
// - no pixel may differ by more than gross_tolerance (a glyph drawn or not: ~150-250 levels),
//   except inside an explicit GoldenAllowance that says why.
//
// GOLDEN_UPDATE=1 in the environment rewrites the baseline instead of comparing (review the diff
// and look at the picture before committing).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/image.hpp"

namespace collide::test {

// A rectangle of the image where differences beyond gross_tolerance are expected, at most
// max_pixels of them, with the reason (e.g. a lossy codec's ringing around text).
struct GoldenAllowance {
  int x = 0, y = 0, width = 0, height = 0;  // pixels, origin top left
  long max_pixels = 0;
  std::string why;
};

struct GoldenOptions {
  int channel_tolerance = 3;    // per channel, in 1/255 steps: llvmpipe varies ±1–2
  long max_pixels_beyond = 24;  // pixels allowed past channel_tolerance (edges), per image
  int gross_tolerance = 48;     // past this a pixel fails unless an allowance covers it
  std::vector<GoldenAllowance> allowances;
  std::string renderer;  // GL_RENDERER that drew `actual`; recorded on update
};

struct ImageDifference {
  bool same_size = false;
  long pixels_beyond = 0;    // pixels with any channel differing by more than the tolerance
  int max_channel_diff = 0;  // largest difference in any channel, 1/255 steps
  double rms = 0.0;          // root mean square over all channels, 1/255 steps
};

// Compares two images channel by channel (alpha included).
ImageDifference compareImages(const core::ImageView& actual, const core::ImageView& expected,
                              int channel_tolerance);

// |actual − expected| × 16 per channel, opaque; the same size as both inputs.
core::Image amplifiedDifference(const core::ImageView& actual, const core::ImageView& expected);

// The verdict of `options` on two images of the same size, without touching any file: success,
// or a failure that says which limit was passed, by how many pixels and where.
::testing::AssertionResult judgeImages(const core::ImageView& actual,
                                       const core::ImageView& expected,
                                       const GoldenOptions& options = {});

// Compares `actual` with golden_frames/<golden_name>. Prints one summary line (RMS, count).
::testing::AssertionResult compareWithGolden(const core::ImageView& actual,
                                             const std::string& golden_name,
                                             const GoldenOptions& options = {});

// Where baselines and failure artefacts go (absolute paths fixed at build time).
std::string goldenSourceDir();
std::string goldenFailureDir();

}  // namespace collide::test
