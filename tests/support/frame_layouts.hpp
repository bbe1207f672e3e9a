#pragma once
// What the frame-description checks share (no GL): the picture sizes they run at, named for the
// test list, and a frame's layout at one of them measured with the real text metrics, as compose
// and the painters lay it out.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "frame/frame_model.hpp"
#include "frame/layout.hpp"
#include "render/text/text_metrics.hpp"

namespace collide::test {

using PictureSize = std::pair<int, int>;  // width, height in pixels

// 1280x720 and 640x360, for INSTANTIATE_TEST_SUITE_P(Sizes, ..., videoSizes(), sizeName).
inline auto videoSizes() {
  return ::testing::Values(PictureSize{1280, 720}, PictureSize{640, 360});
}

// "1280x720".
std::string sizeName(const ::testing::TestParamInfo<PictureSize>& info);

// frame::layoutFrame of `frame` at width_px x height_px, text measured by `metrics`.
frame::FrameLayout layoutMeasured(const frame::FrameModel& frame, int width_px, int height_px,
                                  render::TextMetrics& metrics, double text_floor_px = 0.0);

}  // namespace collide::test
