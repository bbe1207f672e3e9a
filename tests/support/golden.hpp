#pragma once
// Golden-image comparison for tests. Baselines live in the source tree under golden_frames/
// (e.g. "render/two_blocks.png"); failures leave actual, expected and an amplified difference
// under <build>/golden_failures/ with the same relative name.
//
// GOLDEN_UPDATE=1 in the environment rewrites the baseline instead of comparing (review the diff
// and look at the picture before committing).
#include <gtest/gtest.h>

#include <string>

#include "core/image.hpp"

namespace collide::test {

struct GoldenOptions {
  int channel_tolerance = 3;           // per channel, in 1/255 steps: llvmpipe varies ±1–2
  double max_fraction_beyond = 0.001;  // share of pixels allowed beyond channel_tolerance
  std::string renderer;                // GL_RENDERER that drew `actual`; recorded on update
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

// Compares `actual` with golden_frames/<golden_name>. Prints one summary line (RMS, count).
::testing::AssertionResult compareWithGolden(const core::ImageView& actual,
                                             const std::string& golden_name,
                                             const GoldenOptions& options = {});

// Where baselines and failure artefacts go (absolute paths fixed at build time).
std::string goldenSourceDir();
std::string goldenFailureDir();

}  // namespace collide::test
