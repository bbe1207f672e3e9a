#include "frame_models.hpp"

namespace collide::render::testing {

FrameModel twoBlocks() {
  FrameModel frame;
  frame.view = {{-4.0, -0.5}, {4.0, 1.5}};
  frame.track_y_m = 0.0;
  BodyModel left;
  left.center_m = {-2.0, 0.25};
  left.half_extent_m = {0.25, 0.25};
  left.fill = kBlue;
  left.velocity_mps = {1.5, 0.0};
  BodyModel right;
  right.center_m = {1.0, 0.35};
  right.half_extent_m = {0.35, 0.35};
  right.fill = kOrange;
  right.velocity_mps = {-0.5, 0.0};
  frame.bodies = {left, right};
  frame.arrow_m_per_mps = 0.5;
  frame.energy_bar.full_scale_J = 1.0;
  frame.energy_bar.segments = {{0.45, kBlue, "KE1"}, {0.30, kOrange, "KE2"}, {0.15, kGray, "lost"}};
  return frame;
}

FrameModel diskAndTranslucent() {
  FrameModel frame;
  frame.view = {{-2.0, -1.0}, {2.0, 1.0}};
  frame.draw_track = false;
  BodyModel disk;
  disk.shape = BodyShape::kDisk;
  disk.center_m = {-0.5, -0.1};
  disk.half_extent_m = {0.6, 0.6};
  disk.fill = kBlue;
  disk.velocity_mps = {0.8, 0.6};
  BodyModel glass;
  glass.center_m = {0.1, -0.3};
  glass.half_extent_m = {0.4, 0.3};
  glass.fill = {1.0f, 0.5f, 0.05f, 0.5f};
  glass.velocity_mps = {-0.7, 0.3};
  BodyModel resting;
  resting.center_m = {1.4, 0.3};
  resting.half_extent_m = {0.2, 0.2};
  resting.fill = kGray;
  frame.bodies = {disk, glass, resting};
  frame.arrow_m_per_mps = 0.6;
  frame.energy_bar.full_scale_J = 2.0;
  frame.energy_bar.segments = {{1.2, kBlue, "KE"}, {0.8, kGray, "lost"}};
  return frame;
}

}  // namespace collide::render::testing
