#include "frame_layouts.hpp"

namespace collide::test {

std::string sizeName(const ::testing::TestParamInfo<PictureSize>& info) {
  return std::to_string(info.param.first) + "x" + std::to_string(info.param.second);
}

frame::FrameLayout layoutMeasured(const frame::FrameModel& frame, int width_px, int height_px,
                                  render::TextMetrics& metrics, double text_floor_px) {
  return frame::layoutFrame(
      frame, width_px, height_px, text_floor_px,
      [&metrics](std::string_view text, double px) { return metrics.width(text, px); });
}

}  // namespace collide::test
